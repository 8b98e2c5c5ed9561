// shadetree eval FILE --at X,Y,Z: every output of the graph at one point,
// as JSON: the quickest way to debug a graph.
#include <cstdio>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/arguments.h"
#include "pipeline/compile_graph.h"
#include "io/graph_files.h"
#include "interp/interpreter.h"
#include "render/graph_kinds.h"
#include "render/texture_driver.h"

namespace shadetree {

namespace {
struct EvalArguments {
  std::string file;
  std::string at;
  std::vector<std::string> inputs;
  std::string size;
  std::vector<std::string> assignments;
  std::vector<std::string> search_paths;
  std::optional<float> frame;
};

// --input NAME=VALUE: a global's value (nodes/globals.h) for eval.
Status apply_input(const std::string& assignment, SampleBuffers& samples, UniformInputs& uniforms) {
  const auto equals = assignment.find('=');
  const std::string name = assignment.substr(0, equals);
  std::string known;
  const GlobalDef* found = nullptr;
  for (const GlobalDef& global : globals) {
    known += (known.empty() ? "" : ", ") + std::string(global.name);
    if (global.name == name) found = &global;
  }
  if (equals == std::string::npos || !found || found->id == GlobalId::P)
    return invalid_input("--input expects NAME=VALUE with NAME one of the globals other than P (" + known +
                         "), got \"" + assignment + "\"");
  auto values = parse_floats(assignment.substr(equals + 1), found->components, "--input " + name);
  if (!values) return values.error();
  for (int c = 0; c < found->components; ++c) {
    if (found->variability == Variability::uniform)
      uniforms.set(found->id, (*values)[c], c);
    else if (samples.has(found->id))
      samples.plane(found->id, c)[0] = (*values)[c];
  }
  return success();
}

ExitStatus evaluate(const EvalArguments& arguments) {
  Result<LoadedGraph> loaded = load_and_compile(arguments.file, arguments.assignments, {}, graph_files(arguments.search_paths));
  if (!loaded) return report(loaded.error());
  auto at = parse_floats(arguments.at, 3, "--at");
  if (!at) return report(at.error());
  Result<TextureView> view_or_error = texture_view(*loaded->graph, arguments.size, arguments.frame);
  if (!view_or_error) return report(view_or_error.error());
  const TextureView& view = *view_or_error;

  auto kernel = make_interpreted_kernel(loaded->ir);
  SampleBuffers input(1, kernel->reads());
  const PointSample sample = graph_kind_driver(loaded->graph->kind)
                                 .sample_at_point(*loaded->graph, {view.width, view.height}, at->data(), input);
  UniformInputs uniforms = texture_uniforms(view);
  for (const std::string& assignment : arguments.inputs) {
    Status applied = apply_input(assignment, input, uniforms);
    if (!applied) return report(applied.error());
  }
  const OutputLayout& layout = kernel->outputs();
  std::vector<float> values(static_cast<std::size_t>(layout.plane_count));
  std::vector<float*> outputs;
  for (float& value : values) outputs.push_back(&value);
  kernel->bind(loaded->params.data(), uniforms)->run(input.inputs(), outputs.data(), 1);

  nlohmann::ordered_json result;
  result["graph"] = loaded->graph->name;
  result["at"] = {sample.P[0], sample.P[1], sample.P[2]};
  result["uv"] = {sample.uv[0], sample.uv[1]};
  result["filter_width"] = sample.filter_width;
  for (const IrOutput& output : loaded->ir.outputs) {
    const std::string name(output_id_name(output.id));
    const int components = component_count(output.type);
    if (components == 1) {
      result["outputs"][name] = values[layout.plane(output.id)];
      continue;
    }
    nlohmann::json vector = nlohmann::json::array();
    for (int c = 0; c < components; ++c) vector.push_back(values[layout.plane(output.id, c)]);
    result["outputs"][name] = vector;
  }
  std::printf("%s\n", result.dump(2).c_str());
  return ExitStatus::ok;
}
}  // namespace

void add_eval_command(CLI::App& app, CommandRunner& run) {
  auto* command = app.add_subcommand("eval", "print every output of a graph at one point, as JSON");
  auto arguments = std::make_shared<EvalArguments>();
  command->add_option("file", arguments->file, "graph file")->required();
  command->add_option("--at", arguments->at, "the point P as X,Y,Z (for an environment graph, the direction I)")
      ->required();
  command->add_option("--input", arguments->inputs,
                      "set a global other than P: NAME=VALUE, e.g. N=0,1,0 or density=0.5 (repeatable; "
                      "defaults: what the graph's driver gives a sample there (texture and others: N = 0,0,1, uv and "
                      "filter_width as render computes them; environment: I, P and N from the direction), "
                      "time = frame / 24, others 0)");
  command->add_option("--size", arguments->size,
                      "image size WIDTHxHEIGHT that sets filter_width as render would (default: the graph's)");
  command->add_option("--set", arguments->assignments, "set a param: NAME=VALUE (repeatable)");
  add_finite_option(*command, "--frame", arguments->frame, "animation frame (time = frame / 24)");
  add_search_path_option(*command, arguments->search_paths);
  command->callback([&run, arguments] { run = [arguments] { return evaluate(*arguments); }; });
}

}  // namespace shadetree

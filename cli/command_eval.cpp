// shadetree eval FILE --at X,Y,Z: every output of the graph at one point,
// as JSON: the quickest way to debug a graph.
#include <cstdio>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/arguments.h"
#include "pipeline/compile_graph.h"
#include "interp/interpreter.h"
#include "render/texture_driver.h"

namespace shadetree {

namespace {
struct EvalArguments {
  std::string file;
  std::string at;
  std::string normal = "0,0,1";
  std::string size;
  std::vector<std::string> assignments;
  std::optional<float> frame;
  float density = 0.0f;
};

ExitStatus evaluate(const EvalArguments& arguments) {
  Result<LoadedGraph> loaded = load_and_compile(arguments.file, arguments.assignments);
  if (!loaded) return report(loaded.error());
  auto at = parse_floats(arguments.at, 3, "--at");
  if (!at) return report(at.error());
  auto normal = parse_floats(arguments.normal, 3, "--normal");
  if (!normal) return report(normal.error());
  Result<TextureView> view_or_error = texture_view(*loaded->graph, arguments.size, arguments.frame);
  if (!view_or_error) return report(view_or_error.error());
  const TextureView& view = *view_or_error;
  const TextureSample sample = texture_sample_at_point(view, at->data());

  InputBuffers input(1);
  const float sample_values[input_plane_count] = {sample.P[0],  sample.P[1],  sample.P[2],         (*normal)[0], (*normal)[1],
                                           (*normal)[2], sample.uv[0], sample.uv[1], sample.filter_width,
                                           arguments.density};
  for (int p = 0; p < input_plane_count; ++p) input.plane(static_cast<InputPlane>(p))[0] = sample_values[p];
  const KernelInputs inputs = input.inputs(view.frame / frames_per_second, view.frame);

  const ShadeIR& ir = loaded->ir;
  std::size_t plane_count = 0;
  for (const IrOutput& output : ir.outputs) plane_count += static_cast<std::size_t>(component_count(output.type));
  std::vector<float> values(plane_count);
  std::vector<float*> outputs;
  for (float& value : values) outputs.push_back(&value);
  make_interpreted_kernel(ir)->run(loaded->params.data(), inputs, outputs.data(), 1);

  nlohmann::ordered_json result;
  result["graph"] = loaded->graph->name;
  result["at"] = {sample.P[0], sample.P[1], sample.P[2]};
  result["uv"] = {sample.uv[0], sample.uv[1]};
  result["filter_width"] = sample.filter_width;
  std::size_t plane = 0;
  for (const IrOutput& output : ir.outputs) {
    const int components = component_count(output.type);
    if (components == 1) {
      result["outputs"][output.name] = values[plane++];
      continue;
    }
    nlohmann::json vector = nlohmann::json::array();
    for (int c = 0; c < components; ++c) vector.push_back(values[plane++]);
    result["outputs"][output.name] = vector;
  }
  std::printf("%s\n", result.dump(2).c_str());
  return ExitStatus::ok;
}
}  // namespace

void add_eval_command(CLI::App& app, CommandRunner& run) {
  auto* command = app.add_subcommand("eval", "print every output of a graph at one point, as JSON");
  auto arguments = std::make_shared<EvalArguments>();
  command->add_option("file", arguments->file, "graph file")->required();
  command->add_option("--at", arguments->at, "the point P as X,Y,Z")->required();
  command->add_option("--normal", arguments->normal, "the normal N as X,Y,Z (default 0,0,1)");
  command->add_option("--size", arguments->size,
                      "image size WIDTHxHEIGHT that sets filter_width as render would (default: the graph's)");
  command->add_option("--set", arguments->assignments, "set a param: NAME=VALUE (repeatable)");
  command->add_option("--frame", arguments->frame, "animation frame (time = frame / 24)");
  command->add_option("--density", arguments->density, "incoming density, for volume graphs");
  command->callback([&run, arguments] { run = [arguments] { return evaluate(*arguments); }; });
}

}  // namespace shadetree

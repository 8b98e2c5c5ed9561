#include "cli/arguments.h"

#include <sstream>

#include <CLI/CLI.hpp>

#include "graph/number_list.h"
#include "graph/parse.h"
#include "interp/interpreter.h"
#include "jit/jit_kernel.h"

namespace shadetree {

Result<std::pair<int, int>> parse_size(const std::string& text) {
  int width = 0, height = 0;
  char separator = 0, trailing = 0;
  std::istringstream stream(text);
  if (!(stream >> width >> separator >> height) || separator != 'x' || (stream >> trailing))
    return invalid_input("--size expects WIDTHxHEIGHT, got \"" + text + "\"");
  if (width < 1 || height < 1 || width > max_image_side || height > max_image_side)
    return invalid_input("--size " + text + ": each side must be between 1 and " + std::to_string(max_image_side) +
                         " pixels");
  return std::pair{width, height};
}

Result<std::vector<float>> parse_floats(const std::string& text, std::size_t count, const std::string& what) {
  std::optional<std::vector<float>> values = parse_number_list(text);
  if (!values || values->size() != count)
    return invalid_input(what + " expects " + std::to_string(count) + " comma-separated numbers, got \"" + text + "\"");
  return *values;
}

Result<TextureView> texture_view(const Graph& graph, const std::string& size, std::optional<float> frame) {
  TextureView view = TextureView::from_settings(graph.render);
  if (!size.empty()) {
    auto parsed = parse_size(size);
    if (!parsed) return parsed.error();
    view.width = parsed->first;
    view.height = parsed->second;
  }
  if (frame) view.frame = *frame;
  return view;
}

Result<std::pair<int, int>> image_size(const Graph& graph, const std::string& size) {
  if (size.empty()) return std::pair{graph.render.width, graph.render.height};
  return parse_size(size);
}

void add_search_path_option(CLI::App& command, std::vector<std::string>& search_paths) {
  command.add_option("--search-path", search_paths,
                     "a folder outside the graph's own from which the graph may read files (repeatable)");
}

CLI::Option* add_finite_option(CLI::App& command, const std::string& name, std::optional<float>& value,
                               const std::string& description) {
  return command.add_option(name, value, description)->check(CLI::Validator(
      [](std::string& text) -> std::string {
        const auto numbers = parse_number_list(text);
        return numbers && numbers->size() == 1 ? "" : "expected a finite decimal number, got \"" + text + "\"";
      },
      "NUMBER"));
}

Result<std::unique_ptr<Kernel>> make_kernel(const std::string& backend, const ShadeIR& ir, int width) {
  if (backend == "interp") return make_interpreted_kernel(ir);
  return make_jit_kernel(ir, width);
}

void add_sampling_options(CLI::App& command, SamplingArguments& arguments) {
  command.add_option("--set", arguments.assignments, "set a param: NAME=VALUE (repeatable)");
  add_finite_option(command, "--frame", arguments.frame, "animation frame (time = frame / 24)");
  command.add_option("--threads", arguments.threads, "worker threads (default: all cores)")->check(CLI::Range(1, 1024));
  command.add_option("--backend", arguments.backend, "backend: jit (default) or interp")
      ->check(CLI::IsMember({"jit", "interp"}));
  add_search_path_option(command, arguments.search_paths);
}

}  // namespace shadetree

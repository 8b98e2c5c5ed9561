// Parsing of command-line values shared by several commands.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <memory>
#include <optional>

#include "graph/diagnostic.h"
#include "graph/graph.h"
#include "ir/kernel.h"
#include "render/texture_driver.h"

namespace CLI {
class App;
class Option;
}

namespace shadetree {

// "512x256" -> {512, 256}, within the image size limit.
Result<std::pair<int, int>> parse_size(const std::string& text);

// --size if given, else the graph's render size.
Result<std::pair<int, int>> image_size(const Graph& graph, const std::string& size);

// "1,2,3" -> three floats.
Result<std::vector<float>> parse_floats(const std::string& text, std::size_t count, const std::string& what);

// The texture view of a graph's render settings with --size and --frame
// applied (empty size / no frame: keep the graph's).
Result<TextureView> texture_view(const Graph& graph, const std::string& size, std::optional<float> frame);

// --search-path DIR (repeatable): a folder outside the graph's own from
// which it may read files (meshes, images).
void add_search_path_option(CLI::App& command, std::vector<std::string>& search_paths);

// An option taking one finite decimal number: nan, inf and hex are refused
// (exit status 2), as they are in graph files.
CLI::Option* add_finite_option(CLI::App& command, const std::string& name, std::optional<float>& value,
                               const std::string& description);

// The options of the commands that sample a graph into files rather than
// render it (voxelize, bake): --set, --frame, --threads, --backend (jit or
// interp) and --search-path.
struct SamplingArguments {
  std::vector<std::string> assignments;
  std::optional<float> frame;
  int threads = 0;
  std::string backend = "jit";
  std::vector<std::string> search_paths;
};
void add_sampling_options(CLI::App& command, SamplingArguments& arguments);

// The kernel of `ir` from the named backend ("jit" or "interp"); width is
// the JIT's vector width (0: the host's).
Result<std::unique_ptr<Kernel>> make_kernel(const std::string& backend, const ShadeIR& ir, int width);

}  // namespace shadetree

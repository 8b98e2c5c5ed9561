#include "bench/texture_samples.h"

#include <cstdio>
#include <cstdlib>
#include <utility>

#include "render/texture_driver.h"

namespace shadetree {
namespace {

LoadedGraph load_graph(const std::string& path) {
  Result<LoadedGraph> loaded = load_and_compile(path, {});
  if (!loaded) {
    std::fprintf(stderr, "%s\n", loaded.error().to_string().c_str());
    std::exit(1);
  }
  return std::move(*loaded);
}

// What the graph reads, and the planes a PlaneKernel takes.
GlobalSet stored_globals(const LoadedGraph& graph) {
  GlobalSet stored = globals_read(graph.ir);
  stored.set(static_cast<std::size_t>(GlobalId::P));
  stored.set(static_cast<std::size_t>(GlobalId::filter_width));
  return stored;
}

}  // namespace

TextureSamples::TextureSamples(const std::string& graph_path, int side)
    : graph_(load_graph(graph_path)),
      input_(static_cast<std::size_t>(side) * side, stored_globals(graph_)) {
  TextureView view = TextureView::from_settings(graph_.graph->render);
  view.width = view.height = side;
  for (auto& plane : rgb_) plane.resize(count());
  const OutputLayout layout = output_layout(graph_.ir);
  outputs_.assign(static_cast<std::size_t>(layout.plane_count), nullptr);
  for (int c = 0; c < 3; ++c) outputs_[static_cast<std::size_t>(layout.plane(OutputId::color, c))] = rgb_[c].data();
  for (int row = 0; row < side; ++row)
    for (int column = 0; column < side; ++column)
      store_texture_sample(input_, static_cast<std::size_t>(row) * side + column,
                           texture_sample_at_pixel(view, column, row));
}

void TextureSamples::run(BoundKernel& kernel) {
  kernel.run(input_.inputs(), outputs_.data(), count());
}

void TextureSamples::run(PlaneKernel* kernel) {
  kernel(input_.plane(GlobalId::P, 0), input_.plane(GlobalId::P, 1), input_.plane(GlobalId::P, 2),
         input_.plane(GlobalId::filter_width), rgb_[0].data(), rgb_[1].data(), rgb_[2].data(), count());
}

}  // namespace shadetree

// Throughput of the interpreted backend on the gallery graphs, through the
// texture driver, at one thread and at all threads. Reported as samples per
// second (Google Benchmark's items_per_second); run with
//   build/shadetree_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// to get medians.
#include <benchmark/benchmark.h>

#include "pipeline/compile_graph.h"
#include "interp/interpreter.h"
#include "render/texture_driver.h"

namespace shadetree {
namespace {

constexpr int image_side = 256;

void render_gallery_graph(benchmark::State& state, const char* name) {
  Result<LoadedGraph> loaded = load_and_compile(std::string(SHADETREE_SOURCE_DIR "/graphs/") + name + ".json", {});
  if (!loaded) {
    state.SkipWithError(loaded.error().to_string().c_str());
    return;
  }
  auto kernel = make_interpreted_kernel(loaded->ir);
  TextureView view = TextureView::from_settings(loaded->graph->render);
  view.width = view.height = image_side;
  TextureRenderOptions options;
  options.threads = static_cast<int>(state.range(0));
  for (auto _ : state) {
    Result<Image> image = render_texture(*kernel, loaded->params, view, options);
    benchmark::DoNotOptimize(image->pixels.data());
  }
  state.SetItemsProcessed(state.iterations() * image_side * image_side);
}

// Arg: thread count (0 = all cores).
BENCHMARK_CAPTURE(render_gallery_graph, marble, "marble")->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(render_gallery_graph, corona, "corona")->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(render_gallery_graph, checker_aa, "checker_aa")->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(render_gallery_graph, julia, "julia")->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace shadetree

// The surface driver on graphs/marble_vase.json at 256x256, one thread:
// the whole render (visibility, shading, lighting) with the interpreter
// and with the JIT.
// Run
//   build/shadetree_bench --benchmark_filter=surface_ --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// items_per_second is pixels per second; `shadetree bench
// graphs/marble_vase.json` splits a render into its stages and sets the
// shading stage against the kernel alone.
#include <benchmark/benchmark.h>

#include "interp/interpreter.h"
#include "jit/jit_kernel.h"
#include "pipeline/compile_graph.h"
#include "render/surface_driver.h"

namespace shadetree {
namespace {

constexpr int side = 256;

struct Vase {
  LoadedGraph graph = *load_and_compile(SHADETREE_SOURCE_DIR "/graphs/marble_vase.json", {});
  Scene scene = *Scene::build(*graph.graph->render.scene, SHADETREE_SOURCE_DIR "/graphs/marble_vase.json", {});
  Camera camera{scene.desc().camera, side, side};
};

Vase& vase() {
  static Vase instance;
  return instance;
}

void render(benchmark::State& state, const Kernel& kernel) {
  SurfaceView view;
  view.width = view.height = side;
  SurfaceRenderOptions options;
  options.threads = 1;
  for (auto _ : state) {
    Result<Image> image = render_surface(kernel, vase().graph.params, vase().scene, vase().camera, view, options);
    benchmark::DoNotOptimize(image);
  }
  state.SetItemsProcessed(state.iterations() * side * side);
}

void surface_render_interpreter(benchmark::State& state) { render(state, *make_interpreted_kernel(vase().graph.ir)); }

void surface_render_jit(benchmark::State& state) {
  auto kernel = make_jit_kernel(vase().graph.ir);
  if (!kernel) return state.SkipWithError(kernel.error().to_string().c_str());
  render(state, **kernel);
}

BENCHMARK(surface_render_interpreter)->Unit(benchmark::kMillisecond);
BENCHMARK(surface_render_jit)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace shadetree

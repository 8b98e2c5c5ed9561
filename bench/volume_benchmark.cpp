// The ray marcher on graphs/fireball.json at 128x128 (the size of an
// interactive preview), with the interpreter and with the JIT, at one
// thread and at all threads.
// Run
//   build/shadetree_bench --benchmark_filter=volume_ --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// items_per_second is density samples per second through the marcher;
// frames per second is 1 / the time per iteration. `shadetree bench
// graphs/fireball.json` sets the density rate against the kernel alone.
#include <benchmark/benchmark.h>

#include "interp/interpreter.h"
#include "jit/jit_kernel.h"
#include "pipeline/compile_graph.h"
#include "render/volume_driver.h"

namespace shadetree {
namespace {

constexpr int side = 128;

struct Fireball {
  LoadedGraph graph = *load_and_compile(SHADETREE_SOURCE_DIR "/graphs/fireball.json", {});
  Scene scene = *Scene::build(volume_scene(graph.graph->render.scene), SHADETREE_SOURCE_DIR "/graphs/fireball.json", {});
  Camera camera{scene.desc().camera, side, side};
};

Fireball& fireball() {
  static Fireball instance;
  return instance;
}

// state.range(0): threads (0: all cores).
void render(benchmark::State& state, const Kernel& kernel) {
  VolumeView view;
  view.width = view.height = side;
  VolumeRenderOptions options;
  options.threads = static_cast<int>(state.range(0));
  long samples = 0;
  for (auto _ : state) {
    VolumeRenderStats stats;
    Result<Image> image = render_volume(kernel, fireball().graph.params, fireball().scene,
                                        *fireball().graph.graph->render.volume, fireball().camera, view, options, &stats);
    benchmark::DoNotOptimize(image);
    samples += stats.density_samples;
  }
  state.SetItemsProcessed(samples);
}

void volume_render_interpreter(benchmark::State& state) { render(state, *make_interpreted_kernel(fireball().graph.ir)); }

void volume_render_jit(benchmark::State& state) {
  auto kernel = make_jit_kernel(fireball().graph.ir);
  if (!kernel) return state.SkipWithError(kernel.error().to_string().c_str());
  render(state, **kernel);
}

BENCHMARK(volume_render_interpreter)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(volume_render_jit)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace shadetree

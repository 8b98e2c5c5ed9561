// graphs/marble.json five ways, one thread each, on the same 256x256
// samples: the interpreter, the JIT, the C++ of `emit --cpp` built by g++
// and by clang++ (-O2 -march=native), and the hand-written scalar C++
// yardstick (-O3 -march=native). Run
//   build/shadetree_bench --benchmark_filter=marble_ --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// and compare items_per_second (samples per second) of the medians.
#include <benchmark/benchmark.h>

#include <cmath>

#include "bench/marble_emitted.h"
#include "bench/marble_yardstick.h"
#include "pipeline/compile_graph.h"
#include "interp/interpreter.h"
#include "jit/jit_kernel.h"
#include "render/texture_driver.h"

namespace shadetree {
namespace {

constexpr int side = 256;

struct MarbleSamples {
  SampleBuffers input{side * side, GlobalSet().set(static_cast<std::size_t>(GlobalId::P)).set(
                                     static_cast<std::size_t>(GlobalId::filter_width))};
  std::vector<float> rgb[3];
  LoadedGraph graph;

  MarbleSamples() {
    graph = *load_and_compile(SHADETREE_SOURCE_DIR "/graphs/marble.json", {});
    TextureView view = TextureView::from_settings(graph.graph->render);
    view.width = view.height = side;
    for (auto& plane : rgb) plane.resize(side * side);
    for (int row = 0; row < side; ++row)
      for (int column = 0; column < side; ++column) {
        const TextureSample sample = texture_sample_at_pixel(view, column, row);
        const std::size_t i = static_cast<std::size_t>(row) * side + column;
        store_texture_sample(input, i, sample);
      }
  }

  // One binding, as a driver keeps per thread, run on every iteration.
  void run(BoundKernel& kernel) {
    float* outputs[4] = {rgb[0].data(), rgb[1].data(), rgb[2].data(), nullptr};
    kernel.run(input.inputs(), outputs, side * side);
  }
};

MarbleSamples& samples() {
  static MarbleSamples instance;
  return instance;
}

void marble_interpreter(benchmark::State& state) {
  auto kernel = make_interpreted_kernel(samples().graph.ir);
  auto bound = kernel->bind(samples().graph.params.data(), UniformInputs{});
  for (auto _ : state) samples().run(*bound);
  state.SetItemsProcessed(state.iterations() * side * side);
}

void marble_jit(benchmark::State& state) {
  auto kernel = make_jit_kernel(samples().graph.ir, static_cast<int>(state.range(0)));
  if (!kernel) {
    state.SkipWithError(kernel.error().to_string().c_str());
    return;
  }
  auto bound = (*kernel)->bind(samples().graph.params.data(), UniformInputs{});
  for (auto _ : state) samples().run(*bound);
  state.SetItemsProcessed(state.iterations() * side * side);
}

using PlaneFunction = void(const float*, const float*, const float*, const float*, float*, float*, float*,
                           std::size_t);

void run_planes(benchmark::State& state, PlaneFunction* function) {
  MarbleSamples& s = samples();
  for (auto _ : state)
    function(s.input.plane(GlobalId::P, 0), s.input.plane(GlobalId::P, 1), s.input.plane(GlobalId::P, 2),
             s.input.plane(GlobalId::filter_width), s.rgb[0].data(), s.rgb[1].data(), s.rgb[2].data(), side * side);
  state.SetItemsProcessed(state.iterations() * side * side);
}

void marble_yardstick(benchmark::State& state) { run_planes(state, yardstick::marble); }
void marble_emitted_gcc(benchmark::State& state) { run_planes(state, emitted::marble_gcc); }
void marble_emitted_clang(benchmark::State& state) { run_planes(state, emitted::marble_clang); }

BENCHMARK(marble_interpreter)->Unit(benchmark::kMillisecond);
BENCHMARK(marble_jit)->Arg(0)->Arg(8)->Arg(4)->Unit(benchmark::kMillisecond);  // 0: host width
BENCHMARK(marble_emitted_gcc)->Unit(benchmark::kMillisecond);
BENCHMARK(marble_emitted_clang)->Unit(benchmark::kMillisecond);
BENCHMARK(marble_yardstick)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace shadetree

BENCHMARK_MAIN();

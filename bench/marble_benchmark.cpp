// graphs/marble.json six ways, one thread each, on the same 256x256
// samples: the interpreter, the JIT, the C++ of `emit --cpp` built by g++
// and by clang++ (-O2 -march=native), and the hand-written scalar C++
// yardstick built by each (-O3 -march=native). Run
//   build/shadetree_bench --benchmark_filter=marble_ --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// and compare items_per_second (samples per second) of the medians.
#include <benchmark/benchmark.h>

#include "bench/marble_emitted.h"
#include "bench/scalar_yardsticks.h"
#include "bench/texture_samples.h"
#include "interp/interpreter.h"
#include "jit/jit_kernel.h"

namespace shadetree {
namespace {

constexpr int side = 256;

TextureSamples& samples() {
  static TextureSamples instance(SHADETREE_SOURCE_DIR "/graphs/marble.json", side);
  return instance;
}

void marble_interpreter(benchmark::State& state) {
  auto kernel = make_interpreted_kernel(samples().graph().ir);
  auto bound = kernel->bind(samples().graph().params.data(), UniformInputs{});
  for (auto _ : state) samples().run(*bound);
  state.SetItemsProcessed(state.iterations() * side * side);
}

void marble_jit(benchmark::State& state) {
  auto kernel = make_jit_kernel(samples().graph().ir, static_cast<int>(state.range(0)));
  if (!kernel) {
    state.SkipWithError(kernel.error().to_string().c_str());
    return;
  }
  auto bound = (*kernel)->bind(samples().graph().params.data(), UniformInputs{});
  for (auto _ : state) samples().run(*bound);
  state.SetItemsProcessed(state.iterations() * side * side);
}

void run_planes(benchmark::State& state, PlaneKernel* kernel) {
  for (auto _ : state) samples().run(kernel);
  state.SetItemsProcessed(state.iterations() * side * side);
}

void marble_yardstick_gcc(benchmark::State& state) { run_planes(state, yardstick::gcc::marble); }
void marble_yardstick_clang(benchmark::State& state) { run_planes(state, yardstick::clang::marble); }
void marble_emitted_gcc(benchmark::State& state) { run_planes(state, emitted::marble_gcc); }
void marble_emitted_clang(benchmark::State& state) { run_planes(state, emitted::marble_clang); }

BENCHMARK(marble_interpreter)->Unit(benchmark::kMillisecond);
BENCHMARK(marble_jit)->Arg(0)->Arg(8)->Arg(4)->Unit(benchmark::kMillisecond);  // 0: host width
BENCHMARK(marble_emitted_gcc)->Unit(benchmark::kMillisecond);
BENCHMARK(marble_emitted_clang)->Unit(benchmark::kMillisecond);
BENCHMARK(marble_yardstick_gcc)->Unit(benchmark::kMillisecond);
BENCHMARK(marble_yardstick_clang)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace shadetree

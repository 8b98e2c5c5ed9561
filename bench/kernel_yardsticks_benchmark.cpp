// Noise, turbulence and marble (bench/graphs/noise.json, graphs/
// turbulence.json, graphs/marble.json): the JIT at the host's width against
// the hand-written yardsticks, scalar C++ built by g++ and by clang++, AVX2
// intrinsics with gathers and with the interleaved gradient table, and
// AVX-512 intrinsics with gathers and with in-register lookups, one
// thread each, on the same samples: each graph's render domain at
// 1024x1024. Run
//   build/shadetree_bench --benchmark_filter='^yardstick/' --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
// The run ends with a table of the JIT's samples per second over each
// yardstick's. Before a yardstick is timed its colour is compared with
// the JIT's on every sample: past `tolerance` the benchmark fails with the
// difference, so a wrong yardstick never reports a speed.
//
// This file also holds shadetree_bench's main: BENCHMARK_MAIN's, with the
// table's reporter in front of the one the flags choose.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bench/avx2_yardsticks.h"
#include "bench/avx512_yardsticks.h"
#include "bench/ratio_table_reporter.h"
#include "bench/scalar_yardsticks.h"
#include "bench/texture_samples.h"
#include "jit/jit_kernel.h"

namespace shadetree {
namespace {

constexpr int side = 1024;
// The JIT rounds like the interpreter, the yardsticks like their compiler
// (FMAs, libm's or their own sin and pow): far below a colour's 1/255.
constexpr float tolerance = 1e-4f;
const std::string prefix = "yardstick/", reference = "jit";

struct TextureGraph {
  const char* name;
  const char* graph;
};

constexpr TextureGraph textures[] = {{"noise", SHADETREE_SOURCE_DIR "/bench/graphs/noise.json"},
                                {"turbulence", SHADETREE_SOURCE_DIR "/graphs/turbulence.json"},
                                {"marble", SHADETREE_SOURCE_DIR "/graphs/marble.json"}};

// What a yardstick's instructions need of the host.
struct Needs {
  bool (*host_has)();  // nullptr: any x86-64 host
  const char* missing;
};
constexpr Needs any_host{nullptr, ""}, avx2{yardstick::host_has_avx2, "no AVX2 on this host"},
    avx512{yardstick::host_has_avx512, "no AVX-512 on this host"};

struct Yardstick {
  const char* name;
  PlaneKernel* kernel[3];  // by texture
  Needs needs;
};

const Yardstick yardsticks[] = {
    {"scalar_gcc", {yardstick::gcc::noise, yardstick::gcc::turbulence, yardstick::gcc::marble}, any_host},
    {"scalar_clang", {yardstick::clang::noise, yardstick::clang::turbulence, yardstick::clang::marble}, any_host},
    {"avx2_gathers",
     {yardstick::avx2_gathers::noise, yardstick::avx2_gathers::turbulence, yardstick::avx2_gathers::marble},
     avx2},
    {"avx2_interleaved",
     {yardstick::avx2_interleaved::noise, yardstick::avx2_interleaved::turbulence,
      yardstick::avx2_interleaved::marble},
     avx2},
    {"avx512_gathers",
     {yardstick::avx512_gathers::noise, yardstick::avx512_gathers::turbulence, yardstick::avx512_gathers::marble},
     avx512},
    {"avx512_in_register",
     {yardstick::avx512_in_register::noise, yardstick::avx512_in_register::turbulence,
      yardstick::avx512_in_register::marble},
     avx512}};

// A texture's samples, its JIT kernel bound to its default params, and the
// colour that kernel computes, made once for every benchmark of the texture.
class TextureUnderTest {
 public:
  explicit TextureUnderTest(const TextureGraph& texture) : samples_(texture.graph, side) {
    auto kernel = make_jit_kernel(samples_.graph().ir);
    if (!kernel) {
      jit_error_ = kernel.error().to_string();
      return;
    }
    kernel_ = std::move(*kernel);
    bound_ = kernel_->bind(samples_.graph().params.data(), UniformInputs{});
    samples_.run(*bound_);
    for (int c = 0; c < 3; ++c) jit_rgb_[c] = samples_.rgb(c);
  }

  TextureSamples& samples() { return samples_; }
  BoundKernel* jit() { return bound_.get(); }
  const std::string& jit_error() const { return jit_error_; }

  struct Agreement {
    float largest_difference;
    std::string description;  // the difference and where it is
  };

  // `yardstick`'s colour against the JIT's, measured once per yardstick.
  const Agreement& agreement(PlaneKernel* yardstick) {
    auto found = agreements_.find(yardstick);
    if (found == agreements_.end()) found = agreements_.emplace(yardstick, measure_agreement(yardstick)).first;
    return found->second;
  }

 private:
  Agreement measure_agreement(PlaneKernel* yardstick) {
    samples_.run(yardstick);
    float largest = 0.0f;
    std::size_t where = 0;
    int channel = 0;
    for (int c = 0; c < 3; ++c)
      for (std::size_t i = 0; i < samples_.count(); ++i) {
        const float difference = std::fabs(samples_.rgb(c)[i] - jit_rgb_[c][i]);
        if (difference > largest || (std::isnan(difference) && !std::isnan(largest))) {
          largest = difference;
          where = i;
          channel = c;
        }
      }
    char text[160];
    std::snprintf(text, sizeof text, "max |difference| from the JIT %.2g (pixel %zu,%zu channel %d: %.7g vs %.7g)",
                  largest, where % side, where / side, channel, samples_.rgb(channel)[where], jit_rgb_[channel][where]);
    return {largest, text};
  }

  TextureSamples samples_;
  std::unique_ptr<Kernel> kernel_;
  std::unique_ptr<BoundKernel> bound_;
  std::string jit_error_;
  std::vector<float> jit_rgb_[3];
  std::map<PlaneKernel*, Agreement> agreements_;
};

TextureUnderTest& texture_under_test(int texture) {
  static std::map<int, std::unique_ptr<TextureUnderTest>> made;
  auto& entry = made[texture];
  if (!entry) entry = std::make_unique<TextureUnderTest>(textures[texture]);
  return *entry;
}

void time_jit(benchmark::State& state, int texture) {
  TextureUnderTest& under_test = texture_under_test(texture);
  if (!under_test.jit()) {
    state.SkipWithError(under_test.jit_error().c_str());
    return;
  }
  for (auto _ : state) under_test.samples().run(*under_test.jit());
  state.SetItemsProcessed(state.iterations() * side * side);
}

void time_yardstick(benchmark::State& state, int texture, const Yardstick& yardstick) {
  if (yardstick.needs.host_has && !yardstick.needs.host_has()) {
    state.SkipWithError(yardstick.needs.missing);
    return;
  }
  TextureUnderTest& under_test = texture_under_test(texture);
  if (!under_test.jit()) {
    state.SkipWithError(("no JIT kernel to compare with: " + under_test.jit_error()).c_str());
    return;
  }
  const auto& agreement = under_test.agreement(yardstick.kernel[texture]);
  if (!(agreement.largest_difference <= tolerance)) {
    state.SkipWithError(("past the tolerance " + std::to_string(tolerance) + ": " + agreement.description).c_str());
    return;
  }
  state.SetLabel(agreement.description);
  for (auto _ : state) under_test.samples().run(yardstick.kernel[texture]);
  state.SetItemsProcessed(state.iterations() * side * side);
}

const bool registered = [] {
  for (int texture = 0; texture < 3; ++texture) {
    const std::string name = prefix + textures[texture].name + "/";
    benchmark::RegisterBenchmark((name + reference).c_str(), time_jit, texture)->Unit(benchmark::kMillisecond);
    for (const Yardstick& yardstick : yardsticks)
      benchmark::RegisterBenchmark((name + yardstick.name).c_str(), time_yardstick, texture, yardstick)
          ->Unit(benchmark::kMillisecond);
  }
  return true;
}();

}  // namespace
}  // namespace shadetree

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  shadetree::RatioTableReporter reporter(
      benchmark::CreateDefaultDisplayReporter(), shadetree::prefix, shadetree::reference,
      "Yardsticks: one thread, each graph's render domain at " + std::to_string(shadetree::side) + "x" +
          std::to_string(shadetree::side));
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}

// Tiered execution: runs on the interpreter until the JIT's compile is
// done (with quick first, then on a quick kernel until the full one is),
// then on the JIT, with the same output bit for bit.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "interp/interpreter.h"
#include "pipeline/compile_graph.h"
#include "pipeline/tiered_kernel.h"
#include "support/graph_text.h"

namespace shadetree {
namespace {

// A chain of exps on varying P: tens of milliseconds to compile at least.
Result<LoadedGraph> exp_chain(int links, float scale) {
  std::string nodes = R"({"id": "p", "op": "P"}, {"id": "s", "op": "split", "in": {"v": "p"}},
                         {"id": "v0", "op": "mul", "in": {"a": "s.x", "b": )" + std::to_string(scale) + "}}";
  for (int i = 1; i <= links; ++i)
    nodes += R"(, {"id": "v)" + std::to_string(i) + R"(", "op": "exp", "in": {"x": "v)" + std::to_string(i - 1) +
             R"("}}, {"id": "w)" + std::to_string(i) + R"(", "op": "mul", "in": {"a": "v)" + std::to_string(i) +
             R"(", "b": 0.001}})";
  return compile_graph_text(testing::graph_text(nodes, R"("color": "w)" + std::to_string(links) + "\""),
                            "chain.json");
}

TEST(TieredKernel, SwitchesFromInterpreterToJitWithIdenticalOutput) {
  Result<LoadedGraph> loaded = exp_chain(120, 0.01f);
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  std::unique_ptr<TieredKernel> kernel = make_tiered_kernel(loaded->ir, 8, JitSettings{false, {}, true, std::nullopt});

  constexpr std::size_t count = 37;
  SampleBuffers input(count, kernel->reads());
  for (std::size_t i = 0; i < count; ++i) input.plane(GlobalId::P)[i] = 0.1f * static_cast<float>(i) - 1.0f;
  std::unique_ptr<BoundKernel> bound = kernel->bind(loaded->params.data(), UniformInputs{});
  OutputBuffers first(count, kernel->outputs()), second(count, kernel->outputs());
  bound->run(input.inputs(), first.planes(), count);
  EXPECT_EQ(kernel->report().interpreted_runs, 1);

  for (int wait = 0; wait < 600 && !kernel->report().jit_ready; ++wait)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  ASSERT_TRUE(kernel->report().jit_ready);
  ASSERT_FALSE(kernel->report().jit_failed);
  bound->run(input.inputs(), second.planes(), count);
  EXPECT_EQ(kernel->report().compiled_runs, 1);
  for (int c = 0; c < 3; ++c)
    for (std::size_t i = 0; i < count; ++i) ASSERT_EQ(first.plane(c)[i], second.plane(c)[i]) << i;
}

// Quick first: the quick kernel is ready before the full one, every run
// after both is on the full one, and all three tiers give the same bits.
TEST(TieredKernel, QuickFirstRunsAQuickKernelUntilTheFullOneIsReady) {
  Result<LoadedGraph> loaded = exp_chain(120, 0.02f);
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  std::unique_ptr<TieredKernel> kernel =
      make_tiered_kernel(loaded->ir, 8, JitSettings{false, {}, true, std::nullopt}, true);
  constexpr std::size_t count = 37;
  SampleBuffers input(count, kernel->reads());
  for (std::size_t i = 0; i < count; ++i) input.plane(GlobalId::P)[i] = 0.1f * static_cast<float>(i) - 1.0f;
  std::unique_ptr<BoundKernel> bound = kernel->bind(loaded->params.data(), UniformInputs{});
  OutputBuffers reference(count, kernel->outputs()), output(count, kernel->outputs());
  make_interpreted_kernel(loaded->ir)->bind(loaded->params.data(), UniformInputs{})->run(input.inputs(),
                                                                                          reference.planes(), count);
  auto same_as_reference = [&] {
    for (int c = 0; c < 3; ++c)
      for (std::size_t i = 0; i < count; ++i)
        if (reference.plane(c)[i] != output.plane(c)[i]) return false;
    return true;
  };
  long runs = 0;
  for (int wait = 0; wait < 6000 && !kernel->report().jit_ready; ++wait, ++runs) {
    bound->run(input.inputs(), output.planes(), count);
    ASSERT_TRUE(same_as_reference()) << "run " << runs;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  const TieredReport report = kernel->report();
  ASSERT_TRUE(report.jit_ready);
  ASSERT_FALSE(report.jit_failed);
  EXPECT_GT(report.quick_ready_milliseconds, 0.0);
  EXPECT_LT(report.quick_ready_milliseconds, report.jit_ready_milliseconds);
  bound->run(input.inputs(), output.planes(), count);
  EXPECT_TRUE(same_as_reference());
  EXPECT_EQ(kernel->report().compiled_runs, 1);
  EXPECT_EQ(kernel->report().interpreted_runs + kernel->report().quick_runs, runs);
}

// A program whose full kernel is cached needs no quick one.
TEST(TieredKernel, QuickFirstSkipsTheQuickKernelWhenTheFullOneIsCached) {
  Result<LoadedGraph> loaded = exp_chain(20, 0.03f);
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  const JitSettings memory_only{false, {}, false, std::nullopt};
  ASSERT_TRUE(compile_kernel(loaded->ir, 8, memory_only).ok());
  std::unique_ptr<TieredKernel> kernel = make_tiered_kernel(loaded->ir, 8, memory_only, true);
  for (int wait = 0; wait < 600 && !kernel->report().jit_ready; ++wait)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_TRUE(kernel->report().jit_ready);
  EXPECT_EQ(kernel->report().quick_ready_milliseconds, 0.0);
}

}  // namespace
}  // namespace shadetree

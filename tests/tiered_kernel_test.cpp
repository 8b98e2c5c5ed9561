// Tiered execution: runs on the interpreter until the JIT's compile is
// done, then on the JIT, with the same output bit for bit.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "pipeline/compile_graph.h"
#include "pipeline/tiered_kernel.h"
#include "support/graph_text.h"

namespace shadetree {
namespace {

TEST(TieredKernel, SwitchesFromInterpreterToJitWithIdenticalOutput) {
  // A chain of exps on varying P: tens of milliseconds to compile at least.
  std::string nodes = R"({"id": "p", "op": "P"}, {"id": "s", "op": "split", "in": {"v": "p"}},
                         {"id": "v0", "op": "mul", "in": {"a": "s.x", "b": 0.01}})";
  for (int i = 1; i <= 120; ++i)
    nodes += R"(, {"id": "v)" + std::to_string(i) + R"(", "op": "exp", "in": {"x": "v)" + std::to_string(i - 1) +
             R"("}}, {"id": "w)" + std::to_string(i) + R"(", "op": "mul", "in": {"a": "v)" + std::to_string(i) +
             R"(", "b": 0.001}})";
  Result<LoadedGraph> loaded =
      compile_graph_text(testing::graph_text(nodes, R"("color": "w120")"), "chain.json");
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

}  // namespace
}  // namespace shadetree

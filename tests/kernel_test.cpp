// The kernel interface (ir/kernel.h): output layouts follow the contracts,
// sample buffers hold only what a program reads, a binding runs many times
// with the same result, and runs on index lists agree sample for sample
// with dense runs, in both backends.
#include <gtest/gtest.h>

#include <numeric>

#include "interp/interpreter.h"
#include "jit/jit_kernel.h"
#include "pipeline/compile_graph.h"
#include "support/graph_text.h"

namespace shadetree {
namespace {

const std::string surface_graph = testing::graph_text(
    R"({"id": "p", "op": "P"}, {"id": "n", "op": "N"}, {"id": "t", "op": "time"},
       {"id": "f", "op": "fbm", "in": {"p": "p", "octaves": 4}},
       {"id": "g", "op": "add", "in": {"a": "f", "b": "t"}},
       {"id": "c", "op": "lt", "in": {"a": "f", "b": 0}},
       {"id": "k", "op": "if", "in": {"cond": "c", "then": "n", "else": "p"}})",
    R"("color": "g", "normal": "k", "opacity": 0.5)", "", "surface");

TEST(OutputLayout, FollowsTheContractOfTheKind) {
  Result<LoadedGraph> loaded = compile_graph_text(surface_graph, "s.json");
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  const OutputLayout layout = output_layout(loaded->ir);
  EXPECT_EQ(layout.plane_count, 12);  // color 3, normal 3, specular, roughness, opacity, emission 3
  EXPECT_EQ(layout.plane(OutputId::color), 0);
  EXPECT_EQ(layout.plane(OutputId::normal, 2), 5);
  EXPECT_EQ(layout.plane(OutputId::opacity), 8);
  EXPECT_FALSE(layout.provides(OutputId::specular));
  EXPECT_FALSE(layout.provides(OutputId::emission));
  EXPECT_EQ(provided_planes(layout), (std::vector<int>{0, 1, 2, 3, 4, 5, 8}));
}

TEST(SampleBuffers, HoldOnlyTheGlobalsAProgramReads) {
  Result<LoadedGraph> loaded = compile_graph_text(surface_graph, "s.json");
  ASSERT_TRUE(loaded.ok());
  const GlobalSet read = globals_read(loaded->ir);
  EXPECT_TRUE(read.test(static_cast<std::size_t>(GlobalId::P)));
  EXPECT_TRUE(read.test(static_cast<std::size_t>(GlobalId::time)));
  EXPECT_FALSE(read.test(static_cast<std::size_t>(GlobalId::uv)));
  SampleBuffers buffers(10, read);
  EXPECT_TRUE(buffers.has(GlobalId::N));
  EXPECT_FALSE(buffers.has(GlobalId::uv));
  const SampleInputs inputs = buffers.inputs();
  EXPECT_NE(inputs.plane(GlobalId::N, 2), nullptr);
  EXPECT_EQ(inputs.plane(GlobalId::uv), nullptr);
  EXPECT_EQ(varying_planes(read), (std::vector<int>{0, 1, 2, 3, 4, 5}));
}

// Samples whose P and N vary, and output planes for the whole layout.
struct Run {
  static constexpr std::size_t count = 301;
  SampleBuffers input{count, GlobalSet().set()};
  std::vector<std::vector<float>> planes;

  explicit Run(int plane_count) : planes(static_cast<std::size_t>(plane_count), std::vector<float>(count, -7.0f)) {
    for (std::size_t i = 0; i < count; ++i)
      for (int c = 0; c < 3; ++c) {
        input.plane(GlobalId::P, c)[i] = 0.37f * static_cast<float>(i) - 40.0f + static_cast<float>(c);
        input.plane(GlobalId::N, c)[i] = c == 2 ? 1.0f : 0.01f * static_cast<float>(i);
      }
  }
  std::vector<float*> outputs() {
    std::vector<float*> pointers;
    for (auto& plane : planes) pointers.push_back(plane.data());
    return pointers;
  }
};

void expect_indexed_runs_agree(const Kernel& kernel, const std::vector<float>& params) {
  UniformInputs uniforms;
  uniforms.set(GlobalId::time, 0.25f);
  std::unique_ptr<BoundKernel> bound = kernel.bind(params.data(), uniforms);
  Run dense(kernel.outputs().plane_count), again(kernel.outputs().plane_count), indexed(kernel.outputs().plane_count);
  bound->run(dense.input.inputs(), dense.outputs().data(), Run::count);
  bound->run(again.input.inputs(), again.outputs().data(), Run::count);
  EXPECT_EQ(dense.planes, again.planes);

  // Every third sample, in reverse order: the others keep their -7.
  std::vector<std::uint32_t> index;
  for (std::uint32_t i = Run::count; i-- > 0;)
    if (i % 3 == 0) index.push_back(i);
  bound->run_indexed(indexed.input.inputs(), indexed.outputs().data(), index.data(), index.size());
  for (int p : provided_planes(kernel.outputs()))
    for (std::size_t i = 0; i < Run::count; ++i)
      ASSERT_EQ(indexed.planes[p][i], i % 3 == 0 ? dense.planes[p][i] : -7.0f) << "plane " << p << " sample " << i;
}

TEST(BoundKernel, InterpreterRunsOnIndexListsAsOnDensePlanes) {
  Result<LoadedGraph> loaded = compile_graph_text(surface_graph, "s.json");
  ASSERT_TRUE(loaded.ok());
  expect_indexed_runs_agree(*make_interpreted_kernel(loaded->ir), loaded->params);
}

TEST(BoundKernel, JitRunsOnIndexListsAsOnDensePlanes) {
  Result<LoadedGraph> loaded = compile_graph_text(surface_graph, "s.json");
  ASSERT_TRUE(loaded.ok());
  for (int width : {4, 8}) {
    Result<std::unique_ptr<Kernel>> kernel = make_jit_kernel(loaded->ir, width);
    ASSERT_TRUE(kernel.ok()) << kernel.error().to_string();
    expect_indexed_runs_agree(**kernel, loaded->params);
  }
}

TEST(KernelAbi, NamesEveryOpGlobalAndContract) {
  const std::string abi = kernel_abi();
  EXPECT_NE(abi.find("fbm "), std::string::npos);
  EXPECT_NE(abi.find("step_size float"), std::string::npos);
  EXPECT_NE(abi.find("volume: density float"), std::string::npos);
  EXPECT_EQ(abi, kernel_abi());
}

}  // namespace
}  // namespace shadetree

// The editor server's kernels: a new program renders at once (the
// interpreter while the JIT compiles in the background), requests for a
// program under compile share its kernel, each program compiles once, and
// past the bound of background compiles a program compiles before it runs.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "pipeline/compile_graph.h"
#include "server/preview_kernels.h"
#include "support/graph_text.h"

namespace shadetree {
namespace {

// The graph's colour is the constant `red`: a new program for each value.
ShadeIR constant_program(float red) {
  Result<LoadedGraph> loaded = compile_graph_text(
      testing::graph_text(R"({"id": "c", "op": "color", "in": {"r": )" + std::to_string(red) + "}}", R"("color": "c")"),
      "constant.json");
  EXPECT_TRUE(loaded.ok()) << loaded.error().to_string();
  return loaded ? loaded->ir : ShadeIR{};
}

float red_of(const Kernel& kernel) {
  std::unique_ptr<BoundKernel> bound = kernel.bind(nullptr, UniformInputs{});
  float red[1], green[1], blue[1], alpha[1];
  float* outputs[4] = {red, green, blue, alpha};
  bound->run(SampleInputs{}, outputs, 1);
  return red[0];
}

void wait_for_compiles(PreviewKernels& kernels) {
  for (int poll = 0; poll < 3000 && kernels.compiling() > 0; ++poll)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_EQ(kernels.compiling(), 0) << "a background compile ran for 30 s";
}

JitSettings memory_only() { return JitSettings{false, {}, false, std::nullopt}; }

TEST(PreviewKernels, ANewProgramRunsWhileItCompilesThenRunsCompiled) {
  PreviewKernels kernels(memory_only(), 2);
  const ShadeIR program = constant_program(0.5f);
  Result<PreviewKernel> first = kernels.kernel_for(program);
  ASSERT_TRUE(first.ok());
  EXPECT_EQ(first->source, PreviewKernel::Source::compiling);
  EXPECT_FLOAT_EQ(red_of(*first->kernel), 0.5f);
  Result<PreviewKernel> again = kernels.kernel_for(program);
  ASSERT_TRUE(again.ok());
  if (again->source == PreviewKernel::Source::compiling) {
    EXPECT_EQ(again->kernel, first->kernel) << "a request during the compile shares it";
  }
  wait_for_compiles(kernels);
  Result<PreviewKernel> compiled = kernels.kernel_for(program);
  ASSERT_TRUE(compiled.ok());
  EXPECT_EQ(compiled->source, PreviewKernel::Source::memory);
  EXPECT_FLOAT_EQ(red_of(*compiled->kernel), 0.5f);
  EXPECT_EQ(kernels.compiles(), 1) << "one program, one compile";
  EXPECT_STREQ(source_name(compiled->source), "memory");
}

TEST(PreviewKernels, PastTheBoundAProgramCompilesBeforeItRuns) {
  PreviewKernels kernels(memory_only(), 0);
  Result<PreviewKernel> kernel = kernels.kernel_for(constant_program(0.75f));
  ASSERT_TRUE(kernel.ok());
  EXPECT_EQ(kernel->source, PreviewKernel::Source::compiled);
  EXPECT_EQ(kernels.compiling(), 0);
  EXPECT_EQ(kernels.compiles(), 1);
  EXPECT_FLOAT_EQ(red_of(*kernel->kernel), 0.75f);
}

TEST(PreviewKernels, ManyNewProgramsAllRunAndEachCompilesOnce) {
  PreviewKernels kernels(memory_only(), 2);
  constexpr int programs = 8;
  for (int i = 0; i < programs; ++i) {
    Result<PreviewKernel> kernel = kernels.kernel_for(constant_program(1.0f + static_cast<float>(i)));
    ASSERT_TRUE(kernel.ok());
    EXPECT_LE(kernels.compiling(), 2) << "background compiles stay at their bound";
    EXPECT_FLOAT_EQ(red_of(*kernel->kernel), 1.0f + static_cast<float>(i));
  }
  wait_for_compiles(kernels);
  EXPECT_EQ(kernels.compiles(), programs);
  for (int i = 0; i < programs; ++i)
    EXPECT_EQ(kernels.kernel_for(constant_program(1.0f + static_cast<float>(i)))->source,
              PreviewKernel::Source::memory);
}

}  // namespace
}  // namespace shadetree

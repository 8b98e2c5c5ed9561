// The JIT emits vector code of the chosen width and caches kernels: a second
// compile of the same graph is a lookup, params are bound at call time,
// compiled objects land in the disk cache, and the memory cache is bounded,
// releasing kernels no one uses.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <thread>
#include <vector>

#include "pipeline/compile_graph.h"
#include "jit/jit_compiler.h"
#include "interp/interpreter.h"
#include "jit/jit_kernel.h"
#include "support/differential_samples.h"
#include "support/gallery.h"
#include "support/graph_text.h"

namespace shadetree {
namespace {

const std::string noise_graph = testing::graph_text(
    R"({"id": "p", "op": "P"}, {"id": "q", "op": "mul", "in": {"a": "p", "b": "$scale"}},
       {"id": "n", "op": "turbulence", "in": {"p": "q", "octaves": 4}},
       {"id": "c", "op": "color", "in": {"r": "n"}})",
    R"("color": "c")", R"("params": {"scale": {"type": "float", "default": 3}},)");

JitSettings memory_only() { return JitSettings{false, {}, false, std::nullopt}; }

TEST(JitCompiler, NoiseKernelsUseVectorsOfTheChosenWidth) {
  Result<LoadedGraph> loaded = compile_graph_text(noise_graph, "noise.json");
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  for (int width : {4, 8, 16}) {
    Result<std::string> ir = kernel_listing(loaded->ir, width, Listing::optimized_llvm_ir);
    ASSERT_TRUE(ir.ok()) << ir.error().to_string();
    const std::string vector = "<" + std::to_string(width) + " x float>";
    EXPECT_NE(ir->find("fmul " + vector), std::string::npos) << "width " << width;
    EXPECT_NE(ir->find("@llvm.floor.v" + std::to_string(width) + "f32"), std::string::npos) << "width " << width;
    EXPECT_EQ(ir->find("@st_"), std::string::npos) << "the op library should be inlined";
  }
  Result<std::string> assembly = kernel_listing(loaded->ir, 8, Listing::assembly);
  ASSERT_TRUE(assembly.ok());
  EXPECT_NE(assembly->find("ymm"), std::string::npos);
}

// An if's branches become blocks that a conditional branch skips when no
// lane takes them.
TEST(JitCompiler, IfBranchesAreRegionsSkippedWhenNoLaneTakesThem) {
  Result<LoadedGraph> loaded = compile_graph_text(testing::graph_text(
      R"({"id": "p", "op": "P"}, {"id": "s", "op": "split", "in": {"v": "p"}},
         {"id": "cond", "op": "lt", "in": {"a": "s.x", "b": 0.5}},
         {"id": "t", "op": "turbulence", "in": {"p": "p"}}, {"id": "n", "op": "noise", "in": {"p": "p"}},
         {"id": "pick", "op": "if", "in": {"cond": "cond", "then": "t", "else": "n"}})",
      R"("color": "pick")"), "if.json");
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  Result<std::string> ir = kernel_listing(loaded->ir, 8, Listing::optimized_llvm_ir);
  ASSERT_TRUE(ir.ok()) << ir.error().to_string();
  EXPECT_NE(ir->find("label %after_region, label %region"), std::string::npos) << *ir;
  EXPECT_NE(ir->find("label %after_region2, label %region1"), std::string::npos);
}

// Regression: a global with a constructor in the op library's headers (a
// std::vector of spline basis names) was compiled into every kernel, with
// its initializer, and made LLJIT build a module of its own for it.
TEST(JitCompiler, KernelsHoldOnlyTheirTwoFunctions) {
  Result<LoadedGraph> loaded = compile_graph_text(
      testing::graph_text(R"({"id": "p", "op": "P"}, {"id": "s", "op": "split", "in": {"v": "p"}},
         {"id": "c", "op": "spline", "in": {"x": "s.x"}, "knots": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]]})",
                          R"("color": "c")"),
      "spline.json");
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  Result<std::string> ir = kernel_listing(loaded->ir, 8, Listing::optimized_llvm_ir);
  ASSERT_TRUE(ir.ok()) << ir.error().to_string();
  int functions = 0;
  for (std::size_t at = ir->find("\ndefine "); at != std::string::npos; at = ir->find("\ndefine ", at + 1)) ++functions;
  EXPECT_EQ(functions, 2) << *ir;
  EXPECT_EQ(ir->find("global_ctors"), std::string::npos);
}

// Every table a kernel reads is its own: a weak (linkonce_odr) table from
// the op library, shared by name, bound later kernels to the first
// kernel's copy, and releasing that kernel crashed them (found by the
// random differential test once the memory cache was bounded).
TEST(JitCompiler, KernelsShareNoDataByName) {
  Result<LoadedGraph> loaded = compile_graph_text(
      testing::graph_text(R"({"id": "p", "op": "P"}, {"id": "n", "op": "noise_improved", "in": {"p": "p"}},
         {"id": "c", "op": "color", "in": {"r": "n"}})",
                          R"("color": "c")"),
      "improved.json");
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  Result<std::string> ir = kernel_listing(loaded->ir, 8, Listing::optimized_llvm_ir);
  ASSERT_TRUE(ir.ok()) << ir.error().to_string();
  int globals = 0;
  std::istringstream lines(*ir);
  for (std::string line; std::getline(lines, line);) {
    if (line.empty() || line[0] != '@') continue;
    ++globals;
    EXPECT_TRUE(line.find(" internal ") != std::string::npos || line.find(" private ") != std::string::npos)
        << line.substr(0, 120);
  }
  EXPECT_GT(globals, 0) << "the permutation table is in the kernel";
}

// Past the inlining budget, an op used by many nodes is compiled once and
// called: a chain of 200 exps compiles to a few functions, not one huge
// one (`exp` once in each module of the kernel split in two).
TEST(JitCompiler, LargeGraphsCallTheirLargestOpsInsteadOfInliningThem) {
  std::string nodes = R"({"id": "p", "op": "P"}, {"id": "s", "op": "split", "in": {"v": "p"}},
                         {"id": "v0", "op": "mul", "in": {"a": "s.x", "b": 1}})";
  for (int i = 1; i <= 200; ++i)
    nodes += R"(, {"id": "v)" + std::to_string(i) + R"(", "op": "exp", "in": {"x": "v)" + std::to_string(i - 1) +
             R"("}})";
  Result<LoadedGraph> loaded = compile_graph_text(testing::graph_text(nodes, R"("color": "v200")"), "exp.json");
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  Result<std::string> ir = kernel_listing(loaded->ir, 8, Listing::optimized_llvm_ir);
  ASSERT_TRUE(ir.ok()) << ir.error().to_string();
  int definitions = 0, calls = 0, modules = 0;
  std::istringstream lines(*ir);
  for (std::string line; std::getline(lines, line);) {
    modules += line.rfind("; module ", 0) == 0;
    if (line.find("@st_exp_w8(") == std::string::npos) continue;
    definitions += line.rfind("define ", 0) == 0;
    calls += line.find("call ") != std::string::npos;
  }
  EXPECT_EQ(modules, 2);
  EXPECT_EQ(definitions, 2);
  EXPECT_EQ(calls, 200);
}

TEST(JitCompiler, SecondCompileHitsTheCacheAndParamsNeedNoRecompile) {
  Result<LoadedGraph> loaded = compile_graph_text(noise_graph, "noise.json");
  ASSERT_TRUE(loaded.ok());
  Result<CompiledKernel> first = compile_kernel(loaded->ir, 8, memory_only());
  ASSERT_TRUE(first.ok()) << first.error().to_string();
  Result<LoadedGraph> retuned = compile_graph_text(noise_graph, "noise.json", {"scale=7.5"});
  ASSERT_TRUE(retuned.ok());
  Result<CompiledKernel> second = compile_kernel(retuned->ir, 8, memory_only());
  ASSERT_TRUE(second.ok());
  EXPECT_EQ(second->cache, CacheHit::memory);
  EXPECT_EQ(second->run, first->run);

  // The same machine code gives different values for different params,
  // bound once each.
  float px[8] = {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f, 0.7f, 0.8f}, zero[8] = {};
  float red[2][8], green[8], blue[8], alpha[8];
  const float* inputs[varying_plane_count] = {px, px, zero};
  const UniformInputs uniforms;
  std::vector<float> state(static_cast<std::size_t>(first->state_size) + 1);
  for (int run = 0; run < 2; ++run) {
    float* outputs[4] = {red[run], green, blue, alpha};
    const std::vector<float>& params = run == 0 ? loaded->params : retuned->params;
    first->bind(params.data(), uniforms.values, state.data());
    first->run(state.data(), inputs, outputs, 8);
  }
  EXPECT_NE(std::vector<float>(red[0], red[0] + 8), std::vector<float>(red[1], red[1] + 8));
}

TEST(JitCompiler, CompiledObjectsGoToTheDiskCache) {
  const auto folder = std::filesystem::temp_directory_path() / "shadetree-jit-disk-cache-test";
  std::filesystem::remove_all(folder);
  Result<LoadedGraph> loaded = compile_graph_text(noise_graph, "noise.json");
  ASSERT_TRUE(loaded.ok());
  Result<CompiledKernel> compiled = compile_kernel(loaded->ir, 4, JitSettings{true, folder.string(), false, std::nullopt});
  ASSERT_TRUE(compiled.ok()) << compiled.error().to_string();
  std::size_t objects = 0;
  std::string names;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    objects += entry.path().extension() == ".o";
    names += entry.path().filename().string() + " ";
  }
  EXPECT_EQ(objects, 1u) << names;
  std::filesystem::remove_all(folder);
}

// Enough work for a kernel split in two (codegen/kernel_split.h).
const std::string split_graph = testing::graph_text(
    R"({"id": "p", "op": "P"}, {"id": "t", "op": "turbulence", "in": {"p": "p", "octaves": 6}},
       {"id": "f", "op": "fbm", "in": {"p": "p", "octaves": 5}}, {"id": "tf", "op": "add", "in": {"a": "t", "b": "f"}},
       {"id": "q", "op": "mul", "in": {"a": "p", "b": 3}}, {"id": "v", "op": "dnoise", "in": {"p": "q"}},
       {"id": "l", "op": "length", "in": {"v": "v"}}, {"id": "s", "op": "add", "in": {"a": "tf", "b": "l"}},
       {"id": "k", "op": "spline", "in": {"x": "s"}, "basis": "catmull-rom",
        "knots": [[0, 0, 0], [0, 0.1, 0.2], [0.5, 0.4, 0.3], [1, 0.9, 0.6], [1, 1, 1]]},
       {"id": "n", "op": "noise", "in": {"p": "p"}}, {"id": "m", "op": "mul", "in": {"a": "k", "b": "n"}})",
    R"("color": "m")");

// The graph's colour is the constant `red`: a new program for each value.
Result<LoadedGraph> constant_graph(float red) {
  return compile_graph_text(testing::graph_text(R"({"id": "c", "op": "color", "in": {"r": )" + std::to_string(red) + "}}",
                                                R"("color": "c")"),
                            "constant.json");
}

float red_of(const Kernel& kernel) {
  std::unique_ptr<BoundKernel> bound = kernel.bind(nullptr, UniformInputs{});
  float red[1], green[1], blue[1], alpha[1];
  float* outputs[4] = {red, green, blue, alpha};
  bound->run(SampleInputs{}, outputs, 1);  // a constant reads no planes
  return red[0];
}

TEST(JitCompiler, TheMemoryCacheIsBoundedAndKernelsInUseOutliveIt) {
  Result<LoadedGraph> held_graph = constant_graph(0.25f);
  ASSERT_TRUE(held_graph.ok()) << held_graph.error().to_string();
  Result<std::unique_ptr<Kernel>> held = make_jit_kernel(held_graph->ir, 4, memory_only());
  ASSERT_TRUE(held.ok()) << held.error().to_string();
  const long resident_before = resident_kernel_count();
  for (int i = 1; i <= memory_cache_kernels + 10; ++i) {
    Result<LoadedGraph> other = constant_graph(1.0f + static_cast<float>(i));
    ASSERT_TRUE(other.ok());
    ASSERT_TRUE(compile_kernel(other->ir, 4, memory_only()).ok());
  }
  EXPECT_LE(resident_kernel_count(), resident_before + memory_cache_kernels)
      << "kernels beyond the cache, used by no Kernel, leave the JIT";
  EXPECT_FLOAT_EQ(red_of(**held), 0.25f) << "a kernel in use keeps its code after leaving the cache";
  Result<CompiledKernel> again = compile_kernel(held_graph->ir, 4, memory_only());
  ASSERT_TRUE(again.ok());
  EXPECT_EQ(again->cache, CacheHit::memory) << "and is found again while in use";
  held->reset();
  const long resident_with_again = resident_kernel_count();
  *again = CompiledKernel{};
  for (int i = 1; i <= memory_cache_kernels; ++i) {
    Result<LoadedGraph> other = constant_graph(100.0f + static_cast<float>(i));
    ASSERT_TRUE(other.ok());
    ASSERT_TRUE(compile_kernel(other->ir, 4, memory_only()).ok());
  }
  EXPECT_LE(resident_kernel_count(), resident_with_again) << "the cache stays at its bound";
  Result<CompiledKernel> recompiled = compile_kernel(held_graph->ir, 4, memory_only());
  ASSERT_TRUE(recompiled.ok()) << "a released program compiles anew: " << recompiled.error().to_string();
  EXPECT_EQ(recompiled->cache, CacheHit::none);
  EXPECT_FLOAT_EQ(red_of(*make_jit_kernel(held_graph->ir, *recompiled)), 0.25f);
}

TEST(JitCompiler, TheDiskCacheKeepsTheMostRecentlyUsedObjects) {
  const auto folder = std::filesystem::temp_directory_path() / "shadetree-jit-disk-cache-bound-test";
  std::filesystem::remove_all(folder);
  JitSettings settings{true, folder.string(), false, std::nullopt, 3};
  for (int i = 0; i < 5; ++i) {
    Result<LoadedGraph> graph = constant_graph(200.0f + static_cast<float>(i));
    ASSERT_TRUE(graph.ok());
    ASSERT_TRUE(compile_kernel(graph->ir, 4, settings).ok());
  }
  std::size_t objects = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) objects += entry.path().extension() == ".o";
  EXPECT_EQ(objects, 3u);
  std::filesystem::remove_all(folder);
}

// Compiles more kernels than the memory cache holds, and lets them go.
void evict_memory_cache() {
  for (int i = 0; i <= memory_cache_kernels; ++i) {
    Result<LoadedGraph> graph = constant_graph(1000.0f + static_cast<float>(i));
    ASSERT_TRUE(graph.ok());
    ASSERT_TRUE(compile_kernel(graph->ir, 4, memory_only()).ok());
  }
}

// The names of the objects in the disk cache `folder`, sorted.
std::vector<std::string> cached_objects(const std::filesystem::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    if (entry.path().extension() == ".o") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

// A split kernel is two objects, cached together: it is read back from
// the disk only when both are there, and compiled anew otherwise.
TEST(JitCompiler, SplitKernelsKeepBothObjectsInTheDiskCache) {
  const auto folder = std::filesystem::temp_directory_path() / "shadetree-jit-split-cache-test";
  std::filesystem::remove_all(folder);
  const JitSettings settings{true, folder.string(), false, std::nullopt};
  Result<LoadedGraph> loaded = compile_graph_text(split_graph, "split.json");
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  auto objects = [&] { return cached_objects(folder); };
  const std::string name = kernel_identity(loaded->ir, 8, settings);
  {
    Result<CompiledKernel> compiled = compile_kernel(loaded->ir, 8, settings);
    ASSERT_TRUE(compiled.ok()) << compiled.error().to_string();
    EXPECT_EQ(compiled->cache, CacheHit::none);
  }
  const std::vector<std::string> cached = objects();  // with a half, if a module's code is generated in two
  EXPECT_EQ(std::count(cached.begin(), cached.end(), name), 1);
  EXPECT_EQ(std::count(cached.begin(), cached.end(), name + "_first"), 1);
  evict_memory_cache();
  {
    Result<CompiledKernel> reloaded = compile_kernel(loaded->ir, 8, settings);
    ASSERT_TRUE(reloaded.ok()) << reloaded.error().to_string();
    EXPECT_EQ(reloaded->cache, CacheHit::disk);
  }
  std::filesystem::remove(folder / (name + "_first.o"));
  evict_memory_cache();
  Result<CompiledKernel> recompiled = compile_kernel(loaded->ir, 8, settings);
  ASSERT_TRUE(recompiled.ok()) << recompiled.error().to_string();
  EXPECT_EQ(recompiled->cache, CacheHit::none) << "half a kernel is no kernel";
  EXPECT_EQ(objects(), cached);
  std::filesystem::remove_all(folder);
}

// A compile says where its time went: each stage took some, a split
// kernel generated the code of both its modules (and of any half), and a
// cache hit compiled nothing.
TEST(JitCompiler, CompilesReportTheirStagesAndCacheHitsNone) {
  JitSettings cold = memory_only();
  cold.cold = true;
  Result<LoadedGraph> whole = compile_graph_text(noise_graph, "noise.json");
  ASSERT_TRUE(whole.ok()) << whole.error().to_string();
  Result<LoadedGraph> split = compile_graph_text(split_graph, "split.json");
  ASSERT_TRUE(split.ok()) << split.error().to_string();
  Result<CompiledKernel> compiled = compile_kernel(whole->ir, 8, cold);
  ASSERT_TRUE(compiled.ok()) << compiled.error().to_string();
  const CompileStages& stages = compiled->stages;
  EXPECT_GT(stages.emit_milliseconds, 0.0);
  EXPECT_GT(stages.optimize_milliseconds, 0.0);
  EXPECT_GT(stages.generate_milliseconds, 0.0);
  EXPECT_EQ(stages.modules, 1);
  // One module, compiled on the calling thread: its stages are parts of
  // the compile's time.
  EXPECT_LE(stages.emit_milliseconds + stages.optimize_milliseconds + stages.generate_milliseconds,
            compiled->compile_milliseconds);
  Result<CompiledKernel> parts = compile_kernel(split->ir, 8, cold);
  ASSERT_TRUE(parts.ok()) << parts.error().to_string();
  EXPECT_GE(parts->stages.modules, 2);
  ASSERT_TRUE(compile_kernel(whole->ir, 8, memory_only()).ok());
  Result<CompiledKernel> hit = compile_kernel(whole->ir, 8, memory_only());
  ASSERT_TRUE(hit.ok()) << hit.error().to_string();
  EXPECT_EQ(hit->cache, CacheHit::memory);
  EXPECT_EQ(hit->stages.modules, 0);
  EXPECT_EQ(hit->stages.emit_milliseconds + hit->stages.optimize_milliseconds + hit->stages.generate_milliseconds, 0.0);
}

// A module whose code is generated in two halves (jit/module_halves.h) is
// two objects, cached with the kernel's others; without its half the
// kernel is compiled anew, quietly.
TEST(JitCompiler, HalvedKernelsKeepTheirHalfInTheDiskCache) {
  const auto folder = std::filesystem::temp_directory_path() / "shadetree-jit-halves-cache-test";
  std::filesystem::remove_all(folder);
  const JitSettings settings{true, folder.string(), false, GatherStrategy::per_lane};
  // Where looping_turbulence's first part is well past the size that
  // halves a module.
  constexpr int width = 16;
  Result<LoadedGraph> loaded = testing::load_gallery_graph(SHADETREE_SOURCE_DIR "/graphs/looping_turbulence.json");
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  auto objects = [&] { return cached_objects(folder); };
  const std::string name = kernel_identity(loaded->ir, width, settings);
  const std::vector<std::string> all = {name, name + "_first", name + "_first_half"};
  evict_memory_cache();  // compiled by a test before
  ASSERT_TRUE(compile_kernel(loaded->ir, width, settings).ok());
  EXPECT_EQ(objects(), all);
  evict_memory_cache();
  {
    Result<CompiledKernel> reloaded = compile_kernel(loaded->ir, width, settings);
    ASSERT_TRUE(reloaded.ok()) << reloaded.error().to_string();
    EXPECT_EQ(reloaded->cache, CacheHit::disk);
  }
  std::filesystem::remove(folder / (name + "_first_half.o"));
  evict_memory_cache();
  ::testing::internal::CaptureStderr();
  Result<CompiledKernel> recompiled = compile_kernel(loaded->ir, width, settings);
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  ASSERT_TRUE(recompiled.ok()) << recompiled.error().to_string();
  EXPECT_EQ(recompiled->cache, CacheHit::none) << "half a kernel is no kernel";
  EXPECT_EQ(objects(), all);
  std::filesystem::remove_all(folder);
}

// A graph's large data (a mesh's distance grid) is not in its kernel's
// objects: the JIT binds the declared data to the kernel's own copy when

// A module is halved by what its parts cost the code generator, where a
// shuffle costs two instructions (jit/module_halves.cpp): the fireball's
// octave block begins with its knot rows' loads and transposes, so the
// half cut from that block (in the first part of the split kernel) is
// denser in shuffles than the rest of its module and holds fewer
// instructions, balanced by cost. Counted alike, a half of the whole
// kernel held more (1117 instructions to 1028) and took 31 ms of code
// generation to the rest's 13.
TEST(JitCompiler, HalvesCountAShuffleAsTwoInstructions) {
  Result<LoadedGraph> loaded = testing::load_gallery_graph(SHADETREE_SOURCE_DIR "/graphs/fireball.json");
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  JitSettings per_lane;
  per_lane.gathers = GatherStrategy::per_lane;
  Result<std::string> listing = kernel_listing(loaded->ir, 16, Listing::optimized_llvm_ir, per_lane);
  ASSERT_TRUE(listing.ok()) << listing.error().to_string();
  const std::size_t cut = listing->find("; the half of this module compiled on a thread of its own");
  ASSERT_NE(cut, std::string::npos) << "generated whole";
  struct Counts {
    int instructions = 0, shuffles = 0;
  };
  auto count = [](const std::string& module) {
    Counts counts;
    std::istringstream lines(module);
    for (std::string line; std::getline(lines, line);)
      if (line.size() > 2 && line.starts_with("  ") && line[2] != ' ' && line[2] != ';') {
        ++counts.instructions;
        if (line.find("= shufflevector ") != std::string::npos) ++counts.shuffles;
      }
    return counts;
  };
  // The module the half was cut from: from its heading (the kernel is
  // split in two) to the half, which runs to the next module's heading.
  const std::size_t heading = listing->rfind("; module", cut);
  const std::size_t from = heading == std::string::npos ? 0 : heading;
  const Counts rest = count(listing->substr(from, cut - from)),
               half = count(listing->substr(cut, listing->find("; module", cut) - cut));
  EXPECT_LT(half.instructions, rest.instructions);
  EXPECT_GT(half.shuffles * rest.instructions, rest.shuffles * half.instructions);
  const int half_cost = half.instructions + half.shuffles, rest_cost = rest.instructions + rest.shuffles;
  EXPECT_GE(10 * half_cost, 3 * (half_cost + rest_cost));
}
// it links them, compiled or read from the disk cache, and the kernel
// computes what the interpreter does.
TEST(JitCompiler, KernelsOfLargeDataBindItWhenLinked) {
  const auto folder = std::filesystem::temp_directory_path() / "shadetree-jit-data-cache-test";
  std::filesystem::remove_all(folder);
  const JitSettings settings{true, folder.string(), false, std::nullopt};
  Result<LoadedGraph> loaded = testing::load_gallery_graph(SHADETREE_SOURCE_DIR "/graphs/mesh_hypertexture.json");
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  ASSERT_GT(loaded->ir.data.size() * sizeof(float), max_embedded_data_bytes);
  Result<std::string> listing = kernel_listing(loaded->ir, 8, Listing::optimized_llvm_ir);
  ASSERT_TRUE(listing.ok()) << listing.error().to_string();
  EXPECT_NE(listing->find("@shade_kernel_data = external constant"), std::string::npos);
  const auto reference = testing::run(*make_interpreted_kernel(loaded->ir), loaded->params);
  for (CacheHit expected : {CacheHit::none, CacheHit::disk}) {
    evict_memory_cache();
    Result<CompiledKernel> compiled = compile_kernel(loaded->ir, 8, settings);
    ASSERT_TRUE(compiled.ok()) << compiled.error().to_string();
    EXPECT_EQ(compiled->cache, expected);
    Result<std::unique_ptr<Kernel>> kernel = make_jit_kernel(loaded->ir, 8, settings);
    ASSERT_TRUE(kernel.ok()) << kernel.error().to_string();
    EXPECT_EQ(testing::run(**kernel, loaded->params), reference) << "cache " << static_cast<int>(expected);
  }
  std::filesystem::remove_all(folder);
}

TEST(JitCompiler, CachedKernelFindsOnlyWhatWasCompiled) {
  Result<LoadedGraph> graph = constant_graph(300.0f);
  ASSERT_TRUE(graph.ok());
  EXPECT_FALSE(cached_kernel(graph->ir, 4, memory_only()).has_value()) << "nothing is compiled to look";
  ASSERT_TRUE(compile_kernel(graph->ir, 4, memory_only()).ok());
  std::optional<CompiledKernel> found = cached_kernel(graph->ir, 4, memory_only());
  ASSERT_TRUE(found.has_value());
  EXPECT_EQ(found->cache, CacheHit::memory);
  EXPECT_FLOAT_EQ(red_of(*make_jit_kernel(graph->ir, *found)), 300.0f);
  JitSettings cold = memory_only();
  cold.cold = true;
  EXPECT_FALSE(cached_kernel(graph->ir, 4, cold).has_value()) << "a cold compile bypasses the caches";
}

// A quick kernel is the same program with less optimization: it is
// compiled anew each time, never found in or added to a cache, and its
// code is the fast code generator's (no full kernel comes of it).
TEST(JitCompiler, QuickKernelsAreCompiledAnewAndNeverCached) {
  Result<LoadedGraph> graph = constant_graph(350.0f);
  ASSERT_TRUE(graph.ok());
  JitSettings quick = memory_only();
  quick.optimization = Optimization::quick;
  Result<CompiledKernel> first = compile_kernel(graph->ir, 4, quick);
  ASSERT_TRUE(first.ok()) << first.error().to_string();
  Result<CompiledKernel> second = compile_kernel(graph->ir, 4, quick);
  ASSERT_TRUE(second.ok());
  EXPECT_EQ(first->cache, CacheHit::none);
  EXPECT_EQ(second->cache, CacheHit::none);
  EXPECT_NE(first->code, second->code);
  EXPECT_FLOAT_EQ(red_of(*make_jit_kernel(graph->ir, *first)), 350.0f);
  EXPECT_FALSE(cached_kernel(graph->ir, 4, quick).has_value());
  EXPECT_FALSE(cached_kernel(graph->ir, 4, memory_only()).has_value()) << "a quick compile leaves no full kernel";
}

// The quick pipeline still inlines the op library and keeps vectors.
TEST(JitCompiler, QuickListingsInlineTheLibrary) {
  Result<LoadedGraph> loaded = compile_graph_text(noise_graph, "noise.json");
  ASSERT_TRUE(loaded.ok());
  JitSettings quick;
  quick.optimization = Optimization::quick;
  Result<std::string> ir = kernel_listing(loaded->ir, 8, Listing::optimized_llvm_ir, quick);
  ASSERT_TRUE(ir.ok()) << ir.error().to_string();
  EXPECT_NE(ir->find("fmul <8 x float>"), std::string::npos);
  EXPECT_EQ(ir->find("@st_"), std::string::npos) << "the op library should be inlined";
}

// Compiles run outside the JIT's lock: threads compiling the same program
// at once all get one working kernel, and different programs all compile.
TEST(JitCompiler, ThreadsCompileInParallel) {
  constexpr int threads = 6;
  std::vector<Result<CompiledKernel>> same(threads, Diagnostic{}), different(threads, Diagnostic{});
  Result<LoadedGraph> shared_graph = constant_graph(400.0f);
  ASSERT_TRUE(shared_graph.ok());
  std::vector<Result<LoadedGraph>> graphs;
  for (int i = 0; i < threads; ++i) graphs.push_back(constant_graph(401.0f + static_cast<float>(i)));
  {
    std::vector<std::jthread> running;
    for (int i = 0; i < threads; ++i)
      running.emplace_back([&, i] {
        same[i] = compile_kernel(shared_graph->ir, 4, memory_only());
        different[i] = compile_kernel(graphs[i]->ir, 4, memory_only());
      });
  }
  for (int i = 0; i < threads; ++i) {
    ASSERT_TRUE(same[i].ok()) << same[i].error().to_string();
    ASSERT_TRUE(different[i].ok()) << different[i].error().to_string();
    EXPECT_EQ(same[i]->code, same[0]->code) << "one kernel in the JIT for one program";
    EXPECT_FLOAT_EQ(red_of(*make_jit_kernel(shared_graph->ir, *same[i])), 400.0f);
    EXPECT_FLOAT_EQ(red_of(*make_jit_kernel(graphs[i]->ir, *different[i])), 401.0f + static_cast<float>(i));
  }
}

}  // namespace
}  // namespace shadetree

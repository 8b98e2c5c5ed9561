// Differential testing: the JIT must compute exactly what the interpreter
// computes, bit for bit, for the gallery, for every node of the
// library over every type it accepts, and for hundreds of random well-typed
// graphs; on samples that include lattice points, negative and large
// (1e4) coordinates and vector tails.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <sstream>

#include "pipeline/compile_graph.h"
#include "support/differential_samples.h"
#include "support/gallery.h"
#include "support/graph_text.h"
#include "support/random_graph.h"
#include "support/test_files.h"
#include "interp/interpreter.h"
#include "ir/verify.h"
#include "jit/jit_compiler.h"
#include "jit/jit_kernel.h"
#include "graph/check.h"
#include "nodes/limits.h"
#include "nodes/registry.h"

namespace shadetree {
namespace {

using testing::attributes_for;
using testing::header;
using testing::preamble;
using testing::RandomGraph;
using testing::run;
using testing::samples;
using testing::SampleSet;
using testing::three_component_outputs;
using testing::to_color;

// The backends run the same semantics with the same operations in the
// same order (and no contraction into fused multiply-adds), so they agree
// to the bit; NaN agrees with NaN.
bool agree(float a, float b) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  return a == b;
}

// Compares the backends on `ir`; returns "" or the first disagreement.
std::string compare_backends(const std::string& name, const ShadeIR& ir, const std::vector<float>& params,
                             int width, std::optional<GatherStrategy> gathers = std::nullopt,
                             Optimization optimization = Optimization::full) {
  auto reference = run(*make_interpreted_kernel(ir), params);
  JitSettings settings{false, {}, false, gathers};
  settings.optimization = optimization;
  Result<std::unique_ptr<Kernel>> jit = make_jit_kernel(ir, width, settings);
  if (!jit) return name + ": JIT failed: " + jit.error().to_string();
  auto compiled = run(**jit, params);
  for (std::size_t plane = 0; plane < reference.size(); ++plane)
    for (std::size_t i = 0; i < SampleSet::count; ++i)
      if (!agree(reference[plane][i], compiled[plane][i])) {
        std::ostringstream message;
        message.precision(9);
        message << name << " (width " << width << "): output plane " << plane << " sample " << i << " at P = ("
                << samples().P(0, i) << ", " << samples().P(1, i) << ", " << samples().P(2, i)
                << "): interp " << reference[plane][i] << ", jit " << compiled[plane][i];
        return message.str();
      }
  return "";
}

// Every generated program is verified after lowering and after each pass.
Result<LoadedGraph> compile_text(const std::string& text) {
  const PassObserver verify = [&](const char* pass, const ShadeIR& ir) {
    const std::string problem = verify_shade_ir(ir);
    EXPECT_EQ(problem, "") << "after " << pass << "\n" << format_shade_ir(ir) << "\n" << text;
  };
  return compile_graph_text(text, "generated.json", {}, verify, testing::test_files());
}

// --- the gallery -------------------------------------------------------


class GalleryDifferential : public ::testing::TestWithParam<std::string> {};

TEST_P(GalleryDifferential, BackendsAgreeAtEveryWidth) {
  Result<LoadedGraph> loaded = testing::load_gallery_graph(GetParam());
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  for (int width : {4, 8, 16})
    EXPECT_EQ(compare_backends(GetParam(), loaded->ir, loaded->params, width), "");
  EXPECT_EQ(compare_backends(GetParam(), loaded->ir, loaded->params, 0, std::nullopt, Optimization::quick), "")
      << "quick kernel";
  EXPECT_EQ(compare_backends(GetParam(), loaded->ir, loaded->params, 8, GatherStrategy::hardware), "")
      << "hardware gathers at width 8";
  if (host_vector_width() < 16) return;  // the other strategies need AVX-512 at width 16
  for (GatherStrategy gathers : {GatherStrategy::hardware, GatherStrategy::per_lane, GatherStrategy::in_register,
                                 GatherStrategy::in_register_byte_permutes, GatherStrategy::byte_permutes_and_gathers,
                                 GatherStrategy::byte_permutes_and_per_lane})
    EXPECT_EQ(compare_backends(GetParam(), loaded->ir, loaded->params, 16, gathers), "")
        << "gather strategy " << static_cast<int>(gathers);
}

INSTANTIATE_TEST_SUITE_P(Gallery, GalleryDifferential, ::testing::ValuesIn(testing::gallery_graphs()),
                         [](const auto& info) { return testing::gallery_graph_name(info.param); });

// --- every node, over every type it accepts ------------------------------

// A source for an input of type `type`; `which` picks among alternatives.
std::string source_for(Type type, const std::string& port, int which) {
  const char* letter = which % 2 == 0 ? "a" : "b";
  switch (type) {
    case Type::float_:
      if (port == "filter_width") return "\"fw\"";
      return std::string("\"float_") + (which % 3 == 0 ? "a" : which % 3 == 1 ? "b" : "c") + "\"";
    case Type::int_: return port == "iterations" ? "40" : "5";
    case Type::bool_: return "\"bool_a\"";
    case Type::vec2: return std::string("\"vec2_") + letter + "\"";
    case Type::vec3: return std::string("\"vec3_") + letter + "\"";
    case Type::color: return std::string("\"color_") + letter + "\"";
  }
  return "0";
}

std::vector<std::string> single_node_graphs() {
  std::vector<std::string> graphs;
  for (const OpDef& op : all_ops()) {
    if (!op.kinds.contains(GraphKind::surface)) continue;  // volume only: covered with kind volume below
    std::vector<Type> instances{Type::float_};
    if (op.generic == GenericSet::numeric && !op.type_from_knots)
      instances = {Type::float_, Type::vec2, Type::vec3, Type::color};
    if (op.generic == GenericSet::vectors) instances = {Type::vec2, Type::vec3, Type::color};
    for (Type instance : instances) {
      std::ostringstream text;
      text << header << R"("name": ")" << op.name << "_"
           << type_name(instance) << R"(", "nodes": [)" << preamble << R"(, {"id": "node", "op": ")" << op.name
           << R"(", "in": {)";
      for (std::size_t i = 0; i < op.inputs.size(); ++i) {
        const PortSpec& port = op.inputs[i];
        const Type type = port.rule == TypeRule::generic ? instance : port.type;
        text << (i ? ", " : "") << '"' << port.name << "\": " << source_for(type, port.name, static_cast<int>(i));
      }
      text << "}" << attributes_for(op.id) << "}";
      std::string outputs;
      for (std::size_t k = 0; k < op.outputs.size(); ++k) {
        const PortSpec& port = op.outputs[k];
        const Type type = port.rule == TypeRule::generic ? (op.type_from_knots ? Type::color : instance) : port.type;
        text << to_color("node." + port.name, type, "out" + std::to_string(k));
        outputs += std::string(k ? ", " : "") + '"' + three_component_outputs[k] + "\": \"out" + std::to_string(k) + '"';
      }
      text << "], \"outputs\": {" << outputs << "}}";
      graphs.push_back(text.str());
    }
  }
  return graphs;
}

TEST(NodeDifferential, EveryNodeAgreesOverEveryType) {
  int compared = 0;
  for (const std::string& text : single_node_graphs()) {
    Result<LoadedGraph> loaded = compile_text(text);
    ASSERT_TRUE(loaded.ok()) << loaded.error().to_string() << "\n" << text;
    EXPECT_EQ(compare_backends(loaded->graph->name, loaded->ir, loaded->params, 8), "");
    ++compared;
  }
  EXPECT_GT(compared, static_cast<int>(all_ops().size()));
}

TEST(NodeDifferential, DensityInputAgreesInVolumes) {
  Result<LoadedGraph> loaded = compile_text(R"({"format": "shadetree-graph", "version": 1, "kind": "volume",
      "nodes": [{"id": "p", "op": "P"}, {"id": "d", "op": "density"},
                {"id": "s", "op": "sphere", "in": {"p": "p", "radius": 2}},
                {"id": "out", "op": "union", "in": {"a": "d", "b": "s"}}],
      "outputs": {"density": "out"}, "render": {"volume": {"bounds": {"min": [-2, -2, -2], "max": [2, 2, 2]}}}})");
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  EXPECT_EQ(compare_backends("density", loaded->ir, loaded->params, 16), "");
}

// Repeated and clamped lookups of a grey and an RGB image, at P.xy (which
// the samples take far outside [0,1]).
TEST(NodeDifferential, ImagesAgreeInBothWrapModes) {
  Result<LoadedGraph> loaded = compile_text(std::string(header) + R"("nodes": [)" + preamble + R"(,
      {"id": "a", "op": "image", "in": {"uv": "vec2_a"}, "file": "7x5x1.png", "wrap": "clamp"},
      {"id": "b", "op": "image", "in": {"uv": "vec2_a"}, "file": "3x4x3.png"}],
      "outputs": {"color": "a", "emission": "b"}})");
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  for (int width : {4, 16}) EXPECT_EQ(compare_backends("images", loaded->ir, loaded->params, width), "");
}

// A spline component's knots are permuted in one vector where they fit in
// the kernel's width, in two registers where their span has at most 32
// entries (x86_small_table_entries, AVX-512), and gathered beyond: knot
// counts either side of each size, float and color, in every basis, at
// every width, by every strategy.
TEST(NodeDifferential, SplinesAgreeEitherSideOfTheRegisterTableSizes) {
  auto knots = [](int count, int components) {
    std::string text;
    for (int k = 0; k < count; ++k) {
      std::string knot;
      for (int c = 0; c < components; ++c)
        knot += (c ? ", " : "") + std::to_string(0.03 * k * k - 0.5 * c + 0.1 * ((k * 7 + c) % 5));
      text += (k ? ", " : "") + (components == 1 ? knot : "[" + knot + "]");
    }
    return "[" + text + "]";
  };
  for (auto [count, components] :
       {std::pair{4, 1}, {5, 1}, {8, 1}, {9, 1}, {16, 1}, {17, 1}, {32, 1}, {33, 1}, {5, 3}, {8, 3}, {9, 3}, {11, 3}}) {
    std::string nodes;
    const char* bases[] = {"catmull-rom", "linear", "step"};
    for (int b = 0; b < 3; ++b)
      nodes += R"(, {"id": "s)" + std::to_string(b) + R"(", "op": "spline", "in": {"x": "float_)" + "abc"[b] +
               R"("}, "basis": ")" + bases[b] + R"(", "knots": )" + knots(count, components) + "}";
    const std::string as_color = components == 1 ? R"({"id": "c", "op": "color", "in": {"r": "s0", "g": "s1", "b": "s2"}})"
                                                 : R"({"id": "c", "op": "add", "in": {"a": "s0", "b": "s1"}})";
    Result<LoadedGraph> loaded = compile_text(std::string(header) + R"("nodes": [)" + preamble + nodes + ", " +
                                              as_color + R"(], "outputs": {"color": "c")" +
                                              (components == 1 ? "" : R"(, "emission": "s2")") + "}}");
    ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
    const std::string name = "spline of " + std::to_string(count) + "x" + std::to_string(components);
    for (int width : {4, 8, 16}) EXPECT_EQ(compare_backends(name, loaded->ir, loaded->params, width), "") << width;
    if (host_vector_width() < 16) continue;
    for (GatherStrategy gathers : {GatherStrategy::hardware, GatherStrategy::per_lane, GatherStrategy::in_register,
                                   GatherStrategy::in_register_byte_permutes,
                                   GatherStrategy::byte_permutes_and_gathers,
                                   GatherStrategy::byte_permutes_and_per_lane})
      EXPECT_EQ(compare_backends(name, loaded->ir, loaded->params, 16, gathers), "")
          << "gather strategy " << static_cast<int>(gathers);
  }
}

TEST(NodeDifferential, ScalarArgumentsSplatToTheOpsType) {
  Result<LoadedGraph> loaded = compile_text(std::string(header) + R"("nodes": [{"id": "p", "op": "P"},
      {"id": "d", "op": "dot", "in": {"a": 1, "b": "p"}}, {"id": "l", "op": "normalize", "in": {"v": "p"}},
      {"id": "m", "op": "dot", "in": {"a": "l", "b": 0.5}}, {"id": "c", "op": "color", "in": {"r": "d", "g": "m"}}],
      "outputs": {"color": "c"}})");
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  EXPECT_EQ(compare_backends("splat", loaded->ir, loaded->params, 8), "");
}

// --- graphs at the documented limits ---------------------------------------

// Octaves and iterations at their maxima, tables of max_table_entries, and
// functions nested as deep as the checker allows.
TEST(LimitsDifferential, GraphsAtTheDocumentedLimitsAgree) {
  auto list = [](int count, int components) {
    std::string text = "[";
    for (int i = 0; i < count; ++i) {
      const float value = static_cast<float>((i * 37) % 101) / 100.0f;
      text += i ? ", " : "";
      text += components == 1 ? std::to_string(value)
                              : "[" + std::to_string(value) + ", " + std::to_string(1 - value) + ", 0.5]";
    }
    return text + "]";
  };
  std::string rows = "[";
  for (int r = 0; r < 64; ++r) rows += (r ? ", " : "") + list(64, 1);
  rows += "]";
  std::string functions = R"("functions": {"f0": {"inputs": {"x": "float"}, "nodes": [{"id": "s", "op": "sin", "in": {"x": "$x"}}], "outputs": {"y": "s"}})";
  for (int depth = 1; depth < max_function_nesting; ++depth)
    functions += ", \"f" + std::to_string(depth) + R"(": {"inputs": {"x": "float"}, "nodes": [{"id": "c", "op": "f)" +
                 std::to_string(depth - 1) + R"(", "in": {"x": "$x"}}, {"id": "a", "op": "add", "in": {"a": "c", "b": 0.01}}], "outputs": {"y": "a"}})";
  functions += "},";
  const std::string text = std::string(header) + functions + R"("nodes": [)" + preamble + R"(,
      {"id": "fbm", "op": "fbm", "in": {"p": "p", "octaves": 16, "filter_width": "fw"}},
      {"id": "turb", "op": "turbulence", "in": {"p": "p", "octaves": 16}},
      {"id": "waves", "op": "sines", "in": {"p": "p", "octaves": 16}},
      {"id": "jul", "op": "julia", "in": {"p": "vec2_a", "c": [-0.8, 0.156], "iterations": 1024}},
      {"id": "sp", "op": "spline", "in": {"x": "float_b"}, "knots": )" + list(max_table_entries, 3) + R"(},
      {"id": "ct", "op": "color_table", "in": {"x": "float_c", "filter_width": "fw"}, "entries": )" +
                           list(max_table_entries, 3) + R"(},
      {"id": "t2", "op": "table2d", "in": {"x": "float_b", "y": "float_c"}, "values": )" + rows + R"(},
      {"id": "deep", "op": "f)" + std::to_string(max_function_nesting - 1) + R"(", "in": {"x": "float_a"}},
      {"id": "scalars", "op": "color", "in": {"r": "fbm", "g": "turb", "b": "waves"}}],
      "outputs": {"color": "scalars", "emission": "sp", "normal": "ct", "specular": "jul", "roughness": "t2",
                  "opacity": "deep"}})";
  Result<LoadedGraph> loaded = compile_text(text);
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  EXPECT_EQ(compare_backends("limits", loaded->ir, loaded->params, 8), "");
}

// A kernel past the size where the JIT switches to fast code generation
// (jit/jit_compiler.cpp) still computes what the interpreter does.
TEST(LimitsDifferential, HugeKernelsAgree) {
  std::string nodes = std::string(preamble) + R"(, {"id": "m0", "op": "mul", "in": {"a": "float_a", "b": 0.01}})";
  for (int i = 1; i <= 2000; ++i)
    nodes += R"(, {"id": "e)" + std::to_string(i) + R"(", "op": "exp", "in": {"x": "m)" + std::to_string(i - 1) +
             R"("}}, {"id": "m)" + std::to_string(i) + R"(", "op": "mul", "in": {"a": "e)" + std::to_string(i) +
             R"(", "b": 0.001}})";
  Result<LoadedGraph> loaded =
      compile_text(std::string(header) + R"("nodes": [)" + nodes + R"(], "outputs": {"color": "m2000"}})");
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  EXPECT_EQ(compare_backends("exp chain", loaded->ir, loaded->params, 8), "");
}

// --- kernels split in two (codegen/kernel_split.h) ------------------------

// Turbulence, fbm in a region, noise and its gradient, a spline: enough
// for a kernel past the split threshold.
const std::string split_graph = testing::graph_text(
    R"({"id": "p", "op": "P"}, {"id": "q", "op": "mul", "in": {"a": "p", "b": 3}},
       {"id": "t", "op": "turbulence", "in": {"p": "q", "octaves": 6}},
       {"id": "f", "op": "fbm", "in": {"p": "q", "octaves": 5}},
       {"id": "c", "op": "lt", "in": {"a": "t", "b": 0.3}},
       {"id": "r", "op": "if", "in": {"cond": "c", "then": "t", "else": "f"}},
       {"id": "q2", "op": "mul", "in": {"a": "q", "b": 2}}, {"id": "n", "op": "noise", "in": {"p": "q2"}},
       {"id": "g", "op": "gradient", "in": {"x": "n"}}, {"id": "s", "op": "add", "in": {"a": "r", "b": "n"}},
       {"id": "k", "op": "spline", "in": {"x": "s"}, "basis": "catmull-rom",
        "knots": [[0, 0, 0], [0, 0.1, 0.2], [0.5, 0.4, 0.3], [1, 0.9, 0.6], [1, 1, 1]]},
       {"id": "gg", "op": "dot", "in": {"a": "g", "b": "g"}}, {"id": "m", "op": "mul", "in": {"a": "k", "b": "gg"}})",
    R"("color": "m")");

// The two parts pass the values that cross the cut (here one computed in
// a region) through scratch, chunk by chunk, over a sample count that is
// no multiple of the chunk; the result is the interpreter's to the bit.
TEST(SplitKernelDifferential, KernelsSplitInTwoAgree) {
  Result<LoadedGraph> loaded = compile_text(split_graph);
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  for (int width : {4, 8, 16}) {
    Result<std::string> listing = kernel_listing(loaded->ir, width, Listing::optimized_llvm_ir);
    ASSERT_TRUE(listing.ok()) << listing.error().to_string();
    EXPECT_NE(listing->find("; module 2 of 2"), std::string::npos) << "width " << width << ": compiled whole";
    EXPECT_EQ(compare_backends("split", loaded->ir, loaded->params, width), "");
    EXPECT_EQ(compare_backends("split", loaded->ir, loaded->params, width, std::nullopt, Optimization::quick), "");
  }
}

// A small kernel compiles whole: one module.
TEST(SplitKernelDifferential, SmallKernelsCompileWhole) {
  Result<LoadedGraph> loaded = compile_text(
      testing::graph_text(R"({"id": "p", "op": "P"}, {"id": "n", "op": "noise", "in": {"p": "p"}})", R"("color": "n")"));
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  Result<std::string> listing = kernel_listing(loaded->ir, 8, Listing::optimized_llvm_ir);
  ASSERT_TRUE(listing.ok()) << listing.error().to_string();
  EXPECT_EQ(listing->find("; module"), std::string::npos);
}

// Half of a module of each of these kernels is compiled apart and called,
// with the values it leaves passed through memory: of looping_turbulence,
// the first part of its octave loop's one long block (a periodic 4D
// noise, antialiased); of the fireball at width 16, the same; of
// tileable_stones at width 16, a stretch of its first part's sample loop
// (its cellular noise) and a block of its second's; of mesh_hypertexture
// at width 16, a stretch that reads the mesh, which both modules only
// declare (the JIT binds it when it links them). Their sizes are per-lane
// lookups' (other strategies read the mesh by gathers, and it compiles
// whole). The result is the interpreter's to the bit.
TEST(SplitKernelDifferential, KernelsGeneratedInHalvesAgree) {
  const std::vector<std::pair<const char*, std::vector<int>>> halved = {
      {"looping_turbulence", {8}}, {"fireball", {16}}, {"tileable_stones", {16}}, {"mesh_hypertexture", {16}}};
  JitSettings per_lane;
  per_lane.gathers = GatherStrategy::per_lane;
  for (const auto& [name, widths] : halved) {
    Result<LoadedGraph> loaded = testing::load_gallery_graph(std::string(SHADETREE_SOURCE_DIR "/graphs/") + name + ".json");
    ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
    for (int width : widths) {
      Result<std::string> listing = kernel_listing(loaded->ir, width, Listing::optimized_llvm_ir, per_lane);
      ASSERT_TRUE(listing.ok()) << listing.error().to_string();
      const std::size_t half = listing->find("; the half of this module compiled on a thread of its own");
      EXPECT_NE(half, std::string::npos) << name << " at width " << width << ": generated whole";
      if (std::string(name) == "mesh_hypertexture")
        EXPECT_NE(listing->find("@shade_kernel_data = external constant", half), std::string::npos);
      EXPECT_EQ(compare_backends(name, loaded->ir, loaded->params, width), "");
      EXPECT_EQ(compare_backends(name, loaded->ir, loaded->params, width, GatherStrategy::per_lane), "");
      EXPECT_EQ(compare_backends(name, loaded->ir, loaded->params, width, GatherStrategy::hardware), "");
    }
  }
}

// --- random well-typed graphs ---------------------------------------------

TEST(RandomGraphDifferential, HundredsOfRandomGraphsAgree) {
  int compared = 0;
  for (std::uint32_t seed = 1; seed <= 240; ++seed) {
    const std::string text = RandomGraph(seed).generate(18);
    Result<LoadedGraph> loaded = compile_text(text);
    ASSERT_TRUE(loaded.ok()) << "seed " << seed << ": " << loaded.error().to_string() << "\n" << text;
    const std::string disagreement =
        compare_backends("random graph " + std::to_string(seed), loaded->ir, loaded->params, seed % 3 == 0 ? 4 : 16,
                         std::nullopt, seed % 4 == 1 ? Optimization::quick : Optimization::full);
    EXPECT_EQ(disagreement, "") << text;
    ++compared;
  }
  EXPECT_EQ(compared, 240);
}

}  // namespace
}  // namespace shadetree

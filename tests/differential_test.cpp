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
#include "support/gallery.h"
#include "support/test_files.h"
#include "interp/interpreter.h"
#include "ir/verify.h"
#include "jit/jit_kernel.h"
#include "graph/check.h"
#include "nodes/limits.h"
#include "nodes/registry.h"

namespace shadetree {
namespace {

// 517 samples: two interpreter blocks and a tail, and a tail for every
// vector width. Every varying global has a plane.
struct SampleSet {
  static constexpr std::size_t count = 517;
  SampleBuffers input{count, GlobalSet().set()};
  UniformInputs uniforms;

  SampleSet() {
    std::mt19937 random(1989);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    auto store_unit_vector = [&](GlobalId id, std::size_t i) {
      const float v[3] = {unit(random), unit(random), unit(random) + 2.0f};
      const float length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      for (int c = 0; c < 3; ++c) input.plane(id, c)[i] = v[c] / length;
    };
    for (std::size_t i = 0; i < count; ++i) {
      float p[3];
      switch (i % 5) {
        case 0:  // lattice points
          for (float& c : p) c = std::round(unit(random) * 4.0f);
          break;
        case 1:  // negative coordinates
          for (float& c : p) c = -std::fabs(unit(random)) * 7.0f;
          break;
        case 2:  // far from the origin
          for (float& c : p) c = 1e4f + unit(random) * 3.0f;
          break;
        default:
          for (float& c : p) c = unit(random) * 3.0f;
      }
      for (int c = 0; c < 3; ++c) input.plane(GlobalId::P, c)[i] = p[c];
      for (GlobalId id : {GlobalId::N, GlobalId::I, GlobalId::L}) store_unit_vector(id, i);
      for (int c = 0; c < 2; ++c) input.plane(GlobalId::uv, c)[i] = (unit(random) + 1.0f) / 2.0f;
      const float widths[] = {0.0f, 0.001f, 0.01f, 0.1f, 0.7f};
      input.plane(GlobalId::filter_width)[i] = widths[i % 5];
      input.plane(GlobalId::density)[i] = (unit(random) + 1.0f) / 2.0f;
      input.plane(GlobalId::surface)[i] = static_cast<float>(i % 4);
    }
    uniforms.set(GlobalId::time, 0.75f);
    uniforms.set(GlobalId::frame, 18.0f);
    uniforms.set(GlobalId::step_size, 0.01f);
    for (int c = 0; c < 3; ++c) uniforms.set(GlobalId::light_color, 1.0f - 0.1f * c, c);
  }

  float P(int component, std::size_t i) const { return input.inputs().plane(GlobalId::P, component)[i]; }
};

const SampleSet& samples() {
  static const SampleSet set;
  return set;
}

std::vector<std::vector<float>> run(const Kernel& kernel, const std::vector<float>& params) {
  const OutputLayout& layout = kernel.outputs();
  std::vector<std::vector<float>> results(static_cast<std::size_t>(layout.plane_count),
                                          std::vector<float>(SampleSet::count, -12345.0f));
  std::vector<float*> pointers;
  for (auto& plane : results) pointers.push_back(plane.data());
  kernel.bind(params.data(), samples().uniforms)->run(samples().input.inputs(), pointers.data(), SampleSet::count);
  return results;
}

// The backends run the same semantics with the same operations in the
// same order (and no contraction into fused multiply-adds), so they agree
// to the bit; NaN agrees with NaN.
bool agree(float a, float b) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  return a == b;
}

// Compares the backends on `ir`; returns "" or the first disagreement.
std::string compare_backends(const std::string& name, const ShadeIR& ir, const std::vector<float>& params,
                             int width, std::optional<GatherStrategy> gathers = std::nullopt) {
  auto reference = run(*make_interpreted_kernel(ir), params);
  Result<std::unique_ptr<Kernel>> jit = make_jit_kernel(ir, width, JitSettings{false, {}, false, gathers});
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
  if (host_vector_width() < 16) return;  // the other strategies need AVX-512 at width 16
  for (GatherStrategy gathers : {GatherStrategy::hardware, GatherStrategy::per_lane, GatherStrategy::in_register,
                                 GatherStrategy::in_register_byte_permutes})
    EXPECT_EQ(compare_backends(GetParam(), loaded->ir, loaded->params, 16, gathers), "")
        << "gather strategy " << static_cast<int>(gathers);
}

INSTANTIATE_TEST_SUITE_P(Gallery, GalleryDifferential, ::testing::ValuesIn(testing::gallery_graphs()),
                         [](const auto& info) { return testing::gallery_graph_name(info.param); });

// --- every node, over every type it accepts ------------------------------

// Varying sources of each type, built from the inputs.
const char* const preamble = R"(
  {"id": "p", "op": "P"}, {"id": "s", "op": "split", "in": {"v": "p"}},
  {"id": "float_a", "op": "add", "in": {"a": "s.x", "b": "s.y"}},
  {"id": "float_b", "op": "mul", "in": {"a": "s.z", "b": 0.37}},
  {"id": "float_c", "op": "sub", "in": {"a": "s.y", "b": 0.5}},
  {"id": "vec2_a", "op": "vec2", "in": {"x": "s.x", "y": "s.z"}},
  {"id": "vec2_b", "op": "uv"},
  {"id": "vec3_a", "op": "P"}, {"id": "vec3_b", "op": "N"},
  {"id": "color_a", "op": "to_color", "in": {"v": "p"}},
  {"id": "color_b", "op": "to_color", "in": {"v": "vec3_b"}},
  {"id": "bool_a", "op": "lt", "in": {"a": "s.x", "b": "s.y"}},
  {"id": "fw", "op": "filter_width"},
  {"id": "vec3_c", "op": "I"}, {"id": "vec3_d", "op": "L"}, {"id": "color_c", "op": "light_color"},
  {"id": "object", "op": "surface"}, {"id": "float_d", "op": "add", "in": {"a": "object", "b": "s.x"}})";

// A surface graph: its contract has three 3-component outputs (color,
// emission, normal) and three float ones, enough for any node's outputs.
const char* const header = R"({"format": "shadetree-graph", "version": 1, "kind": "surface", )";
const char* const three_component_outputs[] = {"color", "emission", "normal"};

// Nodes that turn value `id` of `type` into a color named `as`, so that it
// can be an output.
std::string to_color(const std::string& id, Type type, const std::string& as) {
  switch (type) {
    case Type::bool_:
      return R"(, {"id": ")" + as + R"(", "op": "select", "in": {"cond": ")" + id + R"(", "then": 1, "else": 0}})";
    case Type::vec2:
      return R"(, {"id": ")" + as + R"(_s", "op": "split", "in": {"v": ")" + id + R"("}}, {"id": ")" + as +
             R"(", "op": "color", "in": {"r": ")" + as + R"(_s.x", "g": ")" + as + R"(_s.y"}})";
    default:
      return R"(, {"id": ")" + as + R"(", "op": "mul", "in": {"a": ")" + id + R"(", "b": 1}})";
  }
}

std::string attributes_for(OpId op) {
  switch (op) {
    case OpId::spline: return R"(, "basis": "catmull-rom", "knots": [[1,0,0],[0.9,0.5,0.1],[0.2,0.8,0.3],[0,0,1],[0.5,0.5,0.5]])";
    case OpId::color_table: return R"(, "entries": [[1,0,0],[0,1,0],[0,0,1],[1,1,0]])";
    case OpId::table1d: return R"(, "values": [0, 0.8, 0.2, 1, 0.4], "domain": [-2, 3])";
    case OpId::table2d: return R"(, "values": [[0, 1, 0.5], [0.2, 0.9, 0.1]])";
    case OpId::image: return R"(, "file": "5x3x3.png")";
    case OpId::mesh_distance: case OpId::mesh_closest: return R"(, "file": "ball.obj", "resolution": 16)";
    case OpId::noise: case OpId::turbulence: return R"(, "seed": 7)";
    default: return "";
  }
}

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
      "outputs": {"density": "out"}})");
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

// --- random well-typed graphs ---------------------------------------------

// Grows a graph one node at a time from a pool of typed values, picking ops
// from every family (conditionals included) and wiring each input from a
// value of an acceptable type.
class RandomGraph {
 public:
  explicit RandomGraph(std::uint32_t seed) : random_(seed) {}

  std::string generate(int node_count) {
    pool_ = {{"float_a", Type::float_}, {"float_b", Type::float_}, {"float_c", Type::float_},
             {"vec2_a", Type::vec2},    {"vec2_b", Type::vec2},    {"vec3_a", Type::vec3},
             {"vec3_b", Type::vec3},    {"color_a", Type::color},  {"color_b", Type::color},
             {"bool_a", Type::bool_},   {"fw", Type::float_},      {"vec3_c", Type::vec3},
             {"vec3_d", Type::vec3},    {"color_c", Type::color},  {"float_d", Type::float_}};
    std::ostringstream nodes;
    nodes << preamble;
    const auto ops = all_ops();
    for (int n = 0; n < node_count; ++n) {
      const OpDef& op = ops[pick(ops.size())];
      if (op.family == OpFamily::input || op.id == OpId::split || !op.kinds.contains(GraphKind::surface)) continue;
      Type instance = Type::float_;
      if (op.generic == GenericSet::numeric && !op.type_from_knots) instance = pick_of({Type::float_, Type::vec2, Type::vec3, Type::color});
      if (op.generic == GenericSet::vectors) instance = pick_of({Type::vec2, Type::vec3, Type::color});
      const std::string id = "n" + std::to_string(n);
      nodes << R"(, {"id": ")" << id << R"(", "op": ")" << op.name << R"(", "in": {)";
      std::vector<std::string> wires;
      for (std::size_t i = 0; i < op.inputs.size(); ++i) {
        const PortSpec& port = op.inputs[i];
        const Type type = port.rule == TypeRule::generic ? instance : port.type;
        // Generic inputs take exactly T, so that T is what the checker infers.
        wires.push_back(wire(type, port.name, port.rule == TypeRule::generic));
        nodes << (i ? ", " : "") << '"' << port.name << "\": " << wires.back();
      }
      nodes << "}" << attributes_for(op.id) << "}";
      Type output = op.outputs[0].rule == TypeRule::generic ? instance : op.outputs[0].type;
      if (op.id == OpId::spline || op.id == OpId::color_table) output = Type::color;
      pool_.push_back({id, output});
      // Every other `if` is nested in one more on the same condition, the
      // shape that once broke the interpreter's lane lists.
      if (op.id == OpId::if_ && pick(2) == 0) {
        nodes << R"(, {"id": ")" << id << R"(_outer", "op": "if", "in": {"cond": )" << wires[0] << R"(, "then": ")"
              << id << R"(", "else": )" << wire(instance, "else", true) << "}}";
        pool_.push_back({id + "_outer", output});
      }
    }
    std::ostringstream outputs;
    for (int k = 0; k < 3; ++k) {
      const auto& [id, type] = pool_[pool_.size() - 1 - static_cast<std::size_t>(k) * 3];
      nodes << to_color(id, type, "out" + std::to_string(k));
      outputs << (k ? ", " : "") << '"' << three_component_outputs[k] << "\": \"out" << k << '"';
    }
    for (const char* name : {"specular", "roughness", "opacity"})
      outputs << ", \"" << name << "\": " << wire(Type::float_, name, true);
    return header + std::string(R"("nodes": [)") + nodes.str() + "], \"outputs\": {" + outputs.str() + "}}";
  }

 private:
  std::size_t pick(std::size_t count) { return std::uniform_int_distribution<std::size_t>(0, count - 1)(random_); }
  Type pick_of(std::initializer_list<Type> types) { return *(types.begin() + pick(types.size())); }

  // A recent value that converts to `type` (floats splat into vectors), or
  // a literal where the type needs one.
  std::string wire(Type type, const std::string& port, bool exact) {
    if (type == Type::int_) return port == "iterations" ? "24" : std::to_string(1 + pick(6));
    if (port == "filter_width") return "\"fw\"";
    std::vector<std::string> candidates;
    for (const auto& [id, value_type] : pool_)
      if (value_type == type || (!exact && value_type == Type::float_ && is_vector(type))) candidates.push_back(id);
    if (candidates.empty()) return type == Type::bool_ ? "true" : "0.5";
    // Prefer recent values so that graphs grow deep, not wide.
    const std::size_t recent = std::min<std::size_t>(candidates.size(), 6);
    return '"' + candidates[candidates.size() - 1 - pick(recent)] + '"';
  }

  std::mt19937 random_;
  std::vector<std::pair<std::string, Type>> pool_;
};

TEST(RandomGraphDifferential, HundredsOfRandomGraphsAgree) {
  int compared = 0;
  for (std::uint32_t seed = 1; seed <= 240; ++seed) {
    const std::string text = RandomGraph(seed).generate(18);
    Result<LoadedGraph> loaded = compile_text(text);
    ASSERT_TRUE(loaded.ok()) << "seed " << seed << ": " << loaded.error().to_string() << "\n" << text;
    const std::string disagreement =
        compare_backends("random graph " + std::to_string(seed), loaded->ir, loaded->params, seed % 3 == 0 ? 4 : 16);
    EXPECT_EQ(disagreement, "") << text;
    ++compared;
  }
  EXPECT_EQ(compared, 240);
}

}  // namespace
}  // namespace shadetree

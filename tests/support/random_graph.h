// Generated surface graphs for differential tests: varying sources of
// every type, conversions to colour outputs, the attributes each op needs,
// and random well-typed graphs of every op family.
#pragma once

#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "nodes/registry.h"

namespace shadetree::testing {

// Varying sources of each type, built from the inputs.
inline const char* const preamble = R"(
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
inline const char* const header = R"({"format": "shadetree-graph", "version": 1, "kind": "surface", )";
inline const char* const three_component_outputs[] = {"color", "emission", "normal"};

// Nodes that turn value `id` of `type` into a color named `as`, so that it
// can be an output.
inline std::string to_color(const std::string& id, Type type, const std::string& as) {
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

inline std::string attributes_for(OpId op) {
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

}  // namespace shadetree::testing

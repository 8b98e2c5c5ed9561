// A graph around one op, for the tests that run every op's forms (interval,
// dual) against its lane form.
#pragma once

#include <string>

#include "nodes/registry.h"
#include "pipeline/compile_graph.h"
#include "graph_text.h"
#include "random_graph.h"
#include "test_files.h"

namespace shadetree::testing {

// A graph whose only interesting node is `op` over inputs of type
// `instance`, compiled as the checker and lowering lay it out.
inline Result<LoadedGraph> one_op_graph(const OpDef& op, Type instance) {
  std::string nodes = R"({"id": "p", "op": "P"}, {"id": "s", "op": "split", "in": {"v": "p"}},
    {"id": "float_a", "op": "add", "in": {"a": "s.x", "b": "s.y"}},
    {"id": "vec2_a", "op": "vec2", "in": {"x": "s.x", "y": "s.z"}}, {"id": "vec3_a", "op": "P"},
    {"id": "color_a", "op": "to_color", "in": {"v": "p"}}, {"id": "bool_a", "op": "lt", "in": {"a": "s.x", "b": "s.y"}},
    {"id": "n", "op": ")" + op.name + R"(", "in": {)";
  for (std::size_t i = 0; i < op.inputs.size(); ++i) {
    const PortSpec& port = op.inputs[i];
    const Type type = port.rule == TypeRule::generic ? instance : port.type;
    nodes += (i ? ", \"" : "\"") + port.name + "\": ";
    nodes += type == Type::int_ ? std::string("3") : "\"" + std::string(type_name(type)) + "_a\"";
  }
  nodes += "}" + attributes_for(op.id) + "}";
  const Type output = op.outputs[0].rule == TypeRule::generic ? instance : op.outputs[0].type;
  nodes += to_color("n", output, "out");
  const std::string kind = op.kinds.contains(GraphKind::surface) ? "surface" : "volume";
  return compile_graph_text(graph_text(nodes, R"("color": "out")", "", kind), "op.json", {}, {},
                            test_files());
}

// The types each op is tried over: its generic instances, or float.
inline std::vector<Type> op_instances(const OpDef& op) {
  if (op.generic == GenericSet::numeric && !op.type_from_knots) return {Type::float_, Type::vec2, Type::vec3, Type::color};
  if (op.generic == GenericSet::vectors) return {Type::vec2, Type::vec3, Type::color};
  return {Type::float_};
}

}  // namespace shadetree::testing

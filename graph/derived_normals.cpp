#include "graph/derived_normals.h"

#include <string>
#include <utility>
#include <vector>

namespace shadetree {
namespace {

InputValue node_value(const std::string& node, const std::string& output = {}) {
  InputValue value;
  value.kind = InputValue::Kind::node;
  value.node = node;
  value.output = output;
  value.text = output.empty() ? node : node + "." + output;
  return value;
}

InputValue number_value(float number) {
  InputValue value;
  value.numbers = {number};
  value.text = std::to_string(number);
  return value;
}

void add_node(Graph& graph, const std::string& id, const std::string& op,
              std::vector<std::pair<std::string, InputValue>> inputs) {
  graph.nodes.push_back(Node{id, op, std::move(inputs), {}});
}

}  // namespace

Graph with_normal_from_height(Graph graph, float strength) {
  const OutputDecl* height = find_output(graph, "height");
  if (!height || find_output(graph, "normal")) return graph;
  add_node(graph, "bake.gradient", "gradient", {{"x", height->source}});
  add_node(graph, "bake.slopes", "split", {{"v", node_value("bake.gradient")}});
  add_node(graph, "bake.across", "mul", {{"a", node_value("bake.slopes", "x")}, {"b", number_value(-strength)}});
  add_node(graph, "bake.up", "mul", {{"a", node_value("bake.slopes", "y")}, {"b", number_value(-strength)}});
  add_node(graph, "bake.tilted", "vec3",
           {{"x", node_value("bake.across")}, {"y", node_value("bake.up")}, {"z", number_value(1.0f)}});
  add_node(graph, "bake.normal", "normalize", {{"v", node_value("bake.tilted")}});
  graph.outputs.push_back(OutputDecl{"normal", node_value("bake.normal")});
  return graph;
}

Graph with_normal_from_density(Graph graph) {
  const OutputDecl* density = find_output(graph, "density");
  if (!density || find_output(graph, "normal")) return graph;
  // Only the density and its normal: the rest of the graph's work (colour,
  // opacity) is done once per sample by its own kernel.
  graph.outputs = {*density};
  density = &graph.outputs.front();
  add_node(graph, "march.gradient", "gradient", {{"x", density->source}});
  add_node(graph, "march.inward", "normalize", {{"v", node_value("march.gradient")}});
  add_node(graph, "march.normal", "neg", {{"x", node_value("march.inward")}});
  graph.outputs.push_back(OutputDecl{"normal", node_value("march.normal")});
  return graph;
}

}  // namespace shadetree

#include "server/node_probe.h"

#include <algorithm>
#include <memory>
#include <set>
#include <vector>

#include <nlohmann/json.hpp>

#include "graph/parse.h"

namespace shadetree {
namespace {

using nlohmann::json;

// The output names of a checked node, for its op or its function.
std::vector<std::string> output_names(const CheckedGraph& checked, const CheckedNode& node) {
  std::vector<std::string> names;
  if (node.op) {
    for (const PortSpec& port : node.op->outputs) names.push_back(port.name);
  } else {
    for (const OutputDecl& output : checked.functions[node.function].definition->outputs) names.push_back(output.name);
  }
  return names;
}

// A node id that no node of the graph has.
std::string fresh_id(const Graph& graph, const std::string& base) {
  for (int n = 0;; ++n) {
    const std::string id = n == 0 ? base : base + std::to_string(n);
    bool taken = false;
    for (const Node& node : graph.nodes) taken |= node.id == id || node.id == id + "_xy";
    if (!taken) return id;
  }
}

}  // namespace

Result<std::string> node_probe_graph(const std::string& text, const std::string& file, const std::string& node,
                                     const GraphFiles& files) {
  Result<Graph> parsed = parse_graph(text, file);
  if (!parsed) return parsed.error();
  auto graph = std::make_shared<const Graph>(std::move(*parsed));
  Result<CheckedGraph> checked = check_graph(graph, files);
  if (!checked) return checked.error();

  const std::size_t dot = node.find('.');
  const std::string id = node.substr(0, dot);
  const std::string output = dot == std::string::npos ? std::string() : node.substr(dot + 1);
  const CheckedNode* probed = nullptr;
  for (const CheckedNode& candidate : checked->main.nodes)
    if (candidate.node->id == id) probed = &candidate;
  if (!probed) return invalid_input("no node \"" + id + "\" in the main graph of " + file);
  const std::vector<std::string> names = output_names(*checked, *probed);
  std::size_t index = 0;
  if (!output.empty()) {
    while (index < names.size() && names[index] != output) ++index;
    if (index == names.size()) return invalid_input("node \"" + id + "\" has no output \"" + output + "\"");
  }
  if (probed->output_types.empty()) return invalid_input("node \"" + id + "\" has no output to show");
  const Type type = probed->output_types[index];
  const std::string source = output.empty() ? id : id + "." + output;

  // Only the node and what it reads: a volume's other nodes may read
  // globals a texture has not (step_size, density).
  std::set<std::string> upstream;
  std::vector<const CheckedNode*> pending = {probed};
  while (!pending.empty()) {
    const CheckedNode* next = pending.back();
    pending.pop_back();
    if (!upstream.insert(next->node->id).second) continue;
    for (const CheckedSource& source : next->inputs)
      if (source.kind == CheckedSource::Kind::node) pending.push_back(&checked->main.nodes[source.index]);
  }
  json document = json::parse(text);
  json& nodes = document["nodes"];
  nodes.erase(std::remove_if(nodes.begin(), nodes.end(),
                             [&](const json& node) { return !upstream.contains(node.value("id", std::string())); }),
              nodes.end());
  const std::string probe = fresh_id(*graph, "probe_output");
  json colour = source;
  switch (type) {
    case Type::float_:
    case Type::int_:
    case Type::color: break;
    case Type::vec3:
      document["nodes"].push_back({{"id", probe}, {"op", "to_color"}, {"in", {{"v", source}}}});
      colour = probe;
      break;
    case Type::vec2:
      document["nodes"].push_back({{"id", probe + "_xy"}, {"op", "split"}, {"in", {{"v", source}}}});
      document["nodes"].push_back(
          {{"id", probe}, {"op", "color"}, {"in", {{"r", probe + "_xy.x"}, {"g", probe + "_xy.y"}, {"b", 0}}}});
      colour = probe;
      break;
    case Type::bool_:
      document["nodes"].push_back({{"id", probe}, {"op", "select"}, {"in", {{"cond", source}, {"then", 1}, {"else", 0}}}});
      colour = probe;
      break;
  }
  document["outputs"] = {{"color", colour}};
  if (graph->kind == GraphKind::volume && graph->render.volume) {
    const VolumeDesc& volume = *graph->render.volume;
    json& render = document["render"];
    render.erase("scene");
    render.erase("volume");
    render["domain"] = {{"min", {volume.bounds_min[0], volume.bounds_min[1]}},
                        {"max", {volume.bounds_max[0], volume.bounds_max[1]}}};
    render["z"] = 0.5f * (volume.bounds_min[2] + volume.bounds_max[2]);
    document["kind"] = "texture";
  }
  return document.dump();
}

}  // namespace shadetree

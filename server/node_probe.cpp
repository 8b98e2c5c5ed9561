#include "server/node_probe.h"

#include <algorithm>
#include <memory>
#include <set>
#include <vector>

#include "graph/json_document.h"  // objects in file order, as a function's outputs must be
#include "graph/parse.h"
#include "render/graph_kinds.h"

namespace shadetree {
namespace {

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

// A name that neither `taken` (an object's keys or a list of nodes' ids) has.
std::string fresh_name(const json& taken, const std::string& base) {
  auto has = [&](const std::string& name) {
    if (taken.is_object()) return taken.contains(name);
    for (const json& node : taken)
      if (node.value("id", std::string()) == name) return true;
    return false;
  };
  std::string name = base;
  for (int n = 1; has(name); ++n) name = base + std::to_string(n);
  return name;
}

// The graph with a copy of `function` whose one output is its node
// `node`, called where the main graph first calls `function`, and that
// call's id.
Result<std::pair<json, std::string>> call_of_function_node(const std::string& text, const std::string& file,
                                                            const std::string& function, const std::string& node) {
  Result<json> parsed = parse_json_document(text, file);
  if (!parsed) return parsed.error();
  json& document = *parsed;
  if (!document.is_object() || !document.contains("functions") || !document["functions"].is_object() ||
      !document["functions"].contains(function))
    return Diagnostic{ExitStatus::invalid_input, file, {}, {}, "no function \"" + function + "\""};
  json probe = document["functions"][function];
  const std::string id = node.substr(0, node.find('.'));
  bool found = false;
  for (const json& body_node : probe.value("nodes", json::array())) found |= body_node.value("id", std::string()) == id;
  if (!found) return Diagnostic{ExitStatus::invalid_input, file, {}, {}, "no node \"" + id + "\" in function \"" + function + "\""};
  const json* call = nullptr;
  if (document.contains("nodes") && document["nodes"].is_array())
    for (const json& main_node : document["nodes"])
      if (!call && main_node.value("op", std::string()) == function) call = &main_node;
  if (!call)
    return Diagnostic{ExitStatus::invalid_input, file, {}, {},
                      "the main graph does not call function \"" + function + "\": its nodes have no value to show"};
  const std::string probe_function = fresh_name(document["functions"], function + "_probe");
  probe["outputs"] = {{"value", node}};
  const std::string probe_call = fresh_name(document["nodes"], "probe_call");
  json call_node = {{"id", probe_call}, {"op", probe_function}};
  if (call->contains("in")) call_node["in"] = (*call)["in"];
  document["functions"][probe_function] = std::move(probe);
  document["nodes"].push_back(std::move(call_node));
  return std::pair{std::move(document), probe_call};
}

}  // namespace

Result<std::string> node_probe_graph(const std::string& text, const std::string& file, const std::string& node,
                                     const GraphFiles& files, const std::string& function) {
  if (!function.empty()) {
    // Parsed first: the file's structure is then known to be sound.
    if (Result<Graph> parsed = parse_graph(text, file); !parsed) return parsed.error();
    Result<std::pair<json, std::string>> called = call_of_function_node(text, file, function, node);
    if (!called) return called.error();
    return node_probe_graph(called->first.dump(), file, called->second, files);
  }
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
  if (!probed) return Diagnostic{ExitStatus::invalid_input, file, {}, {}, "no node \"" + id + "\" in the main graph"};
  const std::vector<std::string> names = output_names(*checked, *probed);
  std::size_t index = 0;
  if (!output.empty()) {
    while (index < names.size() && names[index] != output) ++index;
    if (index == names.size())
      return Diagnostic{ExitStatus::invalid_input, file, id, {}, "no output \"" + output + "\""};
  }
  if (probed->output_types.empty()) return Diagnostic{ExitStatus::invalid_input, file, id, {}, "no output to show"};
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
  Result<json> read = parse_json_document(text, file);
  if (!read) return read.error();
  json& document = *read;
  json& nodes = document["nodes"];
  nodes.erase(std::remove_if(nodes.begin(), nodes.end(),
                             [&](const json& node) { return !upstream.contains(node.value("id", std::string())); }),
              nodes.end());
  const std::string probe = fresh_name(document["nodes"], "probe_output");
  json colour = source;
  switch (type) {
    case Type::float_:
    case Type::int_:
    case Type::color: break;
    case Type::vec3:
      document["nodes"].push_back({{"id", probe}, {"op", "to_color"}, {"in", {{"v", source}}}});
      colour = probe;
      break;
    case Type::vec2: {
      const std::string parts = fresh_name(document["nodes"], "probe_parts");
      document["nodes"].push_back({{"id", parts}, {"op", "split"}, {"in", {{"v", source}}}});
      document["nodes"].push_back(
          {{"id", probe}, {"op", "color"}, {"in", {{"r", parts + ".x"}, {"g", parts + ".y"}, {"b", 0}}}});
      colour = probe;
      break;
    }
    case Type::bool_:
      document["nodes"].push_back({{"id", probe}, {"op", "select"}, {"in", {{"cond", source}, {"then", 1}, {"else", 0}}}});
      colour = probe;
      break;
  }
  document["outputs"] = {{"color", colour}};
  if (const auto thumbnail = graph_kind_driver(graph->kind).thumbnail_document) thumbnail(*graph, document);
  return document.dump();
}

}  // namespace shadetree

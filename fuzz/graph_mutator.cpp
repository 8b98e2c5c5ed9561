// libFuzzer's custom mutator for graph files. Byte mutations of JSON mostly
// make invalid JSON, which stops at the parser; most of the time this
// mutator parses the input and changes it the way a user editing a graph
// would (another op, a rewired input, a boundary number, a node duplicated
// or dropped, another kind), so that well-formed graphs reach the checker,
// the passes and both backends. Otherwise, and when the input is not a
// graph, libFuzzer's own byte mutations run.
#include <cstdint>
#include <cstring>
#include <random>
#include <string>

#include <nlohmann/json.hpp>

#include "nodes/registry.h"

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size);

namespace shadetree {
namespace {

using json = nlohmann::ordered_json;

// Numbers at the edges of what ops and limits accept.
constexpr double boundary_numbers[] = {0, -0.0, 1, -1, 0.5, 2, 16, 17, 1024, 1025, 4096, 1e-30, -1e30, 3.4e38, 1e6, 64};

template <class Random>
std::size_t pick(Random& random, std::size_t count) {
  return std::uniform_int_distribution<std::size_t>(0, count - 1)(random);
}

// The node's "in" object, made if absent; null if the node has some other
// "in" (a string, a number: the checker's to refuse, not ours to edit).
json* inputs_of(json& node) {
  if (!node.contains("in")) node["in"] = json::object();
  return node["in"].is_object() ? &node["in"] : nullptr;
}

template <class Random>
bool mutate_graph(json& graph, Random& random) {
  if (!graph.is_object() || !graph.contains("nodes") || !graph["nodes"].is_array() || graph["nodes"].empty())
    return false;
  json& nodes = graph["nodes"];
  json& node = nodes[pick(random, nodes.size())];
  if (!node.is_object()) return false;
  const auto ops = all_ops();
  switch (pick(random, 7)) {
    case 0:  // another op, keeping the inputs
      node["op"] = ops[pick(random, ops.size())].name;
      return true;
    case 1: {  // an input wired to another node (perhaps a later one: a cycle)
      const OpDef* op = node.contains("op") && node["op"].is_string() ? find_op(node["op"].get<std::string>()) : nullptr;
      if (!op || op->inputs.empty()) return false;
      const json source = nodes[pick(random, nodes.size())];
      json* inputs = inputs_of(node);
      if (!inputs || !source.is_object() || !source.contains("id")) return false;
      (*inputs)[op->inputs[pick(random, op->inputs.size())].name] = source["id"];
      return true;
    }
    case 2: {  // a boundary number in an input
      const OpDef* op = node.contains("op") && node["op"].is_string() ? find_op(node["op"].get<std::string>()) : nullptr;
      json* inputs = inputs_of(node);
      if (!op || op->inputs.empty() || !inputs) return false;
      (*inputs)[op->inputs[pick(random, op->inputs.size())].name] =
          boundary_numbers[pick(random, std::size(boundary_numbers))];
      return true;
    }
    case 3: {  // a node duplicated under a new id
      json copy = node;
      copy["id"] = "m" + std::to_string(random() % 100000);
      nodes.push_back(copy);
      return true;
    }
    case 4:  // a node dropped: its users now name an unknown id
      nodes.erase(nodes.begin() + static_cast<std::ptrdiff_t>(pick(random, nodes.size())));
      return true;
    case 5: {  // another graph kind, with the bounds a volume needs
      const GraphKind kind = all_graph_kinds[pick(random, all_graph_kinds.size())];
      graph["kind"] = graph_kind_name(kind);
      if (kind == GraphKind::volume) {
        if (!graph["render"].is_object()) graph["render"] = json::object();
        graph["render"]["volume"] = {{"bounds", {{"min", {-1, -1, -1}}, {"max", {1, 1, 1}}}}};
      }
      return true;
    }
    default: {  // an attribute at a boundary (octaves, seeds, table sizes)
      const OpDef* op = node.contains("op") && node["op"].is_string() ? find_op(node["op"].get<std::string>()) : nullptr;
      if (!op || op->attributes.empty()) return false;
      node[op->attributes[pick(random, op->attributes.size())].name] =
          boundary_numbers[pick(random, std::size(boundary_numbers))];
      return true;
    }
  }
}

}  // namespace
}  // namespace shadetree

extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t max_size,
                                               unsigned int seed) {
  std::minstd_rand random(seed);
  if (random() % 4 != 0) {
    auto graph = shadetree::json::parse(data, data + size, nullptr, false);
    if (!graph.is_discarded() && shadetree::mutate_graph(graph, random)) {
      const std::string text = graph.dump();
      if (text.size() <= max_size) {
        std::memcpy(data, text.data(), text.size());
        return text.size();
      }
    }
  }
  return LLVMFuzzerMutate(data, size, max_size);
}

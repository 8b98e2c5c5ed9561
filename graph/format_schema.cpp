#include "graph/format_schema.h"

#include "graph/format_fields.h"
#include "nodes/registry.h"

namespace shadetree {

json graph_format_schema() {
  json op_names = json::array();
  for (const OpDef& op : all_ops()) op_names.push_back(op.name);
  const json vector = {{"type", "array"}, {"items", {{"type", "number"}}}, {"minItems", 2}, {"maxItems", 3}};
  const json value = {{"description", "a node id (\"id\" or \"id.output\"), \"$param\", or a literal"},
                      {"oneOf", json::array({{{"type", "string"}, {"minLength", 1}},
                                             {{"type", "number"}},
                                             {{"type", "boolean"}},
                                             vector})}};
  const json node = {
      {"type", "object"},
      {"required", {"id", "op"}},
      {"properties",
       {{"id", {{"type", "string"}, {"pattern", "^[^$.][^.]*$"}}},
        {"op", {{"description", "a library op or a function of this graph"},
                {"anyOf", json::array({{{"enum", op_names}}, {{"type", "string"}}})}}},
        {"in", {{"type", "object"}, {"additionalProperties", {{"$ref", "#/$defs/value"}}}}},
        {"doc", {{"type", "string"}}}}},
      {"additionalProperties", {{"description", "op attributes (knots, basis, seed, entries, values, domain)"}}}};
  const json outputs = {{"type", "object"}, {"minProperties", 1}, {"additionalProperties", {{"$ref", "#/$defs/value"}}}};
  const json nodes = {{"type", "array"}, {"items", {{"$ref", "#/$defs/node"}}}};

  // One schema per kind, chosen by the file's "kind".
  json kinds = json::array();
  for (GraphKind kind : all_graph_kinds) {
    json variant = object_schema(graph_fields(kind), kind);
    variant["properties"]["kind"] = {{"const", graph_kind_name(kind)}};
    kinds.push_back(variant);
  }
  return {{"$schema", "https://json-schema.org/draft/2020-12/schema"},
          {"title", "shadetree graph"},
          {"oneOf", kinds},
          {"$defs", {{"value", value}, {"node", node}, {"nodes", nodes}, {"outputs", outputs}}}};
}

}  // namespace shadetree

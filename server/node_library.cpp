#include "server/node_library.h"

#include "graph/format_fields.h"
#include "nodes/output_contract.h"
#include "nodes/registry.h"

namespace shadetree {
namespace {

const char* attribute_kind_name(AttributeKind kind) {
  switch (kind) {
    case AttributeKind::integer: return "integer";
    case AttributeKind::choice: return "choice";
    case AttributeKind::value_list: return "value_list";
    case AttributeKind::number_grid: return "number_grid";
    case AttributeKind::number_pair: return "number_pair";
    case AttributeKind::image_file: return "image_file";
    case AttributeKind::mesh_file: return "mesh_file";
  }
  return "";
}

nlohmann::json port_json(const PortSpec& port) {
  nlohmann::json json = {{"name", port.name},
                         {"type", port.rule == TypeRule::generic ? "T" : std::string(type_name(port.type))}};
  if (port.default_value) json["default"] = *port.default_value;
  if (!port.doc.empty()) json["doc"] = port.doc;
  return json;
}

}  // namespace

nlohmann::json node_library_json() {
  nlohmann::json ops = nlohmann::json::array();
  for (const OpDef& op : all_ops()) {
    nlohmann::json json = {{"name", op.name}, {"family", std::string(family_name(op.family))}, {"doc", op.doc}};
    json["generic"] = op.generic == GenericSet::numeric   ? "numeric"
                      : op.generic == GenericSet::vectors ? "vectors"
                                                          : "none";
    for (const PortSpec& port : op.inputs) json["inputs"].push_back(port_json(port));
    for (const PortSpec& port : op.outputs) json["outputs"].push_back(port_json(port));
    if (!json.contains("inputs")) json["inputs"] = nlohmann::json::array();
    for (const AttributeSpec& attribute : op.attributes)
      json["attributes"].push_back({{"name", attribute.name},
                                    {"kind", attribute_kind_name(attribute.kind)},
                                    {"required", attribute.required},
                                    {"choices", attribute.choices},
                                    {"doc", attribute.doc}});
    if (!json.contains("attributes")) json["attributes"] = nlohmann::json::array();
    for (GraphKind kind : all_graph_kinds)
      if (op.kinds.contains(kind)) json["kinds"].push_back(std::string(graph_kind_name(kind)));
    ops.push_back(std::move(json));
  }
  // What a graph of each kind may output and which fields of a render
  // section it takes: the editor's New command, kind field and outputs
  // node offer these.
  nlohmann::json kinds = nlohmann::json::array();
  for (const GraphKindDef& def : graph_kind_defs) {
    nlohmann::json outputs = nlohmann::json::array();
    for (const OutputSpec& output : output_contract(def.kind))
      outputs.push_back({{"name", output.name},
                         {"type", std::string(type_name(output.type))},
                         {"required", output.required},
                         {"doc", output.doc}});
    nlohmann::json render = nlohmann::json::array();
    for (const FormatField& field : render_fields(def.kind))
      if (field.kinds.contains(def.kind)) render.push_back(field.name);
    kinds.push_back({{"name", def.name}, {"doc", def.doc}, {"outputs", outputs}, {"render", render}});
  }
  return {{"ops", ops}, {"kinds", kinds}};
}

}  // namespace shadetree

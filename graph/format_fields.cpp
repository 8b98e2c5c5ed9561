#include "graph/format_fields.h"

#include <array>
#include <map>

#include "graph/graph.h"
#include "graph/parse.h"
#include "graph/scene.h"
#include "nodes/type.h"

namespace shadetree {
namespace {

json numbers_of(int count) {
  return {{"type", "array"}, {"items", {{"type", "number"}}}, {"minItems", count}, {"maxItems", count}};
}
json positive_number() { return {{"type", "number"}, {"exclusiveMinimum", 0}}; }
json colour() { return {{"oneOf", {{{"type", "number"}, {"minimum", 0}}, numbers_of(3)}}}; }
json number_or_triple() { return {{"oneOf", {{{"type", "number"}}, numbers_of(3)}}}; }
json text() { return {{"type", "string"}}; }

json type_names() {
  json names = json::array();
  for (Type type : all_types) names.push_back(type_name(type));
  return names;
}

// A param's default or a function input's: a number, a boolean or a vector.
json typed_value() {
  return {{"oneOf", json::array({{{"type", "number"}}, {{"type", "boolean"}}, {{"type", "array"},
                                                                               {"items", {{"type", "number"}}},
                                                                               {"minItems", 2},
                                                                               {"maxItems", 3}}})}};
}

// Objects of one of several types, each with its own fields: one schema
// per type, told apart by "type".
json typed_objects(const std::vector<std::string>& types, const FormatFields& (*fields_of)(const std::string&),
                   GraphKind kind, std::size_t most) {
  json choices = json::array();
  for (const std::string& type : types) {
    json choice = object_schema(fields_of(type), kind);
    choice["properties"]["type"] = {{"const", type}};
    choices.push_back(choice);
  }
  return {{"type", "array"}, {"items", {{"oneOf", choices}}}, {"maxItems", most}};
}

// The editor's node places (docs/graph-format.md, "Layout"): kept in the
// file for people, ignored by the compiler, so only its shape is checked
// by the schema and nothing of it by the parser.
json layout_schema() {
  const json places = {{"type", "object"}, {"additionalProperties", numbers_of(2)}};
  return {{"type", "object"},
          {"properties", {{"nodes", places}, {"functions", {{"type", "object"}, {"additionalProperties", places}}}}},
          {"additionalProperties", false}};
}

KindSet kinds_needing_a_render_section() {
  KindSet kinds;
  for (const GraphKindDef& def : graph_kind_defs)
    if (def.needed_sections) kinds = kinds | kinds_of(def.kind);
  return kinds;
}

FormatFields build_graph_fields(GraphKind kind) {
  json kinds = json::array();
  for (GraphKind each : all_graph_kinds) kinds.push_back(graph_kind_name(each));
  return {
      {"format", {{"const", "shadetree-graph"}}, every_kind, every_kind},
      {"version", {{"const", graph_format_version}}, every_kind, every_kind},
      {"name", text()},
      {"kind", {{"enum", kinds}}, every_kind, every_kind},
      {"doc", text()},
      {"params", {{"type", "object"}, {"additionalProperties", object_schema(param_fields(), kind)}}},
      {"functions", {{"type", "object"}, {"additionalProperties", object_schema(function_fields(), kind)}}},
      {"nodes", {{"$ref", "#/$defs/nodes"}}, every_kind, every_kind},
      {"outputs", {{"$ref", "#/$defs/outputs"}}, every_kind, every_kind},
      {"render", object_schema(render_fields(kind), kind), every_kind, kinds_needing_a_render_section()},
      {"layout", layout_schema()},
  };
}

FormatFields build_param_fields() {
  return {{"type", {{"enum", type_names()}}, every_kind, every_kind},
          {"default", typed_value(), every_kind, every_kind},
          {"min", {{"type", "number"}}},
          {"max", {{"type", "number"}}},
          {"doc", text()}};
}

FormatFields build_function_fields() {
  json inputs = {{"type", "object"},
                 {"additionalProperties",
                  {{"oneOf", json::array({{{"enum", type_names()}},
                                          object_schema(function_input_fields(), GraphKind::texture)})}}}};
  return {{"doc", text()},
          {"inputs", inputs},
          {"nodes", {{"$ref", "#/$defs/nodes"}}, every_kind, every_kind},
          {"outputs", {{"$ref", "#/$defs/outputs"}}, every_kind, every_kind}};
}

FormatFields build_function_input_fields() {
  return {{"type", {{"enum", type_names()}}, every_kind, every_kind}, {"default", typed_value()}};
}

FormatFields build_render_fields(GraphKind kind) {
  // Each part is for the kinds that take it (nodes/graph_kind.h).
  auto part = [](std::string name, json schema, RenderSection section) {
    return FormatField{std::move(name), std::move(schema), kinds_taking(section), kinds_taking(section, true)};
  };
  return {
      part("size",
           {{"type", "array"},
            {"items", {{"type", "integer"}, {"minimum", 1}, {"maximum", max_image_side}}},
            {"minItems", 2},
            {"maxItems", 2}},
           section_size),
      part("domain", object_schema(domain_fields(), kind), section_domain),
      part("z", {{"type", "number"}}, section_domain),
      part("frame", {{"type", "number"}}, section_frame),
      part("frames",
           {{"type", "array"},
            {"items", {{"type", "integer"}, {"minimum", 0}, {"maximum", largest_frame}}},
            {"minItems", 2},
            {"maxItems", 2}},
           section_frame),
      part("scene", object_schema(scene_fields(kind), kind), section_scene),
      part("volume", object_schema(volume_fields(), kind), section_volume),
  };
}

FormatFields build_domain_fields() {
  return {{"min", numbers_of(2), every_kind, every_kind}, {"max", numbers_of(2), every_kind, every_kind}};
}

FormatFields build_scene_fields(GraphKind kind) {
  json objects = typed_objects(scene_object_types, scene_object_fields, kind, max_scene_objects);
  if (kind != GraphKind::volume) objects["minItems"] = 1;
  return {
      {"camera", object_schema(camera_fields(), kind)},
      // A surface graph shades its objects; a volume's are optional.
      {"objects", objects, every_kind, surface_kind},
      {"lights", typed_objects(scene_light_types, scene_light_fields, kind, max_scene_lights)},
      {"background", colour()},
      {"environment", {{"type", "string"}, {"minLength", 1}}},
      {"ambient", colour()},
      {"lighting", {{"enum", {"lit", "none"}}}},
      {"shadows", {{"type", "boolean"}}},
  };
}

FormatFields build_camera_fields() {
  return {{"position", numbers_of(3)},
          {"target", numbers_of(3)},
          {"up", numbers_of(3)},
          {"fov", {{"type", "number"}, {"exclusiveMinimum", 0}, {"exclusiveMaximum", 180}}},
          {"orthographic", positive_number()}};
}

FormatFields build_transform_fields() {
  return {{"translate", numbers_of(3)}, {"rotate", numbers_of(3)}, {"scale", number_or_triple()}};
}

FormatFields build_scene_object_fields(const std::string& type) {
  FormatFields fields = {
      {"type", {{"enum", scene_object_types}}, every_kind, every_kind},
      {"id", {{"type", "integer"}, {"minimum", 0}, {"maximum", 1000000}}},
      {"doc", text()},
      {"transform", object_schema(transform_fields(), GraphKind::surface)},
      // A volume's objects are opaque, of one colour each.
      {"color", colour(), volume_kind},
  };
  auto add = [&](FormatField field) { fields.push_back(std::move(field)); };
  if (type == "sphere") add({"radius", positive_number()});
  if (type == "torus") {
    add({"major_radius", positive_number()});
    add({"minor_radius", positive_number()});
  }
  if (type == "box") add({"size", {{"type", "array"}, {"items", positive_number()}, {"minItems", 3}, {"maxItems", 3}}});
  if (type == "revolution")
    add({"profile",
         {{"type", "array"}, {"items", numbers_of(2)}, {"minItems", 2}, {"maxItems", max_profile_points}},
         every_kind,
         every_kind});
  if (type == "mesh") add({"file", {{"type", "string"}, {"minLength", 1}}, every_kind, every_kind});
  return fields;
}

FormatFields build_scene_light_fields(const std::string& type) {
  return {{"type", {{"enum", scene_light_types}}, every_kind, every_kind},
          {type == "point" ? "position" : "direction", numbers_of(3)},
          {"color", colour()},
          {"intensity", {{"type", "number"}, {"minimum", 0}}}};
}

FormatFields build_volume_fields() {
  return {{"bounds", object_schema(bounds_fields(), GraphKind::volume), every_kind, every_kind},
          {"step", positive_number()},
          {"reference_step", positive_number()},
          {"jitter", {{"type", "boolean"}}},
          {"doc", text()}};
}

FormatFields build_bounds_fields() {
  return {{"min", numbers_of(3), every_kind, every_kind}, {"max", numbers_of(3), every_kind, every_kind}};
}

// Each table is built once: the parser reads them for every object.
template <FormatFields (*build)()>
const FormatFields& built_once() {
  static const FormatFields table = build();
  return table;
}

template <FormatFields (*build)(GraphKind)>
const FormatFields& built_once(GraphKind kind) {
  static const std::array<FormatFields, graph_kind_count> tables = [] {
    std::array<FormatFields, graph_kind_count> built;
    for (GraphKind each : all_graph_kinds) built[static_cast<std::size_t>(each)] = build(each);
    return built;
  }();
  return tables[static_cast<std::size_t>(kind)];
}

template <FormatFields (*build)(const std::string&)>
const FormatFields& built_once(const std::vector<std::string>& types, const std::string& type) {
  static const std::map<std::string, FormatFields> tables = [&] {
    std::map<std::string, FormatFields> built;
    for (const std::string& each : types) built[each] = build(each);
    return built;
  }();
  return tables.at(type);
}

}  // namespace

const FormatFields& graph_fields(GraphKind kind) { return built_once<build_graph_fields>(kind); }
const FormatFields& render_fields(GraphKind kind) { return built_once<build_render_fields>(kind); }
const FormatFields& scene_fields(GraphKind kind) { return built_once<build_scene_fields>(kind); }
const FormatFields& param_fields() { return built_once<build_param_fields>(); }
const FormatFields& function_fields() { return built_once<build_function_fields>(); }
const FormatFields& function_input_fields() { return built_once<build_function_input_fields>(); }
const FormatFields& domain_fields() { return built_once<build_domain_fields>(); }
const FormatFields& camera_fields() { return built_once<build_camera_fields>(); }
const FormatFields& transform_fields() { return built_once<build_transform_fields>(); }
const FormatFields& volume_fields() { return built_once<build_volume_fields>(); }
const FormatFields& bounds_fields() { return built_once<build_bounds_fields>(); }
const FormatFields& scene_object_fields(const std::string& type) {
  return built_once<build_scene_object_fields>(scene_object_types, type);
}
const FormatFields& scene_light_fields(const std::string& type) {
  return built_once<build_scene_light_fields>(scene_light_types, type);
}

void check_format_fields(const JsonReader& reader, const json& object, const FormatFields& fields, GraphKind kind,
                         const std::string& what) {
  for (const auto& [key, value] : object.items()) {
    const FormatField* field = nullptr;
    for (const FormatField& candidate : fields)
      if (candidate.name == key) field = &candidate;
    if (!field) reader.fail({}, {}, "unknown field \"" + key + "\" in " + what);
    if (!field->kinds.contains(kind))
      reader.fail({}, {}, what + " \"" + key + "\" is for " + kind_set_names(field->kinds) + " graphs, not " +
                              std::string(graph_kind_name(kind)) + "s");
  }
}

json object_schema(const FormatFields& fields, GraphKind kind) {
  json properties = json::object(), required = json::array();
  for (const FormatField& field : fields) {
    if (!field.kinds.contains(kind)) continue;
    properties[field.name] = field.schema;
    if (field.required.contains(kind)) required.push_back(field.name);
  }
  json schema = {{"type", "object"}, {"properties", properties}, {"additionalProperties", false}};
  if (!required.empty()) schema["required"] = required;
  return schema;
}

}  // namespace shadetree

// shadetree schema: a JSON Schema (draft 2020-12) of the graph format, with
// the op names enumerated from the node library, for editors to validate
// and complete graph files.
#include <cstdio>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "graph/graph.h"
#include "graph/parse.h"
#include "nodes/registry.h"

namespace shadetree {

namespace {
using json = nlohmann::ordered_json;

json graph_schema() {
  json op_names = json::array();
  for (const OpDef& op : all_ops()) op_names.push_back(op.name);
  json type_names = json::array();
  for (Type type : all_types) type_names.push_back(type_name(type));

  const json number_array = {{"type", "array"}, {"items", {{"type", "number"}}}, {"minItems", 2}, {"maxItems", 3}};
  const json input_value = {{"description", "a node id (\"id\" or \"id.output\"), \"$param\", or a literal"},
                            {"oneOf", json::array({{{"type", "string"}, {"minLength", 1}},
                                                   {{"type", "number"}},
                                                   {{"type", "boolean"}},
                                                   number_array})}};
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
  const json value_of_type = {
      {"oneOf", json::array({{{"type", "number"}}, {{"type", "boolean"}}, number_array})}};
  const json param = {{"type", "object"},
                      {"required", {"type", "default"}},
                      {"properties",
                       {{"type", {{"enum", type_names}}},
                        {"default", value_of_type},
                        {"min", {{"type", "number"}}},
                        {"max", {{"type", "number"}}},
                        {"doc", {{"type", "string"}}}}},
                      {"additionalProperties", false}};
  const json function_input = {
      {"oneOf", json::array({{{"enum", type_names}},
                             {{"type", "object"},
                              {"required", {"type"}},
                              {"properties", {{"type", {{"enum", type_names}}}, {"default", value_of_type}}},
                              {"additionalProperties", false}}})}};
  const json function = {{"type", "object"},
                         {"required", {"nodes", "outputs"}},
                         {"properties",
                          {{"doc", {{"type", "string"}}},
                           {"inputs", {{"type", "object"}, {"additionalProperties", function_input}}},
                           {"nodes", nodes},
                           {"outputs", outputs}}},
                         {"additionalProperties", false}};
  const json pair = {{"type", "array"}, {"items", {{"type", "number"}}}, {"minItems", 2}, {"maxItems", 2}};
  const json triple = {{"type", "array"}, {"items", {{"type", "number"}}}, {"minItems", 3}, {"maxItems", 3}};
  const json colour = {{"oneOf", {{{"type", "number"}, {"minimum", 0}}, triple}}};
  const json transform = {{"type", "object"},
                          {"properties",
                           {{"translate", triple},
                            {"rotate", triple},
                            {"scale", {{"oneOf", {{{"type", "number"}}, triple}}}}}},
                          {"additionalProperties", false}};
  const json object = {
      {"type", "object"},
      {"required", {"type"}},
      {"properties",
       {{"type", {{"enum", {"sphere", "torus", "plane", "box", "revolution", "mesh"}}}},
        {"id", {{"type", "integer"}, {"minimum", 0}, {"maximum", 1000000}}},
        {"doc", {{"type", "string"}}},
        {"transform", transform},
        {"radius", {{"type", "number"}, {"exclusiveMinimum", 0}}},
        {"major_radius", {{"type", "number"}, {"exclusiveMinimum", 0}}},
        {"minor_radius", {{"type", "number"}, {"exclusiveMinimum", 0}}},
        {"size", triple},
        {"profile", {{"type", "array"}, {"items", pair}, {"minItems", 2}, {"maxItems", max_profile_points}}},
        {"file", {{"type", "string"}, {"minLength", 1}}}}},
      {"additionalProperties", false}};
  const json light = {{"type", "object"},
                      {"required", {"type"}},
                      {"properties",
                       {{"type", {{"enum", {"directional", "point"}}}},
                        {"direction", triple},
                        {"position", triple},
                        {"color", colour},
                        {"intensity", {{"type", "number"}, {"minimum", 0}}}}},
                      {"additionalProperties", false}};
  const json scene = {
      {"type", "object"},
      {"required", {"objects"}},
      {"properties",
       {{"camera", {{"type", "object"},
                    {"properties",
                     {{"position", triple},
                      {"target", triple},
                      {"up", triple},
                      {"fov", {{"type", "number"}, {"exclusiveMinimum", 0}, {"exclusiveMaximum", 180}}},
                      {"orthographic", {{"type", "number"}, {"exclusiveMinimum", 0}}}}},
                    {"additionalProperties", false}}},
        {"objects", {{"type", "array"}, {"items", object}, {"minItems", 1}, {"maxItems", max_scene_objects}}},
        {"lights", {{"type", "array"}, {"items", light}, {"maxItems", max_scene_lights}}},
        {"background", colour},
        {"ambient", colour},
        {"lighting", {{"enum", {"lit", "none"}}}},
        {"shadows", {{"type", "boolean"}}}}},
      {"additionalProperties", false}};
  const json render = {
      {"type", "object"},
      {"properties",
       {{"size", {{"type", "array"}, {"items", {{"type", "integer"}, {"minimum", 1}, {"maximum", max_image_side}}},
                  {"minItems", 2}, {"maxItems", 2}}},
        {"domain", {{"type", "object"},
                    {"required", {"min", "max"}},
                    {"properties", {{"min", pair}, {"max", pair}}},
                    {"additionalProperties", false}}},
        {"z", {{"type", "number"}}},
        {"frame", {{"type", "number"}}},
        {"scene", scene}}},
      {"additionalProperties", false}};
  json kinds = json::array();
  for (GraphKind kind : all_graph_kinds) kinds.push_back(graph_kind_name(kind));

  return {{"$schema", "https://json-schema.org/draft/2020-12/schema"},
          {"title", "shadetree graph"},
          {"type", "object"},
          {"required", {"format", "version", "kind", "nodes", "outputs"}},
          {"properties",
           {{"format", {{"const", "shadetree-graph"}}},
            {"version", {{"const", graph_format_version}}},
            {"name", {{"type", "string"}}},
            {"kind", {{"enum", kinds}}},
            {"doc", {{"type", "string"}}},
            {"params", {{"type", "object"}, {"additionalProperties", param}}},
            {"functions", {{"type", "object"}, {"additionalProperties", function}}},
            {"nodes", nodes},
            {"outputs", outputs},
            {"render", render}}},
          {"additionalProperties", false},
          {"$defs", {{"value", input_value}, {"node", node}}}};
}
}  // namespace

void add_schema_command(CLI::App& app, CommandRunner& run) {
  auto* command = app.add_subcommand("schema", "print a JSON Schema of the graph format");
  command->callback([&run] {
    run = [] {
      std::printf("%s\n", graph_schema().dump(2).c_str());
      return ExitStatus::ok;
    };
  });
}

}  // namespace shadetree

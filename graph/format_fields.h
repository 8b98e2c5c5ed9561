// The objects of the graph format and their fields, written once: the
// parser refuses any field an object's table does not list (or lists for
// another graph kind), and `shadetree schema` is built from the same
// tables (graph/format_schema.h), so the schema cannot drift from what
// `check` accepts. Each field carries the JSON Schema of its value.
#pragma once

#include <string>
#include <vector>

#include "graph/json_reader.h"
#include "nodes/graph_kind.h"

namespace shadetree {

struct FormatField {
  std::string name;
  json schema;                 // of the field's value
  KindSet kinds = every_kind;  // the graph kinds that may have it
  KindSet required = {};       // the graph kinds that must
};
using FormatFields = std::vector<FormatField>;

// The top level of a graph file of `kind`.
const FormatFields& graph_fields(GraphKind kind);
const FormatFields& param_fields();
const FormatFields& function_fields();
const FormatFields& function_input_fields();
// render, and what it holds.
const FormatFields& render_fields(GraphKind kind);
const FormatFields& domain_fields();
const FormatFields& scene_fields(GraphKind kind);
const FormatFields& camera_fields();
const FormatFields& transform_fields();
const FormatFields& volume_fields();
const FormatFields& bounds_fields();

inline const std::vector<std::string> scene_object_types = {"sphere", "torus", "plane", "box", "revolution", "mesh"};
inline const std::vector<std::string> scene_light_types = {"directional", "point"};

// A scene object of `type` (one of scene_object_types); a volume's
// objects also take a colour.
const FormatFields& scene_object_fields(const std::string& type);
const FormatFields& scene_light_fields(const std::string& type);

// Fails (through `reader`) on a field of `object` that `fields` does not
// list, or lists for other graph kinds than `kind`; `what` names the object
// in the message. Required fields are the parser's to ask for, with their
// own messages.
void check_format_fields(const JsonReader& reader, const json& object, const FormatFields& fields, GraphKind kind,
                         const std::string& what);

// The JSON Schema of an object holding `fields`, for a graph of `kind`:
// the fields of other kinds are left out, nothing else is allowed.
json object_schema(const FormatFields& fields, GraphKind kind);

}  // namespace shadetree

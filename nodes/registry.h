// The node library: for every op its name, family, one-line doc, typed
// inputs (with defaults), outputs and compile-time attributes. It is the
// single source of truth for the type checker, `shadetree nodes`, the JSON
// Schema and both backends (which take the semantics from nodes/semantics/).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "nodes/type.h"
#include "nodes/limits.h"
#include "nodes/op_id.h"

namespace shadetree {

// How an input's or output's type is determined.
enum class TypeRule : unsigned char {
  fixed,    // exactly `type` (after implicit conversion)
  generic,  // the op's type variable T, unified over all generic inputs
};

// The types T may take for an op.
enum class GenericSet : unsigned char {
  none,     // the op has no type variable
  numeric,  // float, vec2, vec3, color
  vectors,  // vec2, vec3, color
};

// A default for an unwired input: a scalar splatted over the components.
struct PortSpec {
  std::string name;
  TypeRule rule = TypeRule::fixed;
  Type type = Type::float_;
  std::optional<float> default_value;
  std::string doc;
};

enum class AttributeKind : unsigned char {
  integer,       // e.g. noise seed
  choice,        // one of `choices`, e.g. spline basis
  value_list,    // a list of numbers or of 2/3-arrays (knots, colours)
  number_grid,   // a list of equally long lists of numbers (2D tables)
  number_pair,   // [lo, hi]
};

struct AttributeSpec {
  std::string name;
  AttributeKind kind;
  bool required = false;
  std::vector<std::string> choices;  // for `choice`; the first is the default
  std::string doc;
};

enum class OpFamily : unsigned char {
  input, generator, arithmetic, vector, conditional, spline, soft_object
};

struct OpDef {
  OpId id;
  std::string name;
  OpFamily family;
  std::string doc;
  GenericSet generic = GenericSet::none;
  std::vector<PortSpec> inputs;
  std::vector<PortSpec> outputs;
  std::vector<AttributeSpec> attributes;
  // For `spline` and `color_table`, T is the type of the knot values
  // (numbers -> float, 2-arrays -> vec2, 3-arrays -> color).
  bool type_from_knots = false;
  // Only valid in graphs of these kinds (empty: all kinds).
  std::vector<std::string> kinds;
};

std::span<const OpDef> all_ops();

// Ops that read the seeded noise tables (and take a `seed` attribute).
bool uses_noise_tables(OpId id);
const OpDef& op_def(OpId id);
const OpDef* find_op(std::string_view name);
std::string_view family_name(OpFamily family);

}  // namespace shadetree

// The node library: for every op its name, family, one-line doc, typed
// inputs (with defaults), outputs, compile-time attributes and tables. It
// is the single source of truth for the type checker, `shadetree nodes`,
// the JSON Schema and both backends, whose bindings are generated from the
// op list (SHADETREE_OPS in op_id.h) and each op's semantics in nodes/ops/.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "nodes/attributes.h"
#include "nodes/globals.h"
#include "nodes/graph_kind.h"
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
  image_file,    // the path of an image file, relative to the graph file
  mesh_file,     // the path of a mesh file, relative to the graph file
};

struct AttributeSpec {
  std::string name;
  AttributeKind kind;
  bool required = false;
  std::vector<std::string> choices;  // for `choice`; the first is the default
  std::string doc;
};

enum class OpFamily : unsigned char {
  input, generator, arithmetic, vector, conditional, spline, soft_object, derivative
};

// The tables an op reads besides its attribute data.
enum class OpTables : unsigned char {
  none,
  noise,  // the seeded permutation and gradient tables; the op takes a `seed` attribute
};

// An op's definition: everything but its semantics, which sit beside it in
// nodes/ops/ (see op_frame.h). Input ops are made from the globals table.
struct OpDef {
  OpId id{};  // set by the registry: the op's place in SHADETREE_OPS
  std::string name;
  OpFamily family = OpFamily::arithmetic;
  std::string doc;
  GenericSet generic = GenericSet::none;
  std::vector<PortSpec> inputs;
  std::vector<PortSpec> outputs;
  std::vector<AttributeSpec> attributes;
  OpTables tables = OpTables::none;
  // For `spline` and `color_table`, T is the type of the knot values
  // (numbers -> float, 2-arrays -> vec2, 3-arrays -> color).
  bool type_from_knots = false;
  KindSet kinds = every_kind;  // the graph kinds the op may be used in
  // Lays out the op's attributes (besides the seed of noise ops); set by
  // the registry from the op's `lay_out`, where it has one.
  void (*lay_out)(const Attributes& attributes, AttributeLayout& layout) = nullptr;
};

std::span<const OpDef> all_ops();

const OpDef& op_def(OpId id);
const OpDef* find_op(std::string_view name);
std::string_view family_name(OpFamily family);

// The global an input op reads, or nothing for the other ops.
std::optional<GlobalId> global_of(OpId id);

}  // namespace shadetree

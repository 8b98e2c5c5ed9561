#include "nodes/type.h"

namespace shadetree {

std::string_view type_name(Type type) {
  switch (type) {
    case Type::float_: return "float";
    case Type::int_: return "int";
    case Type::bool_: return "bool";
    case Type::vec2: return "vec2";
    case Type::vec3: return "vec3";
    case Type::color: return "color";
  }
  return "?";
}

std::optional<Type> parse_type_name(std::string_view name) {
  for (Type type : all_types)
    if (type_name(type) == name) return type;
  return std::nullopt;
}

bool is_vector(Type type) { return component_count(type) > 1; }

bool converts_to(Type from, Type to) {
  if (from == to) return true;
  if (from == Type::int_ && to == Type::float_) return true;
  if ((from == Type::float_ || from == Type::int_) && is_vector(to)) return true;
  return false;
}

}  // namespace shadetree

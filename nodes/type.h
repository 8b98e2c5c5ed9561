// The value types of shade graphs. Every type is stored as 1-3 float
// components (ints and bools too: ints are exact up to 2^24, bools are 0/1),
// so registers, kernels and buffers need only one element type.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace shadetree {

enum class Type : unsigned char { float_, int_, bool_, vec2, vec3, color };

inline constexpr Type all_types[] = {Type::float_, Type::int_, Type::bool_,
                                     Type::vec2,   Type::vec3, Type::color};

std::string_view type_name(Type type);
std::optional<Type> parse_type_name(std::string_view name);
constexpr int component_count(Type type) {
  return type == Type::vec2 ? 2 : type == Type::vec3 || type == Type::color ? 3 : 1;
}
bool is_vector(Type type);  // vec2, vec3 or color

// Implicit conversions (PSE-style): int -> float, and float (or int) ->
// any vector type by splatting. vec3 and color do not convert into each
// other implicitly; the to_color / to_vec3 nodes say so explicitly.
bool converts_to(Type from, Type to);

}  // namespace shadetree

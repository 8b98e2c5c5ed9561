// Shorthands for the op definitions of nodes/ops/: typed ports with
// defaults and docs, and the attribute every noise op takes.
#pragma once

#include "nodes/registry.h"

namespace shadetree::define {

inline PortSpec in(std::string name, Type type, std::string doc = {}) {
  return {std::move(name), TypeRule::fixed, type, std::nullopt, std::move(doc)};
}
inline PortSpec in(std::string name, Type type, float default_value, std::string doc = {}) {
  return {std::move(name), TypeRule::fixed, type, default_value, std::move(doc)};
}
inline PortSpec generic_in(std::string name, std::string doc = {}) {
  return {std::move(name), TypeRule::generic, Type::float_, std::nullopt, std::move(doc)};
}
inline PortSpec generic_in(std::string name, float default_value, std::string doc = {}) {
  return {std::move(name), TypeRule::generic, Type::float_, default_value, std::move(doc)};
}
inline PortSpec out(Type type, std::string name = "out") {
  return {std::move(name), TypeRule::fixed, type, std::nullopt, {}};
}
inline PortSpec generic_out() { return {"out", TypeRule::generic, Type::float_, std::nullopt, {}}; }

inline AttributeSpec seed_attribute() {
  return {"seed", AttributeKind::integer, false, {}, "permutation and gradient tables seed (default 1989)"};
}

// The period of the periodic noise ops (OSL's pnoise): per axis, in cells
// of the lattice, rounded to a whole number from 1 to 256; a texture over
// a domain of one period tiles exactly.
inline PortSpec period_input() {
  return in("period", Type::vec3, 4.0f, "repeats every this many units of p, per axis (whole, 1 to 256)");
}

// The fourth coordinate of the 4D noise ops, and their period along it.
inline PortSpec w_input() { return in("w", Type::float_, "fourth coordinate, usually time: the noise evolves along it"); }
inline PortSpec w_period_input() {
  return in("w_period", Type::float_, 4.0f, "repeats every this many units of w (whole, 1 to 256): a loop's length");
}

// T -> T, applied to each component.
inline OpDef unary(std::string name, std::string doc) {
  return {.name = std::move(name), .family = OpFamily::arithmetic, .doc = std::move(doc),
          .generic = GenericSet::numeric, .inputs = {generic_in("x")}, .outputs = {generic_out()}};
}

// (T, T) -> T, applied to each component; floats promote.
inline OpDef binary(std::string name, std::string doc) {
  return {.name = std::move(name), .family = OpFamily::arithmetic, .doc = std::move(doc),
          .generic = GenericSet::numeric, .inputs = {generic_in("a"), generic_in("b")}, .outputs = {generic_out()}};
}

inline OpDef comparison(std::string name, std::string doc) {
  return {.name = std::move(name), .family = OpFamily::conditional, .doc = std::move(doc),
          .inputs = {in("a", Type::float_), in("b", Type::float_)}, .outputs = {out(Type::bool_)}};
}

inline OpDef soft_boolean(std::string name, std::string doc) {
  return {.name = std::move(name), .family = OpFamily::soft_object, .doc = std::move(doc),
          .inputs = {in("a", Type::float_), in("b", Type::float_)}, .outputs = {out(Type::float_)}};
}

}  // namespace shadetree::define

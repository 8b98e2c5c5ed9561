// Vector ops over 2 or 3 components. Each op: its definition and its
// semantics over a frame (see nodes/op_frame.h); the formulas are in
// nodes/semantics/vector.h.
#pragma once

#include "nodes/interval_frame.h"
#include "nodes/op_definition.h"
#include "nodes/op_frame.h"
#include "nodes/semantics/shape_intervals.h"
#include "nodes/semantics/vector.h"

namespace shadetree::ops {

using namespace define;
namespace sem = semantics;

inline OpDef vector_op(std::string name, std::string doc, GenericSet generic, std::vector<PortSpec> inputs,
                       std::vector<PortSpec> outputs) {
  return {.name = std::move(name), .family = OpFamily::vector, .doc = std::move(doc), .generic = generic,
          .inputs = std::move(inputs), .outputs = std::move(outputs)};
}

struct dot {
  static OpDef definition() {
    return vector_op("dot", "inner product", GenericSet::vectors, {generic_in("a"), generic_in("b")},
                     {out(Type::float_)});
  }
  template <class X>
  static void evaluate(const X& x) {
    LaneOf<X> a[3], b[3];
    frame::to_array(x, 0, a);
    frame::to_array(x, 1, b);
    x.out() = sem::dot_n(a, b, x.arg_components(0));
  }
};

struct cross {
  static OpDef definition() {
    return vector_op("cross", "cross product", GenericSet::none, {in("a", Type::vec3), in("b", Type::vec3)},
                     {out(Type::vec3)});
  }
  template <class X>
  static void evaluate(const X& x) {
    frame::store_vec3(x, sem::cross(frame::vec3(x, 0), frame::vec3(x, 1)));
  }
};

struct length {
  static OpDef definition() {
    return vector_op("length", "Euclidean norm", GenericSet::vectors, {generic_in("v")}, {out(Type::float_)});
  }
  template <class X>
  static void evaluate(const X& x) {
    LaneOf<X> v[3];
    frame::to_array(x, 0, v);
    x.out() = sem::length_n(v, x.arg_components(0));
  }
};

struct normalize {
  static OpDef definition() {
    return vector_op("normalize", "v / length(v) (0 stays 0)", GenericSet::vectors, {generic_in("v")},
                     {generic_out()});
  }
  template <class X>
  static void evaluate(const X& x) {
    LaneOf<X> v[3], normalized[3];
    frame::to_array(x, 0, v);
    sem::normalize_n(v, x.components(), normalized);
    frame::for_components(x.components(), [&](int c) { x.out(c) = normalized[c]; });
  }
  static void evaluate_interval(const IntervalFrame& x) {
    evaluate(x);
    // An infinite component may make NaN (inf * 0); finite ones give a unit vector or 0.
    if (!x.finite_inputs(1)) return;
    constexpr float bound = lanes::unit_length_bound;
    frame::for_components(x.components(), [&](int c) { x.out(c) = lanes::meet(x.out(c), {-bound, bound}); });
  }
};

// Lowered to one extract instruction per component (ir/lower.cpp).
struct split {
  static OpDef definition() {
    return vector_op("split", "components x, y, z of a vector (z is 0 for vec2)", GenericSet::vectors,
                     {generic_in("v")}, {out(Type::float_, "x"), out(Type::float_, "y"), out(Type::float_, "z")});
  }
};

// The result's components are the arguments, in order.
struct from_components {
  template <class X>
  static void evaluate(const X& x) {
    frame::for_components(x.components(), [&](int c) { x.out(c) = x.in(c); });
  }
};

struct vec2 : from_components {
  static OpDef definition() {
    return vector_op("vec2", "vec2 from components", GenericSet::none,
                     {in("x", Type::float_, 0.0f), in("y", Type::float_, 0.0f)}, {out(Type::vec2)});
  }
};

struct vec3 : from_components {
  static OpDef definition() {
    return vector_op("vec3", "vec3 from components", GenericSet::none,
                     {in("x", Type::float_, 0.0f), in("y", Type::float_, 0.0f), in("z", Type::float_, 0.0f)},
                     {out(Type::vec3)});
  }
};

struct color : from_components {
  static OpDef definition() {
    return vector_op("color", "color from r, g, b", GenericSet::none,
                     {in("r", Type::float_, 0.0f), in("g", Type::float_, 0.0f), in("b", Type::float_, 0.0f)},
                     {out(Type::color)});
  }
};

// The argument's components, relabelled.
struct same_components {
  template <class X>
  static void evaluate(const X& x) {
    frame::for_components(x.components(), [&](int c) { x.out(c) = x.in(0, c); });
  }
};

struct to_color : same_components {
  static OpDef definition() {
    return vector_op("to_color", "a vec3 reinterpreted as a color", GenericSet::none, {in("v", Type::vec3)},
                     {out(Type::color)});
  }
};

struct to_vec3 : same_components {
  static OpDef definition() {
    return vector_op("to_vec3", "a color reinterpreted as a vec3", GenericSet::none, {in("c", Type::color)},
                     {out(Type::vec3)});
  }
};

}  // namespace shadetree::ops

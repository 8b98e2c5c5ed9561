// Soft objects and their generalized booleans (Perlin & Hoffert 1989
// sections 2.1 and 2.2). Each op: its definition and its semantics over a
// frame (see nodes/op_frame.h); the formulas are in
// nodes/semantics/soft_objects.h.
#pragma once

#include "nodes/op_definition.h"
#include "nodes/op_frame.h"
#include "nodes/ops/arithmetic.h"
#include "nodes/semantics/soft_objects.h"

namespace shadetree::ops {

struct sphere {
  static OpDef definition() {
    return {.name = "sphere", .family = OpFamily::soft_object,
            .doc = "soft sphere density: 1 inside r - s/2, 0 outside r + s/2 (1989 section 2.1)",
            .inputs = {in("p", Type::vec3), in("center", Type::vec3, 0.0f), in("radius", Type::float_, 1.0f),
                       in("softness", Type::float_, 0.2f)},
            .outputs = {out(Type::float_)}};
  }
  template <class X>
  static void evaluate(const X& x) {
    x.out() = sem::soft_sphere(frame::vec3(x, 0), frame::vec3(x, 1), x.in(2), x.in(3));
  }
};

struct box {
  static OpDef definition() {
    return {.name = "box", .family = OpFamily::soft_object,
            .doc = "soft box density: ramps from 1 to 0 across softness around the surface",
            .inputs = {in("p", Type::vec3), in("center", Type::vec3, 0.0f), in("half_size", Type::vec3, 0.5f),
                       in("softness", Type::float_, 0.2f)},
            .outputs = {out(Type::float_)}};
  }
  template <class X>
  static void evaluate(const X& x) {
    x.out() = sem::soft_box(frame::vec3(x, 0), frame::vec3(x, 1), frame::vec3(x, 2), x.in(3));
  }
};

struct torus {
  static OpDef definition() {
    return {.name = "torus", .family = OpFamily::soft_object,
            .doc = "soft torus around the z axis: ramps from 1 to 0 across softness around the surface",
            .inputs = {in("p", Type::vec3), in("center", Type::vec3, 0.0f), in("major_radius", Type::float_, 1.0f),
                       in("minor_radius", Type::float_, 0.25f), in("softness", Type::float_, 0.2f)},
            .outputs = {out(Type::float_)}};
  }
  template <class X>
  static void evaluate(const X& x) {
    x.out() = sem::soft_torus(frame::vec3(x, 0), frame::vec3(x, 1), x.in(2), x.in(3), x.in(4));
  }
};

// Geometry-dependent DMFs (1989 section 2.4, hair and fur: "project each
// point x in the soft region perpendicularly down to the inner solid
// boundary") and the vector fields of Gilet & Dischler 2010 section 4.4
// ("a field that shifts all space points exactly on the sphere boundary":
// closest_on_sphere(p) - p).
struct closest_on_sphere {
  static OpDef definition() {
    return {.name = "closest_on_sphere", .family = OpFamily::soft_object,
            .doc = "the point of a sphere's surface closest to p (1989 project; 2010 vector field to the boundary)",
            .inputs = {in("p", Type::vec3), in("center", Type::vec3, 0.0f), in("radius", Type::float_, 1.0f)},
            .outputs = {out(Type::vec3)}};
  }
  template <class X>
  static void evaluate(const X& x) {
    frame::store_vec3(x, sem::closest_on_sphere(frame::vec3(x, 0), frame::vec3(x, 1), x.in(2)));
  }
};

struct closest_on_torus {
  static OpDef definition() {
    return {.name = "closest_on_torus", .family = OpFamily::soft_object,
            .doc = "the point of a torus's surface (around the z axis, as torus) closest to p (1989 furry donut)",
            .inputs = {in("p", Type::vec3), in("center", Type::vec3, 0.0f), in("major_radius", Type::float_, 1.0f),
                       in("minor_radius", Type::float_, 0.25f)},
            .outputs = {out(Type::vec3)}};
  }
  template <class X>
  static void evaluate(const X& x) {
    frame::store_vec3(x, sem::closest_on_torus(frame::vec3(x, 0), frame::vec3(x, 1), x.in(2), x.in(3)));
  }
};

SHADETREE_COMPONENTWISE_OP(intersect, 2, soft_intersect, soft_boolean("intersect", "a * b (1989 section 2.2)"))
SHADETREE_COMPONENTWISE_OP(union_, 2, soft_union, soft_boolean("union", "a + b - a * b (1989 section 2.2)"))
SHADETREE_COMPONENTWISE_OP(difference, 2, soft_difference,
                           soft_boolean("difference", "a - a * b (1989 section 2.2)"))
SHADETREE_COMPONENTWISE_OP(complement, 1, soft_complement,
                           (OpDef{.name = "complement", .family = OpFamily::soft_object,
                                  .doc = "1 - a (1989 section 2.2)", .inputs = {in("a", Type::float_)},
                                  .outputs = {out(Type::float_)}}))

}  // namespace shadetree::ops

// Soft objects and their generalized booleans (Perlin & Hoffert 1989
// sections 2.1 and 2.2). Each op: its definition and its semantics over a
// frame (see nodes/op_frame.h); the formulas are in
// nodes/semantics/soft_objects.h.
#pragma once

#include "nodes/interval_frame.h"
#include "nodes/op_definition.h"
#include "nodes/op_frame.h"
#include "nodes/ops/arithmetic.h"
#include "nodes/semantics/shape_intervals.h"
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
  // Within the sphere's bounding box, however loose the generic form is
  // where p nears the centre (its direction there is any).
  static void evaluate_interval(const IntervalFrame& x) {
    evaluate(x);
    if (!x.finite_inputs(3)) return;
    const float radius = std::max(std::fabs(x.in(2).lo), std::fabs(x.in(2).hi));
    for (int c = 0; c < 3; ++c) x.out(c) = lanes::within_reach(x.out(c), x.in(1, c), 1.25f * radius);
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
  // Within the torus's bounding box, as closest_on_sphere.
  static void evaluate_interval(const IntervalFrame& x) {
    evaluate(x);
    if (!x.finite_inputs(4)) return;
    const auto magnitude = [](lanes::Interval r) { return std::max(std::fabs(r.lo), std::fabs(r.hi)); };
    const float minor = magnitude(x.in(3)), across = magnitude(x.in(2)) + minor;
    for (int c = 0; c < 3; ++c) x.out(c) = lanes::within_reach(x.out(c), x.in(1, c), 1.25f * (c < 2 ? across : minor));
  }
};

// Gilet & Dischler 2010 section 5, arbitrary objects: a mesh file becomes
// a signed distance grid (OpenVDB), from which these give the distance to
// the surface and the closest point on it, so that any mesh can be a soft
// object (soft_ramp of the distance) with a vector field toward its
// boundary. data: the grid (semantics::distance_grid_header).
inline AttributeSpec mesh_file_attribute() {
  return {"file", AttributeKind::mesh_file, true, {},
          "a closed triangle mesh (.obj, .ply), relative to the graph file; read once per compile"};
}
inline AttributeSpec resolution_attribute() {
  return {"resolution", AttributeKind::integer, false, {},
          "voxels of the distance grid along the mesh's longest side, 8 to 128 (default 64, as in the paper)"};
}

inline void lay_out_distance_grid(const Attributes& attributes, AttributeLayout& layout) {
  const std::uint32_t resolution = attributes.unsigned_integer("resolution", 64);
  if (resolution < 8 || resolution > 128) attributes.fail("attribute \"resolution\" must be from 8 to 128");
  const DistanceGrid& grid = attributes.mesh_distance_grid("file", static_cast<int>(resolution));
  layout.data = {grid.origin[0], grid.origin[1], grid.origin[2], grid.voxel_size, float(grid.size[0]),
                 float(grid.size[1]), float(grid.size[2])};
  layout.data.insert(layout.data.end(), grid.distance.begin(), grid.distance.end());
}

struct mesh_distance {
  static OpDef definition() {
    return {.name = "mesh_distance", .family = OpFamily::soft_object,
            .doc = "signed distance from p to a mesh's surface, negative inside (2010 section 5: arbitrary objects)",
            .inputs = {in("p", Type::vec3)}, .outputs = {out(Type::float_)},
            .attributes = {mesh_file_attribute(), resolution_attribute()}};
  }
  static void lay_out(const Attributes& attributes, AttributeLayout& layout) { lay_out_distance_grid(attributes, layout); }
  template <class X>
  static void evaluate(const X& x) {
    x.out() = sem::grid_distance(x.data(), frame::vec3(x, 0));
  }
  static void evaluate_interval(const IntervalFrame& x) {
    x.out() = lanes::grid_distance_range(x.data(), x.in(0, 0), x.in(0, 1), x.in(0, 2));
  }
};

struct mesh_closest {
  static OpDef definition() {
    return {.name = "mesh_closest", .family = OpFamily::soft_object,
            .doc = "the point of a mesh's surface closest to p (2010: the vector field toward the boundary)",
            .inputs = {in("p", Type::vec3)}, .outputs = {out(Type::vec3)},
            .attributes = {mesh_file_attribute(), resolution_attribute()}};
  }
  static void lay_out(const Attributes& attributes, AttributeLayout& layout) { lay_out_distance_grid(attributes, layout); }
  template <class X>
  static void evaluate(const X& x) {
    frame::store_vec3(x, sem::grid_closest(x.data(), frame::vec3(x, 0)));
  }
  // p - d n with |n| at most 1 (sqrt 1.5 where |grad d|^2 is subnormal):
  // within |d| of p. The generic form (the lane form over intervals, its
  // six probes of the grid each a trilinear lookup) met with this found
  // the same empty space in mesh_hypertexture and took about half of
  // bounding it (at 512x512, 0.18-0.26 s with it, 0.11-0.19 s without),
  // so it is not evaluated.
  static void evaluate_interval(const IntervalFrame& x) {
    for (int c = 0; c < 3; ++c) x.out(c) = lanes::everything();
    if (!x.finite_inputs(1)) return;
    const lanes::Interval d = lanes::grid_distance_range(x.data(), x.in(0, 0), x.in(0, 1), x.in(0, 2));
    if (!lanes::is_finite(d)) return;
    const float reach = 1.25f * std::max(std::fabs(d.lo), std::fabs(d.hi));
    for (int c = 0; c < 3; ++c) x.out(c) = lanes::within_reach(lanes::everything(), x.in(0, c), reach);
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

// A triple of lanes, for the semantics of vec3-valued ops.
#pragma once

#include "nodes/lane_scalar.h"

namespace shadetree::semantics {

template <class F>
struct Vec3 {
  F x, y, z;
};

template <class F>
F dot3(const Vec3<F>& a, const Vec3<F>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

// dot3(a, a), through square so that an interval lane keeps it >= 0.
template <class F>
F length_squared(const Vec3<F>& a) {
  return lanes::square(a.x) + lanes::square(a.y) + lanes::square(a.z);
}

}  // namespace shadetree::semantics

// A triple of lanes, for the semantics of vec3-valued ops.
#pragma once

namespace shadetree::semantics {

template <class F>
struct Vec3 {
  F x, y, z;
};

template <class F>
F dot3(const Vec3<F>& a, const Vec3<F>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

}  // namespace shadetree::semantics

// Lane primitives over dual numbers: F = Dual<G> for a lane type G (float
// in the interpreter, a clang vector in the JIT). A dual carries a value
// and its partial derivatives with respect to the three components of P;
// an op's semantics instantiated over duals compute the value they always
// compute and, by the chain rule applied primitive by primitive (forward
// mode, as OSL carries Dual2 through its shaders), its gradient. The
// gradient is that of the lane form itself: a polynomial approximation's
// own derivative, zero across floor and table lookups (which are piecewise
// constant), a select's chosen side.
//
// The primitives that only mean something on bits (to_bits, from_bits) are
// not defined here, so that semantics computing in bits must state their
// derivative (nodes/semantics/transcendental_duals.h) to compile over duals.
//
// A vector backend must declare its lane primitives before including this
// header: they are looked up when the templates below are defined.
#pragma once

#include <type_traits>

#include "nodes/lane_scalar.h"

namespace shadetree::lanes {

template <class G>
struct Dual {
  G value;
  G dx, dy, dz;  // d value / d P.x, P.y, P.z

  Dual() : value(splat<G>(0.0f)), dx(value), dy(value), dz(value) {}
  // Constants and values that do not depend on P: zero partials.
  Dual(G v) : value(v), dx(splat<G>(0.0f)), dy(dx), dz(dx) {}
  // Float literals, where G is a vector that takes none itself (C++17:
  // emit --cpp includes this). Where G does (float, the GLSL tracer's
  // lanes), a literal beside a dual goes to the operators taking a G.
  template <class S, std::enable_if_t<std::is_same_v<S, float> && !std::is_convertible_v<float, G>, int> = 0>
  Dual(S v) : Dual(splat<G>(v)) {}
  Dual(G v, G x, G y, G z) : value(v), dx(x), dy(y), dz(z) {}

  // The same linear map of every partial: d(f(u)) = f'(u) du.
  Dual chain(G v, G slope) const { return {v, dx * slope, dy * slope, dz * slope}; }

  friend Dual operator+(const Dual& a, const Dual& b) {
    return {a.value + b.value, a.dx + b.dx, a.dy + b.dy, a.dz + b.dz};
  }
  friend Dual operator+(const Dual& a, G b) { return {a.value + b, a.dx, a.dy, a.dz}; }
  friend Dual operator+(G a, const Dual& b) { return b + a; }
  friend Dual operator-(const Dual& a) { return {-a.value, -a.dx, -a.dy, -a.dz}; }
  friend Dual operator-(const Dual& a, const Dual& b) {
    return {a.value - b.value, a.dx - b.dx, a.dy - b.dy, a.dz - b.dz};
  }
  friend Dual operator-(const Dual& a, G b) { return {a.value - b, a.dx, a.dy, a.dz}; }
  friend Dual operator-(G a, const Dual& b) { return {a - b.value, -b.dx, -b.dy, -b.dz}; }
  friend Dual operator*(const Dual& a, const Dual& b) {
    return {a.value * b.value, a.dx * b.value + a.value * b.dx, a.dy * b.value + a.value * b.dy,
            a.dz * b.value + a.value * b.dz};
  }
  friend Dual operator*(const Dual& a, G b) { return {a.value * b, a.dx * b, a.dy * b, a.dz * b}; }
  friend Dual operator*(G a, const Dual& b) { return b * a; }
  // (a / b)' = (a' - q b') / b with q = a / b.
  friend Dual operator/(const Dual& a, const Dual& b) {
    const G q = a.value / b.value;
    return {q, (a.dx - q * b.dx) / b.value, (a.dy - q * b.dy) / b.value, (a.dz - q * b.dz) / b.value};
  }
  friend Dual operator/(const Dual& a, G b) { return {a.value / b, a.dx / b, a.dy / b, a.dz / b}; }
  friend Dual operator/(G a, const Dual& b) { return Dual(a) / b; }

  // Compares and selects look at values only.
  friend auto operator<(const Dual& a, const Dual& b) { return a.value < b.value; }
  friend auto operator<=(const Dual& a, const Dual& b) { return a.value <= b.value; }
  friend auto operator>(const Dual& a, const Dual& b) { return a.value > b.value; }
  friend auto operator>=(const Dual& a, const Dual& b) { return a.value >= b.value; }
  friend auto operator==(const Dual& a, const Dual& b) { return a.value == b.value; }
  friend auto operator!=(const Dual& a, const Dual& b) { return a.value != b.value; }
  friend auto operator<(const Dual& a, G b) { return a.value < b; }
  friend auto operator<=(const Dual& a, G b) { return a.value <= b; }
  friend auto operator>(const Dual& a, G b) { return a.value > b; }
  friend auto operator>=(const Dual& a, G b) { return a.value >= b; }
  friend auto operator==(const Dual& a, G b) { return a.value == b; }
  friend auto operator!=(const Dual& a, G b) { return a.value != b; }
};

// Selects look at the mask only; free templates (not friends) so that the
// semantics' qualified calls, lanes::select, find them.
template <class M, class G>
Dual<G> select(M mask, const Dual<G>& a, const Dual<G>& b) {
  return {select(mask, a.value, b.value), select(mask, a.dx, b.dx), select(mask, a.dy, b.dy),
          select(mask, a.dz, b.dz)};
}
template <class M, class G>
Dual<G> select(M mask, const Dual<G>& a, G b) {
  return select(mask, a, Dual<G>(b));
}
template <class M, class G>
Dual<G> select(M mask, G a, const Dual<G>& b) {
  return select(mask, Dual<G>(a), b);
}

template <class G>
Dual<G> floor(const Dual<G>& x) {
  return Dual<G>(floor(x.value));
}
template <class G>
Dual<G> abs(const Dual<G>& x) {
  return select(x.value < 0.0f, -x, x);
}
// The slope 1 / (2 sqrt x) is infinite at 0; taken as 0 there, so that
// the length of a zero vector has a zero gradient instead of NaN.
template <class G>
Dual<G> sqrt(const Dual<G>& x) {
  const G root = sqrt(x.value);
  return x.chain(root, select(root > 0.0f, 0.5f / root, splat<G>(0.0f)));
}
// The lane form's value; on a tie, a's partials, so that clamp(t, 0, 1)
// at t = 1 keeps t's derivative (the one from inside the interval).
template <class G>
Dual<G> min(const Dual<G>& a, const Dual<G>& b) {
  Dual<G> result = select(a.value <= b.value, a, b);
  result.value = min(a.value, b.value);
  return result;
}
template <class G>
Dual<G> max(const Dual<G>& a, const Dual<G>& b) {
  Dual<G> result = select(a.value >= b.value, a, b);
  result.value = max(a.value, b.value);
  return result;
}
template <class G>
auto to_int(const Dual<G>& x) {
  return to_int(x.value);
}

}  // namespace shadetree::lanes

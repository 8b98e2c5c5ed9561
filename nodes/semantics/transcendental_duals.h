// Dual forms of exp, log and pow (exponential.h): exp and log compute in
// bits and so cannot be instantiated over duals, and pow's special cases
// (x^0 = 1, x^1 = x) would drop the derivative with respect to y where
// they apply. Each takes the lane form for the value and the derivative of
// the function it approximates for the slopes; bias and gain are built on
// pow and need nothing more.
//
// They are overloads in the namespace of Dual so that the generic
// semantics calling them find them by argument-dependent lookup; partial
// ordering prefers them to the generic templates.
#pragma once

#include "nodes/lane_dual.h"
#include "nodes/semantics/exponential.h"

namespace shadetree::lanes {

template <class G>
Dual<G> exponential_of(const Dual<G>& x) {
  const G value = semantics::exponential_of(x.value);
  return x.chain(value, value);
}

template <class G>
Dual<G> logarithm_of(const Dual<G>& x) {
  return x.chain(semantics::logarithm_of(x.value), 1.0f / x.value);
}

// d(x^y) = y x^(y-1) dx + x^y ln|x| dy. A term whose differential is 0
// is 0 whatever its slope (a constant exponent, the common case, whatever
// ln|x| is; a constant base at 0), and the second is 0 where x^y is.
template <class G>
Dual<G> power_of(const Dual<G>& x, const Dual<G>& y) {
  const G value = semantics::power_of(x.value, y.value);
  const G by_x = y.value * semantics::power_of(x.value, y.value - 1.0f);
  const G by_y = select(value == 0.0f, splat<G>(0.0f), value * semantics::logarithm_of(abs(x.value)));
  auto term = [](G slope, G d) { return select(d == 0.0f, splat<G>(0.0f), slope * d); };
  auto slope = [&](G dx, G dy) { return term(by_x, dx) + term(by_y, dy); };
  return {value, slope(x.dx, y.dx), slope(x.dy, y.dy), slope(x.dz, y.dz)};
}

}  // namespace shadetree::lanes

// Sine and cosine, written once over a lane type F so that both backends
// compute them with the same operations (a libm call per lane would keep
// the JIT scalar; a vector libm would round differently from the
// interpreter). The method is Cephes' sinf/cosf (Moshier): reduce |x| to
// z in [-pi/4, pi/4] by the octant j with pi/4 split in three parts
// (Cody-Waite), then a degree-7 sine or degree-8 cosine polynomial.
// Accuracy: about 2 ulp while |x| < 8192; the reduction stays exact up to
// |x| ~ 5e4 and loses digits beyond; from |x| = 2^24 pi/4 (~1.3e7), where a
// float holds no digits of the phase, the result is 0 (NaN for NaN and
// infinities, as in libm).
#pragma once

#include "nodes/lane_scalar.h"

namespace shadetree::semantics {

using namespace shadetree::lanes;

template <class F>
F sine_or_cosine(F x, bool cosine) {
  F magnitude = abs(x);
  // The octant of |x|, rounded up to even (kept in int range: see above).
  F octant = floor(magnitude * 1.27323954473516f);
  auto in_range = octant < 16777216.0f;
  auto j = to_int(select(in_range, octant, splat<F>(0.0f)));
  j = j + (j & 1);
  F y = to_float(j);
  F z = ((magnitude - y * 0.78515625f) - y * 2.4187564849853515625e-4f) - y * 3.77489497744594108e-8f;
  if (cosine) j = j + 2;  // cos x = sin(x + pi/2)
  F zz = z * z;
  F cosine_polynomial =
      ((zz * 2.443315711809948e-5f - 1.388731625493765e-3f) * zz + 4.166664568298827e-2f) * zz * zz - zz * 0.5f +
      1.0f;
  F sine_polynomial = ((zz * -1.9515295891e-4f + 8.3321608736e-3f) * zz - 1.6666654611e-1f) * zz * z + z;
  F value = select((j & 2) != 0, cosine_polynomial, sine_polynomial);
  auto negative = (j & 4) != 0;
  if (!cosine) negative = differ(negative, x < 0.0f);  // sine is odd
  return select(in_range, select(negative, -value, value), magnitude * 0.0f);
}

template <class F>
F sine_of(F x) {
  return sine_or_cosine(x, false);
}

template <class F>
F cosine_of(F x) {
  return sine_or_cosine(x, true);
}

}  // namespace shadetree::semantics

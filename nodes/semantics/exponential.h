// exp, log and pow, written once over a lane type F so that both backends
// compute them with the same operations (see trigonometry.h for why libm
// will not do). exp and log follow Cephes' expf and logf (Moshier): range
// reduction by powers of two through the float's exponent bits, with ln 2
// split in two parts, then minimax polynomials; both are within about
// 2 ulp of libm. pow is exp(y log x) with libm's special cases; its
// relative error grows with |y log x| (up to about 2e-6 at |y log x| = 10).
#pragma once

#include "nodes/lane_scalar.h"

namespace shadetree::semantics {

using namespace shadetree::lanes;

// 2^n for integer n in [-126, 127], built from the exponent bits.
template <class I>
auto power_of_two(I n) {
  return from_bits((n + 127) << 23);
}

template <class F>
F exponential_of(F x) {
  // e^x = 2^n e^r with n = round(x / ln 2) and |r| <= ln 2 / 2.
  F n = floor(x * 1.44269504088896341f + 0.5f);
  F r = (x - n * 0.693359375f) - n * -2.12194440e-4f;
  F r2 = r * r;
  F p = (((((r * 1.9875691500e-4f + 1.3981999507e-3f) * r + 8.3334519073e-3f) * r + 4.1665795894e-2f) * r +
          1.6666665459e-1f) *
             r +
         5.0000001201e-1f) *
            r2 +
        r + 1.0f;
  // Scale by 2^n in two halves so that n = 128 and subnormal results work;
  // n is clamped first so that the int conversion stays defined.
  auto whole = to_int(min(max(n, splat<F>(-254.0f)), splat<F>(254.0f)));
  auto half = whole >> 1;
  F scaled = p * power_of_two(half) * power_of_two(whole - half);
  F result = select(x > 88.7228394f, splat<F>(__builtin_huge_valf()), scaled);
  result = select(x < -103.972076f, splat<F>(0.0f), result);
  return select(x != x, x, result);  // NaN stays NaN
}

template <class F>
F logarithm_of(F x) {
  // Subnormals are scaled into the normal range first (and 23 taken off).
  auto subnormal = both(x > 0.0f, x < 1.17549435e-38f);
  F normal = select(subnormal, x * 8388608.0f, x);
  auto bits = to_bits(normal);
  // x = m 2^e with m in [sqrt(1/2), sqrt(2)).
  auto exponent = ((bits >> 23) & 255) - 126;
  F m = from_bits((bits & 0x007fffff) | 0x3f000000);  // in [1/2, 1)
  auto low = m < 0.707106781186547524f;
  F e = to_float(exponent) - select(subnormal, splat<F>(23.0f), splat<F>(0.0f)) -
        select(low, splat<F>(1.0f), splat<F>(0.0f));
  m = select(low, m + m - 1.0f, m - 1.0f);
  F z = m * m;
  F y = ((((((((m * 7.0376836292e-2f - 1.1514610310e-1f) * m + 1.1676998740e-1f) * m - 1.2420140846e-1f) * m +
             1.4249322787e-1f) *
                m -
            1.6668057665e-1f) *
               m +
           2.0000714765e-1f) *
              m -
          2.4999993993e-1f) *
             m +
         3.3333331174e-1f) *
        m * z;
  y = y + e * -2.12194440e-4f;
  y = y - z * 0.5f;
  F result = m + y + e * 0.693359375f;
  result = select(x == 0.0f, splat<F>(-__builtin_huge_valf()), result);
  result = select(x < 0.0f, splat<F>(__builtin_nanf("")), result);
  return select(either(x == __builtin_huge_valf(), x != x), x, result);
}

// x^y with libm's special cases: x^0 = 1 (even for NaN x), x^1 = x,
// 0^y = 0 for y > 0 and +inf for y < 0, and a negative base only for
// integral y (its sign from y's parity), NaN otherwise.
template <class F>
F power_of(F x, F y) {
  F magnitude = exponential_of(y * logarithm_of(abs(x)));
  auto integral = floor(y) == y;
  auto odd = both(integral, y - floor(y * 0.5f) * 2.0f == 1.0f);
  F signed_result = select(odd, -magnitude, magnitude);
  F result = select(x < 0.0f, select(integral, signed_result, splat<F>(__builtin_nanf(""))), magnitude);
  result = select(y == 1.0f, x, result);
  return select(y == 0.0f, splat<F>(1.0f), result);
}

}  // namespace shadetree::semantics

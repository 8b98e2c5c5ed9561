// The textures of bench/scalar_yardsticks.cpp as a programmer fluent in
// AVX-512 intrinsics writes them: 16 samples per iteration, the last
// count % 16 through masked loads and stores, the noise tables read one of
// the header's two ways, the splines' 8 knots per colour component in one
// register (vpermps). The FMAs are written out: a yardstick need not round
// like the interpreter, as the JIT must.
//
// sin and pow are inline vector polynomials rather than a libm call per
// lane, as a programmer who has come this far writes them: marble's
// pow(unit, 3) is a cube, its sin Cephes' method by quadrant, and the
// turbulence graph's x^0.8 is 2^(0.8 log2 x) (power16 below).
//
// Every function that touches a zmm register has the avx512f target
// attribute, so that the file builds on any x86-64 host.
#include "bench/avx512_yardsticks.h"

// GCC 12 warns of the undefined source operand of its own intrinsics
// (GCC bug 105593); the warnings point into the header, so this hides them.
#pragma GCC diagnostic push
#if !defined(__clang__)
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <immintrin.h>
#pragma GCC diagnostic pop

#include "bench/yardstick_knots.h"
#include "nodes/noise_tables.h"

#define SHADETREE_AVX512 __attribute__((target("avx512f")))

namespace shadetree::yardstick {
namespace {

// Both graphs' octaves param at its default; the pixel size clamps it.
constexpr int turbulence_octaves = 8;

SHADETREE_AVX512 __m512 splat(float value) { return _mm512_set1_ps(value); }

SHADETREE_AVX512 __m512i splat_int(int value) { return _mm512_set1_epi32(value); }

SHADETREE_AVX512 __m512 floor16(__m512 x) { return _mm512_roundscale_ps(x, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC); }

SHADETREE_AVX512 __m512 clamp_unit16(__m512 x) { return _mm512_min_ps(_mm512_max_ps(x, splat(0.0f)), splat(1.0f)); }

// i mod 256, also for negative i.
SHADETREE_AVX512 __m512i wrap16(__m512i i) { return _mm512_and_si512(i, splat_int(255)); }

// The noise tables read by hardware gathers.
class GatheredTables {
 public:
  explicit GatheredTables(const NoiseTables& tables)
      : permutation_(tables.permutation.data()),
        gradient_{tables.hashed_gradient_x.data(), tables.hashed_gradient_y.data(),
                  tables.hashed_gradient_z.data()} {}

  SHADETREE_AVX512 __m512i permutation(__m512i index) const {
    return _mm512_i32gather_epi32(index, permutation_, 4);
  }
  SHADETREE_AVX512 __m512 gradient(int axis, __m512i slot) const {
    return _mm512_i32gather_ps(slot, gradient_[axis], 4);
  }

 private:
  const std::int32_t* permutation_;
  const float* gradient_[3];
};

// A 256-entry table in sixteen registers, 32 entries to a pair. The
// permutation is held as the bits of its ints: a permute moves bits.
struct RegisterTable {
  __m512 part[16];
};

SHADETREE_AVX512 RegisterTable load_register_table(const void* entries) {
  RegisterTable table;
  for (int p = 0; p < 16; ++p) table.part[p] = _mm512_loadu_ps(static_cast<const float*>(entries) + 16 * p);
  return table;
}

// vpermt2ps on the low 5 bits in each of the 8 pairs, then blends on bits
// 5, 6 and 7 halve the candidates three times.
SHADETREE_AVX512 __m512 look_up(const RegisterTable& table, __m512i index) {
  __m512 candidate[8];
  for (int p = 0; p < 8; ++p) candidate[p] = _mm512_permutex2var_ps(table.part[2 * p], index, table.part[2 * p + 1]);
  for (int bit = 5, count = 4; bit < 8; ++bit, count /= 2) {
    const __mmask16 high = _mm512_test_epi32_mask(index, splat_int(1 << bit));
    for (int p = 0; p < count; ++p)
      candidate[p] = _mm512_mask_blend_ps(high, candidate[2 * p], candidate[2 * p + 1]);
  }
  return candidate[0];
}

class RegisterTables {
 public:
  SHADETREE_AVX512 explicit RegisterTables(const NoiseTables& tables)
      : permutation_(load_register_table(tables.permutation.data())),
        gradient_{load_register_table(tables.hashed_gradient_x.data()),
                  load_register_table(tables.hashed_gradient_y.data()),
                  load_register_table(tables.hashed_gradient_z.data())} {}

  SHADETREE_AVX512 __m512i permutation(__m512i index) const {
    return _mm512_castps_si512(look_up(permutation_, index));
  }
  SHADETREE_AVX512 __m512 gradient(int axis, __m512i slot) const { return look_up(gradient_[axis], slot); }

 private:
  RegisterTable permutation_;
  RegisterTable gradient_[3];
};

// Perlin & Hoffert 1989 section 2.3: the drop-off 2|t|^3 - 3|t|^2 + 1.
SHADETREE_AVX512 __m512 weight16(__m512 t) {
  const __m512 a = _mm512_abs_ps(t);
  return _mm512_fmadd_ps(_mm512_mul_ps(_mm512_fmadd_ps(a, splat(2.0f), splat(-3.0f)), a), a, splat(1.0f));
}

// 1989 section 2.3 over 16 points: knot (i, j, k) has the gradient
// hashed_gradient[(i + phi(j + phi(k))) mod 256].
template <class Tables>
SHADETREE_AVX512 __m512 noise16(const Tables& tables, __m512 x, __m512 y, __m512 z) {
  const __m512 point[3] = {x, y, z};
  __m512i cell[3];
  __m512 offset[3][2], weight[3][2];
  for (int axis = 0; axis < 3; ++axis) {
    const __m512 corner = floor16(point[axis]);
    cell[axis] = _mm512_cvttps_epi32(corner);
    for (int d = 0; d < 2; ++d) {
      offset[axis][d] = _mm512_sub_ps(_mm512_sub_ps(point[axis], corner), splat(static_cast<float>(d)));
      weight[axis][d] = weight16(offset[axis][d]);
    }
  }
  __m512 sum = _mm512_setzero_ps();
  // The eight knots written out, as SIMD noise libraries write them: GCC
  // keeps these loops rolled otherwise, and turbulence over the tables in
  // registers runs about 15% slower.
#pragma GCC unroll 2
  for (int k = 0; k < 2; ++k) {
    const __m512i hash_k = tables.permutation(wrap16(_mm512_add_epi32(cell[2], splat_int(k))));
#pragma GCC unroll 2
    for (int j = 0; j < 2; ++j) {
      const __m512i hash_jk =
          tables.permutation(wrap16(_mm512_add_epi32(_mm512_add_epi32(cell[1], splat_int(j)), hash_k)));
      for (int i = 0; i < 2; ++i) {
        const __m512i slot = wrap16(_mm512_add_epi32(_mm512_add_epi32(cell[0], splat_int(i)), hash_jk));
        const __m512 slope = _mm512_fmadd_ps(
            tables.gradient(0, slot), offset[0][i],
            _mm512_fmadd_ps(tables.gradient(1, slot), offset[1][j],
                            _mm512_mul_ps(tables.gradient(2, slot), offset[2][k])));
        sum = _mm512_fmadd_ps(_mm512_mul_ps(_mm512_mul_ps(weight[0][i], weight[1][j]), weight[2][k]), slope, sum);
      }
    }
  }
  return sum;
}

// The 1985 appendix: octaves while the scale is above the pixel size; the
// loop ends when no lane has one left.
template <class Tables>
SHADETREE_AVX512 __m512 turbulence16(const Tables& tables, __m512 x, __m512 y, __m512 z, __m512 pixel_size) {
  __m512 sum = _mm512_setzero_ps();
  float scale = 1.0f;
  for (int octave = 0; octave < turbulence_octaves; ++octave, scale *= 0.5f) {
    const __mmask16 active = _mm512_cmp_ps_mask(pixel_size, splat(scale), _CMP_LT_OQ);
    if (active == 0) break;
    const __m512 frequency = splat(1.0f / scale);
    const __m512 octave_noise =
        noise16(tables, _mm512_mul_ps(x, frequency), _mm512_mul_ps(y, frequency), _mm512_mul_ps(z, frequency));
    sum = _mm512_mask3_fmadd_ps(_mm512_abs_ps(octave_noise), splat(scale), sum, active);
  }
  return sum;
}

// sin by Cephes' sinf method: the quadrant q = round(2x / pi), r = x - q
// pi/2 with pi/2 in three parts (Cody-Waite), the sine or cosine
// polynomial on r by q's parity, the sign by q's bit 1. A few ulp while
// |x| is in the thousands; marble's |x| stays under 40.
SHADETREE_AVX512 __m512 sine16(__m512 x) {
  const __m512 quadrant =
      _mm512_roundscale_ps(_mm512_mul_ps(x, splat(0.636619772f)), _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
  __m512 r = _mm512_fnmadd_ps(quadrant, splat(1.5703125f), x);
  r = _mm512_fnmadd_ps(quadrant, splat(4.837512969970703125e-4f), r);
  r = _mm512_fnmadd_ps(quadrant, splat(7.54978995489188216e-8f), r);
  const __m512 r2 = _mm512_mul_ps(r, r);
  const __m512 sine = _mm512_fmadd_ps(
      _mm512_fmadd_ps(_mm512_fmadd_ps(r2, splat(-1.9515295891e-4f), splat(8.3321608736e-3f)), r2,
                      splat(-1.6666654611e-1f)),
      _mm512_mul_ps(r2, r), r);
  const __m512 cosine = _mm512_fmadd_ps(
      _mm512_fmadd_ps(_mm512_fmadd_ps(r2, splat(2.443315711809948e-5f), splat(-1.388731625493765e-3f)), r2,
                      splat(4.166664568298827e-2f)),
      _mm512_mul_ps(r2, r2), _mm512_fnmadd_ps(r2, splat(0.5f), splat(1.0f)));
  const __m512i q = _mm512_cvtps_epi32(quadrant);
  const __m512 value = _mm512_mask_blend_ps(_mm512_test_epi32_mask(q, splat_int(1)), sine, cosine);
  return _mm512_mask_sub_ps(value, _mm512_test_epi32_mask(q, splat_int(2)), _mm512_setzero_ps(), value);
}

// x^exponent for x in [0, 1] as 2^(exponent log2 x). getmant and getexp
// split x = m 2^e with m in [0.75, 1.5); ln m = 2 atanh(s) with
// s = (m - 1) / (m + 1) in [-1/7, 1/5], by its odd series to s^9; then
// 2^y = 2^n 2^r with n = round(y), 2^r by Cephes' exp2f polynomial on
// [-1/2, 1/2] and the 2^n by scalef. 0 stays 0.
SHADETREE_AVX512 __m512 power16(__m512 x, float exponent) {
  const __m512 m = _mm512_getmant_ps(x, _MM_MANT_NORM_p75_1p5, _MM_MANT_SIGN_zero);
  __m512 e = _mm512_getexp_ps(x);  // of the mantissa in [1, 2): one more where m < 1
  e = _mm512_mask_add_ps(e, _mm512_cmp_ps_mask(m, splat(1.0f), _CMP_LT_OQ), e, splat(1.0f));
  const __m512 s = _mm512_div_ps(_mm512_sub_ps(m, splat(1.0f)), _mm512_add_ps(m, splat(1.0f)));
  const __m512 s2 = _mm512_mul_ps(s, s);
  __m512 series = _mm512_fmadd_ps(s2, splat(1.0f / 9.0f), splat(1.0f / 7.0f));
  series = _mm512_fmadd_ps(series, s2, splat(1.0f / 5.0f));
  series = _mm512_fmadd_ps(series, s2, splat(1.0f / 3.0f));
  const __m512 ln_m = _mm512_mul_ps(_mm512_fmadd_ps(_mm512_mul_ps(series, s2), s, s), splat(2.0f));
  const __m512 y = _mm512_mul_ps(_mm512_fmadd_ps(ln_m, splat(1.44269504088896341f), e), splat(exponent));
  const __m512 n = _mm512_roundscale_ps(y, _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
  const __m512 r = _mm512_sub_ps(y, n);
  __m512 p = _mm512_fmadd_ps(r, splat(1.535336188319500e-4f), splat(1.339887440266574e-3f));
  p = _mm512_fmadd_ps(p, r, splat(9.618437357674640e-3f));
  p = _mm512_fmadd_ps(p, r, splat(5.550332471162809e-2f));
  p = _mm512_fmadd_ps(p, r, splat(2.402264791363012e-1f));
  p = _mm512_fmadd_ps(p, r, splat(6.931472028550421e-1f));
  p = _mm512_fmadd_ps(p, r, splat(1.0f));
  return _mm512_maskz_mov_ps(_mm512_cmp_ps_mask(x, _mm512_setzero_ps(), _CMP_GT_OQ), _mm512_scalef_ps(p, n));
}

struct Colour16 {
  __m512 red, green, blue;
};

// Perlin 1985's spline(): Catmull-Rom through knots 1..6 over x in [0,1].
SHADETREE_AVX512 Colour16 catmull_rom16(const SplineKnots& knots, __m512 x) {
  const __m512 t = _mm512_mul_ps(clamp_unit16(x), splat(5.0f));
  const __m512 segment = _mm512_min_ps(floor16(t), splat(4.0f));
  const __m512 f = _mm512_sub_ps(t, segment), f2 = _mm512_mul_ps(f, f), f3 = _mm512_mul_ps(f2, f);
  const __m512 basis[4] = {
      _mm512_sub_ps(_mm512_fmsub_ps(f2, splat(2.0f), f3), f),
      _mm512_fmadd_ps(f3, splat(3.0f), _mm512_fnmadd_ps(f2, splat(5.0f), splat(2.0f))),
      _mm512_add_ps(_mm512_fnmadd_ps(f3, splat(3.0f), _mm512_mul_ps(f2, splat(4.0f))), f),
      _mm512_sub_ps(f3, f2)};
  const __m512i index = _mm512_cvttps_epi32(segment);
  __m512 channel[3];
  for (int c = 0; c < 3; ++c) {
    const __m512 component = _mm512_loadu_ps(knots.component[c]);
    __m512 sum = _mm512_setzero_ps();
    for (int k = 0; k < 4; ++k)
      sum = _mm512_fmadd_ps(basis[k], _mm512_permutexvar_ps(_mm512_add_epi32(index, splat_int(k)), component), sum);
    channel[c] = _mm512_mul_ps(sum, splat(0.5f));
  }
  return {channel[0], channel[1], channel[2]};
}

// The three graphs at their default params over 16 samples.
template <class Tables>
struct NoiseTexture {
  const Tables& tables;

  SHADETREE_AVX512 Colour16 operator()(__m512 x, __m512 y, __m512 z, __m512) const {
    const __m512 eight = splat(8.0f);
    const __m512 noise = noise16(tables, _mm512_mul_ps(x, eight), _mm512_mul_ps(y, eight), _mm512_mul_ps(z, eight));
    const __m512 grey = _mm512_mul_ps(_mm512_add_ps(noise, splat(1.0f)), splat(0.5f));
    return {grey, grey, grey};
  }
};

template <class Tables>
struct TurbulenceTexture {
  const Tables& tables;

  SHADETREE_AVX512 Colour16 operator()(__m512 x, __m512 y, __m512 z, __m512 filter_width) const {
    const __m512 scale = splat(4.0f);
    const __m512 sum = turbulence16(tables, _mm512_mul_ps(x, scale), _mm512_mul_ps(y, scale),
                                    _mm512_mul_ps(z, scale), _mm512_mul_ps(filter_width, scale));
    const __m512 unit = clamp_unit16(_mm512_mul_ps(sum, splat(1.0f / 0.7f)));
    return catmull_rom16(turbulence_knots, power16(unit, 0.8f));
  }
};

template <class Tables>
struct MarbleTexture {
  const Tables& tables;

  SHADETREE_AVX512 Colour16 operator()(__m512 x, __m512 y, __m512 z, __m512 filter_width) const {
    const __m512 sum = turbulence16(tables, x, y, z, filter_width);
    const __m512 layers = sine16(_mm512_fmadd_ps(sum, splat(7.0f), _mm512_mul_ps(x, splat(6.0f))));
    const __m512 unit = _mm512_mul_ps(_mm512_add_ps(layers, splat(1.0f)), splat(0.5f));
    return catmull_rom16(marble_knots, _mm512_mul_ps(_mm512_mul_ps(unit, unit), unit));
  }
};

template <template <class> class Texture, class Tables>
SHADETREE_AVX512 void shade_planes(const float* x, const float* y, const float* z, const float* filter_width,
                                   float* red, float* green, float* blue, std::size_t count) {
  const Tables tables(noise_tables(default_noise_seed));
  const Texture<Tables> texture{tables};
  for (std::size_t i = 0; i < count; i += 16) {
    const __mmask16 lanes = count - i >= 16 ? 0xffff : static_cast<__mmask16>((1u << (count - i)) - 1);
    const Colour16 colour = texture(_mm512_maskz_loadu_ps(lanes, x + i), _mm512_maskz_loadu_ps(lanes, y + i),
                                    _mm512_maskz_loadu_ps(lanes, z + i), _mm512_maskz_loadu_ps(lanes, filter_width + i));
    _mm512_mask_storeu_ps(red + i, lanes, colour.red);
    _mm512_mask_storeu_ps(green + i, lanes, colour.green);
    _mm512_mask_storeu_ps(blue + i, lanes, colour.blue);
  }
}

}  // namespace

bool host_has_avx512() { return __builtin_cpu_supports("avx512f"); }

PlaneKernel* const avx512_gathers::noise = shade_planes<NoiseTexture, GatheredTables>;
PlaneKernel* const avx512_gathers::turbulence = shade_planes<TurbulenceTexture, GatheredTables>;
PlaneKernel* const avx512_gathers::marble = shade_planes<MarbleTexture, GatheredTables>;

PlaneKernel* const avx512_in_register::noise = shade_planes<NoiseTexture, RegisterTables>;
PlaneKernel* const avx512_in_register::turbulence = shade_planes<TurbulenceTexture, RegisterTables>;
PlaneKernel* const avx512_in_register::marble = shade_planes<MarbleTexture, RegisterTables>;

}  // namespace shadetree::yardstick

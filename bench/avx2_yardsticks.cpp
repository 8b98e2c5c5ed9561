// The textures of bench/scalar_yardsticks.cpp as a programmer fluent in
// AVX2 intrinsics writes them for hosts without AVX-512: 8 samples per
// iteration, the last count % 8 through masked loads and stores, the
// splines' 8 knots per colour component in one register (vpermps), the
// FMAs written out, sin and pow as the inline polynomials of
// bench/avx512_yardsticks.cpp. A knot row's six gradient components are
// read one of two ways: six hardware gathers, or, from the interleaved
// table (x, y, z and a 4D w that 3D noise ignores, per entry), two 16-byte
// loads per lane and a 4x4 transpose within each 128-bit half.
//
// Every function that touches a ymm register has the avx2 and fma target
// attribute, so that the file builds on any x86-64 host.
#include "bench/avx2_yardsticks.h"

#include <immintrin.h>

#include <cstdint>

#include "bench/yardstick_knots.h"
#include "nodes/noise_tables.h"

#define SHADETREE_AVX2 __attribute__((target("avx2,fma")))

namespace shadetree::yardstick {
namespace {

// Both graphs' octaves param at its default; the pixel size clamps it.
constexpr int turbulence_octaves = 8;

SHADETREE_AVX2 __m256 splat(float value) { return _mm256_set1_ps(value); }

SHADETREE_AVX2 __m256i splat_int(int value) { return _mm256_set1_epi32(value); }

SHADETREE_AVX2 __m256 abs8(__m256 x) { return _mm256_andnot_ps(splat(-0.0f), x); }

SHADETREE_AVX2 __m256 clamp_unit8(__m256 x) { return _mm256_min_ps(_mm256_max_ps(x, _mm256_setzero_ps()), splat(1.0f)); }

// i mod 256, also for negative i.
SHADETREE_AVX2 __m256i wrap8(__m256i i) { return _mm256_and_si256(i, splat_int(255)); }

// A knot row's gradients: x, y and z at slot and at slot + 1.
struct RowGradients {
  __m256 x[2], y[2], z[2];
};

// The permutation by hardware gathers, as both yardsticks read it.
class GatheredPermutation {
 public:
  explicit GatheredPermutation(const NoiseTables& tables) : tables_(tables) {}

  SHADETREE_AVX2 __m256i permutation(__m256i index) const {
    return _mm256_i32gather_epi32(tables_.permutation.data(), index, 4);
  }

 protected:
  const NoiseTables& tables_;
};

// The gradients by hardware gathers too; slot + 1 needs no wrap, the
// tables repeating entry 0 after the last.
class GatheredTables : public GatheredPermutation {
 public:
  using GatheredPermutation::GatheredPermutation;

  SHADETREE_AVX2 RowGradients gradients(__m256i slot) const {
    RowGradients row;
    for (int i = 0; i < 2; ++i) {
      const __m256i at = _mm256_add_epi32(slot, splat_int(i));
      row.x[i] = _mm256_i32gather_ps(tables_.hashed_gradient_x.data(), at, 4);
      row.y[i] = _mm256_i32gather_ps(tables_.hashed_gradient_y.data(), at, 4);
      row.z[i] = _mm256_i32gather_ps(tables_.hashed_gradient_z.data(), at, 4);
    }
    return row;
  }
};

// The gradients from the interleaved table: lanes l and l + 4 loaded side
// by side, four such registers transposed within each half.
class InterleavedTables : public GatheredPermutation {
 public:
  using GatheredPermutation::GatheredPermutation;

  SHADETREE_AVX2 RowGradients gradients(__m256i slot) const {
    alignas(32) std::int32_t slots[8];
    _mm256_store_si256(reinterpret_cast<__m256i*>(slots), slot);
    const float* entries = tables_.hashed_gradient_xyzw.data();
    RowGradients row;
    for (int i = 0; i < 2; ++i) {
      __m256 lanes[4];
      for (int l = 0; l < 4; ++l)
        lanes[l] = _mm256_loadu2_m128(entries + 4 * (slots[l + 4] + i), entries + 4 * (slots[l] + i));
      const __m256 xy01 = _mm256_unpacklo_ps(lanes[0], lanes[1]), xy23 = _mm256_unpacklo_ps(lanes[2], lanes[3]);
      const __m256 z01 = _mm256_unpackhi_ps(lanes[0], lanes[1]), z23 = _mm256_unpackhi_ps(lanes[2], lanes[3]);
      row.x[i] = _mm256_castpd_ps(_mm256_unpacklo_pd(_mm256_castps_pd(xy01), _mm256_castps_pd(xy23)));
      row.y[i] = _mm256_castpd_ps(_mm256_unpackhi_pd(_mm256_castps_pd(xy01), _mm256_castps_pd(xy23)));
      row.z[i] = _mm256_castpd_ps(_mm256_unpacklo_pd(_mm256_castps_pd(z01), _mm256_castps_pd(z23)));
    }
    return row;
  }
};

// Perlin & Hoffert 1989 section 2.3: the drop-off 2|t|^3 - 3|t|^2 + 1.
SHADETREE_AVX2 __m256 weight8(__m256 t) {
  const __m256 a = abs8(t);
  return _mm256_fmadd_ps(_mm256_mul_ps(_mm256_fmadd_ps(a, splat(2.0f), splat(-3.0f)), a), a, splat(1.0f));
}

// 1989 section 2.3 over 8 points: knot (i, j, k) has the gradient
// hashed_gradient[(i + phi(j + phi(k))) mod 256], a row along i at a time.
template <class Tables>
SHADETREE_AVX2 __m256 noise8(const Tables& tables, __m256 x, __m256 y, __m256 z) {
  const __m256 point[3] = {x, y, z};
  __m256i cell[3];
  __m256 offset[3][2], weight[3][2];
  for (int axis = 0; axis < 3; ++axis) {
    const __m256 corner = _mm256_floor_ps(point[axis]);
    cell[axis] = _mm256_cvttps_epi32(corner);
    for (int d = 0; d < 2; ++d) {
      offset[axis][d] = _mm256_sub_ps(_mm256_sub_ps(point[axis], corner), splat(static_cast<float>(d)));
      weight[axis][d] = weight8(offset[axis][d]);
    }
  }
  __m256 sum = _mm256_setzero_ps();
#pragma GCC unroll 2
  for (int k = 0; k < 2; ++k) {
    const __m256i hash_k = tables.permutation(wrap8(_mm256_add_epi32(cell[2], splat_int(k))));
#pragma GCC unroll 2
    for (int j = 0; j < 2; ++j) {
      const __m256i hash_jk =
          tables.permutation(wrap8(_mm256_add_epi32(_mm256_add_epi32(cell[1], splat_int(j)), hash_k)));
      const RowGradients row = tables.gradients(wrap8(_mm256_add_epi32(cell[0], hash_jk)));
      for (int i = 0; i < 2; ++i) {
        const __m256 slope = _mm256_fmadd_ps(
            row.x[i], offset[0][i],
            _mm256_fmadd_ps(row.y[i], offset[1][j], _mm256_mul_ps(row.z[i], offset[2][k])));
        sum = _mm256_fmadd_ps(_mm256_mul_ps(_mm256_mul_ps(weight[0][i], weight[1][j]), weight[2][k]), slope, sum);
      }
    }
  }
  return sum;
}

// The 1985 appendix: octaves while the scale is above the pixel size; the
// loop ends when no lane has one left.
template <class Tables>
SHADETREE_AVX2 __m256 turbulence8(const Tables& tables, __m256 x, __m256 y, __m256 z, __m256 pixel_size) {
  __m256 sum = _mm256_setzero_ps();
  float scale = 1.0f;
  for (int octave = 0; octave < turbulence_octaves; ++octave, scale *= 0.5f) {
    const __m256 active = _mm256_cmp_ps(pixel_size, splat(scale), _CMP_LT_OQ);
    if (_mm256_movemask_ps(active) == 0) break;
    const __m256 frequency = splat(1.0f / scale);
    const __m256 octave_noise =
        noise8(tables, _mm256_mul_ps(x, frequency), _mm256_mul_ps(y, frequency), _mm256_mul_ps(z, frequency));
    sum = _mm256_add_ps(sum, _mm256_and_ps(active, _mm256_mul_ps(abs8(octave_noise), splat(scale))));
  }
  return sum;
}

// sin by Cephes' sinf method, as sine16 in bench/avx512_yardsticks.cpp:
// the quadrant q = round(2x / pi), r = x - q pi/2 in three parts, the sine
// or cosine polynomial by q's parity, the sign by q's bit 1.
SHADETREE_AVX2 __m256 sine8(__m256 x) {
  const __m256 quadrant =
      _mm256_round_ps(_mm256_mul_ps(x, splat(0.636619772f)), _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
  __m256 r = _mm256_fnmadd_ps(quadrant, splat(1.5703125f), x);
  r = _mm256_fnmadd_ps(quadrant, splat(4.837512969970703125e-4f), r);
  r = _mm256_fnmadd_ps(quadrant, splat(7.54978995489188216e-8f), r);
  const __m256 r2 = _mm256_mul_ps(r, r);
  const __m256 sine = _mm256_fmadd_ps(
      _mm256_fmadd_ps(_mm256_fmadd_ps(r2, splat(-1.9515295891e-4f), splat(8.3321608736e-3f)), r2,
                      splat(-1.6666654611e-1f)),
      _mm256_mul_ps(r2, r), r);
  const __m256 cosine = _mm256_fmadd_ps(
      _mm256_fmadd_ps(_mm256_fmadd_ps(r2, splat(2.443315711809948e-5f), splat(-1.388731625493765e-3f)), r2,
                      splat(4.166664568298827e-2f)),
      _mm256_mul_ps(r2, r2), _mm256_fnmadd_ps(r2, splat(0.5f), splat(1.0f)));
  const __m256i q = _mm256_cvtps_epi32(quadrant);
  const __m256 odd = _mm256_castsi256_ps(_mm256_cmpeq_epi32(_mm256_and_si256(q, splat_int(1)), splat_int(1)));
  const __m256 value = _mm256_blendv_ps(sine, cosine, odd);
  const __m256 sign = _mm256_castsi256_ps(_mm256_slli_epi32(_mm256_and_si256(q, splat_int(2)), 30));
  return _mm256_xor_ps(value, sign);
}

// x^exponent for x in [0, 1] as 2^(exponent log2 x), as power16 in
// bench/avx512_yardsticks.cpp, with the exponent and mantissa split by
// bits: x = m 2^e with m in [0.75, 1.5), ln m = 2 atanh((m - 1) / (m + 1))
// by its odd series, 2^r by Cephes' exp2f polynomial, and 2^n built in
// the exponent field. 0 stays 0; x is never subnormal here.
SHADETREE_AVX2 __m256 power8(__m256 x, float exponent) {
  const __m256i bits = _mm256_castps_si256(x);
  __m256 e = _mm256_cvtepi32_ps(_mm256_sub_epi32(_mm256_srli_epi32(bits, 23), splat_int(127)));
  __m256 m = _mm256_castsi256_ps(
      _mm256_or_si256(_mm256_and_si256(bits, splat_int(0x007fffff)), splat_int(0x3f800000)));  // [1, 2)
  const __m256 high = _mm256_cmp_ps(m, splat(1.5f), _CMP_GE_OQ);
  m = _mm256_blendv_ps(m, _mm256_mul_ps(m, splat(0.5f)), high);
  e = _mm256_add_ps(e, _mm256_and_ps(high, splat(1.0f)));
  const __m256 s = _mm256_div_ps(_mm256_sub_ps(m, splat(1.0f)), _mm256_add_ps(m, splat(1.0f)));
  const __m256 s2 = _mm256_mul_ps(s, s);
  __m256 series = _mm256_fmadd_ps(s2, splat(1.0f / 9.0f), splat(1.0f / 7.0f));
  series = _mm256_fmadd_ps(series, s2, splat(1.0f / 5.0f));
  series = _mm256_fmadd_ps(series, s2, splat(1.0f / 3.0f));
  const __m256 ln_m = _mm256_mul_ps(_mm256_fmadd_ps(_mm256_mul_ps(series, s2), s, s), splat(2.0f));
  const __m256 y = _mm256_mul_ps(_mm256_fmadd_ps(ln_m, splat(1.44269504088896341f), e), splat(exponent));
  const __m256 n = _mm256_round_ps(y, _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
  const __m256 r = _mm256_sub_ps(y, n);
  __m256 p = _mm256_fmadd_ps(r, splat(1.535336188319500e-4f), splat(1.339887440266574e-3f));
  p = _mm256_fmadd_ps(p, r, splat(9.618437357674640e-3f));
  p = _mm256_fmadd_ps(p, r, splat(5.550332471162809e-2f));
  p = _mm256_fmadd_ps(p, r, splat(2.402264791363012e-1f));
  p = _mm256_fmadd_ps(p, r, splat(6.931472028550421e-1f));
  p = _mm256_fmadd_ps(p, r, splat(1.0f));
  const __m256 two_to_n =
      _mm256_castsi256_ps(_mm256_slli_epi32(_mm256_add_epi32(_mm256_cvtps_epi32(n), splat_int(127)), 23));
  return _mm256_and_ps(_mm256_cmp_ps(x, _mm256_setzero_ps(), _CMP_GT_OQ), _mm256_mul_ps(p, two_to_n));
}

struct Colour8 {
  __m256 red, green, blue;
};

// Perlin 1985's spline(): Catmull-Rom through knots 1..6 over x in [0,1].
SHADETREE_AVX2 Colour8 catmull_rom8(const SplineKnots& knots, __m256 x) {
  const __m256 t = _mm256_mul_ps(clamp_unit8(x), splat(5.0f));
  const __m256 segment = _mm256_min_ps(_mm256_floor_ps(t), splat(4.0f));
  const __m256 f = _mm256_sub_ps(t, segment), f2 = _mm256_mul_ps(f, f), f3 = _mm256_mul_ps(f2, f);
  const __m256 basis[4] = {
      _mm256_sub_ps(_mm256_fmsub_ps(f2, splat(2.0f), f3), f),
      _mm256_fmadd_ps(f3, splat(3.0f), _mm256_fnmadd_ps(f2, splat(5.0f), splat(2.0f))),
      _mm256_add_ps(_mm256_fnmadd_ps(f3, splat(3.0f), _mm256_mul_ps(f2, splat(4.0f))), f),
      _mm256_sub_ps(f3, f2)};
  const __m256i index = _mm256_cvttps_epi32(segment);
  __m256 channel[3];
  for (int c = 0; c < 3; ++c) {
    const __m256 component = _mm256_loadu_ps(knots.component[c]);
    __m256 sum = _mm256_setzero_ps();
    for (int k = 0; k < 4; ++k)
      sum = _mm256_fmadd_ps(basis[k], _mm256_permutevar8x32_ps(component, _mm256_add_epi32(index, splat_int(k))), sum);
    channel[c] = _mm256_mul_ps(sum, splat(0.5f));
  }
  return {channel[0], channel[1], channel[2]};
}

// The three graphs at their default params over 8 samples.
template <class Tables>
struct NoiseTexture {
  const Tables& tables;

  SHADETREE_AVX2 Colour8 operator()(__m256 x, __m256 y, __m256 z, __m256) const {
    const __m256 eight = splat(8.0f);
    const __m256 noise = noise8(tables, _mm256_mul_ps(x, eight), _mm256_mul_ps(y, eight), _mm256_mul_ps(z, eight));
    const __m256 grey = _mm256_mul_ps(_mm256_add_ps(noise, splat(1.0f)), splat(0.5f));
    return {grey, grey, grey};
  }
};

template <class Tables>
struct TurbulenceTexture {
  const Tables& tables;

  SHADETREE_AVX2 Colour8 operator()(__m256 x, __m256 y, __m256 z, __m256 filter_width) const {
    const __m256 scale = splat(4.0f);
    const __m256 sum = turbulence8(tables, _mm256_mul_ps(x, scale), _mm256_mul_ps(y, scale), _mm256_mul_ps(z, scale),
                                   _mm256_mul_ps(filter_width, scale));
    const __m256 unit = clamp_unit8(_mm256_mul_ps(sum, splat(1.0f / 0.7f)));
    return catmull_rom8(turbulence_knots, power8(unit, 0.8f));
  }
};

template <class Tables>
struct MarbleTexture {
  const Tables& tables;

  SHADETREE_AVX2 Colour8 operator()(__m256 x, __m256 y, __m256 z, __m256 filter_width) const {
    const __m256 sum = turbulence8(tables, x, y, z, filter_width);
    const __m256 layers = sine8(_mm256_fmadd_ps(sum, splat(7.0f), _mm256_mul_ps(x, splat(6.0f))));
    const __m256 unit = _mm256_mul_ps(_mm256_add_ps(layers, splat(1.0f)), splat(0.5f));
    return catmull_rom8(marble_knots, _mm256_mul_ps(_mm256_mul_ps(unit, unit), unit));
  }
};

template <template <class> class Texture, class Tables>
SHADETREE_AVX2 void shade_planes(const float* x, const float* y, const float* z, const float* filter_width,
                                 float* red, float* green, float* blue, std::size_t count) {
  const Tables tables(noise_tables(default_noise_seed));
  const Texture<Tables> texture{tables};
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  for (std::size_t i = 0; i < count; i += 8) {
    const int left = count - i >= 8 ? 8 : static_cast<int>(count - i);
    const __m256i lanes = _mm256_cmpgt_epi32(splat_int(left), lane);
    const Colour8 colour = texture(_mm256_maskload_ps(x + i, lanes), _mm256_maskload_ps(y + i, lanes),
                                   _mm256_maskload_ps(z + i, lanes), _mm256_maskload_ps(filter_width + i, lanes));
    _mm256_maskstore_ps(red + i, lanes, colour.red);
    _mm256_maskstore_ps(green + i, lanes, colour.green);
    _mm256_maskstore_ps(blue + i, lanes, colour.blue);
  }
}

}  // namespace

bool host_has_avx2() { return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"); }

PlaneKernel* const avx2_gathers::noise = shade_planes<NoiseTexture, GatheredTables>;
PlaneKernel* const avx2_gathers::turbulence = shade_planes<TurbulenceTexture, GatheredTables>;
PlaneKernel* const avx2_gathers::marble = shade_planes<MarbleTexture, GatheredTables>;

PlaneKernel* const avx2_interleaved::noise = shade_planes<NoiseTexture, InterleavedTables>;
PlaneKernel* const avx2_interleaved::turbulence = shade_planes<TurbulenceTexture, InterleavedTables>;
PlaneKernel* const avx2_interleaved::marble = shade_planes<MarbleTexture, InterleavedTables>;

}  // namespace shadetree::yardstick

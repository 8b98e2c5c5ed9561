// Noise generators, written once over a lane type F (see nodes/lane_scalar.h).
#pragma once

#include <type_traits>
#include <utility>

#include "nodes/improved_noise_permutation.h"
#include "nodes/lane_scalar.h"
#include "nodes/limits.h"
#include "nodes/noise_tables.h"
#include "nodes/semantics/vec3.h"

namespace shadetree::semantics {

using namespace shadetree::lanes;

// Perlin & Hoffert 1989 section 2.3: the drop-off 2|t|^3 - 3|t|^2 + 1.
template <class F>
F noise_weight(F t) {
  F a = abs(t);
  return (a * 2.0f - 3.0f) * a * a + 1.0f;
}

// d/dt of noise_weight: 6 t |t| - 6 t.
template <class F>
F noise_weight_derivative(F t) {
  return t * (abs(t) - 1.0f) * 6.0f;
}

// phi(i) = P[i mod n]; n = 256 so the mod is a mask (also for negative i).
template <class I>
I noise_phi(const NoiseTables& tables, I i) {
  return gather256(tables.permutation.data(), i & (noise_table_size - 1));
}

// The lattice cell of a coordinate: floor(x) for the offsets, and floor(x)
// mod n as an integer for the hash. A cell within int32 converts exactly,
// and n being a power of two, the low bits of its two's complement are the
// mod. Cells from 2^31 on are multiples of 256, hence 0 mod n, as are
// those from -2^31 down; so the conversion is kept defined by clamping to
// [-2^31, the largest float below 2^31], and a cell of 2^31 or more (or
// NaN, or an infinity: cell 0) takes 0 instead of its clamped value.
template <class F>
struct LatticeCoordinate {
  F cell;               // floor(x)
  IntOf<F> hash_index;  // floor(x) mod n, in [0, n)
};

template <class F>
LatticeCoordinate<F> lattice_coordinate(F x) {
  F cell = floor(x);
  F convertible = min(max(cell, splat<F>(-2147483648.0f)), splat<F>(2147483520.0f));  // -2^31, 2^31 - 128
  return {cell, select(cell < 2147483648.0f, to_int(convertible) & (noise_table_size - 1), IntOf<F>{} + 0)};
}

// One axis of the lattice: a coordinate's cell, and the hash index of the
// cell d cells on (phi and the slot reduce it mod n).
template <class F>
struct LatticeAxis {
  static constexpr bool next_cell_hashes_next = true;  // index(1) = index(0) + 1
  LatticeCoordinate<F> at;
  F corner() const { return at.cell; }
  IntOf<F> index(int d) const { return at.hash_index + d; }
};

// Periods of the periodic ops: rounded to a whole number of cells, from 1
// to max_noise_period, so that cell c and cell c + period hash alike.
inline constexpr float max_noise_period = 256.0f;

template <class F>
F noise_period(F period) {
  return min(max(floor(period + 0.5f), splat<F>(1.0f)), splat<F>(max_noise_period));
}

// An axis of a lattice that repeats every `period` cells (OSL's pnoise):
// cell c hashes as c mod period, reduced in float (exact for cells below
// 2^24, which covers 16 octaves of the largest period), then mod n.
template <class F>
struct PeriodicAxis {
  static constexpr bool next_cell_hashes_next = false;  // the last cell of a period wraps to 0
  F cell;    // floor(x)
  F period;  // whole, >= 1
  F corner() const { return cell; }
  IntOf<F> index(int d) const {
    F c = cell + float(d);
    F wrapped = c - floor(c / period) * period;
    wrapped = select(wrapped < 0.0f, wrapped + period, wrapped);
    wrapped = select(wrapped >= period, wrapped - period, wrapped);
    wrapped = select(both(wrapped >= 0.0f, wrapped < period), wrapped, splat<F>(0.0f));  // NaN, infinities
    return to_int(wrapped - floor(wrapped * (1.0f / noise_table_size)) * float(noise_table_size));
  }
};

template <class F>
LatticeAxis<F> lattice_axis(F x) {
  return {lattice_coordinate(x)};
}

template <class F>
PeriodicAxis<F> periodic_axis(F x, F period) {
  return {floor(x), period};
}

// A noise table's entries at the slots (axis.index(d) + hash) mod n of a
// pair of neighbouring cells, d = 0 and 1. Where the axis hashes cell
// c + 1 as cell c's index plus one, the second slot is the first plus one
// (mod n), and both entries are one paired lookup (gather256_pair:
// adjacent in memory, so one 64-bit load per lane); a periodic axis,
// whose last cell wraps to the first, reads them apart.
template <class Axis, class I>
I cell_slot(const Axis& axis, I hash, int d) {
  return (axis.index(d) + hash) & (noise_table_size - 1);
}

template <class T, class Axis, class I>
auto entries_at_cells(const T* table, const Axis& axis, I hash) {
  if constexpr (Axis::next_cell_hashes_next) {
    return gather256_pair(table, cell_slot(axis, hash, 0));
  } else {
    return std::array<decltype(gather256(table, hash)), 2>{gather256(table, cell_slot(axis, hash, 0)),
                                                           gather256(table, cell_slot(axis, hash, 1))};
  }
}

// Whether lanes of index type I look up the gradients of a cell's four
// rows of knots in one go (gather256_knot_rows, which only
// nodes/lane_vector.h declares).
template <class I, class = void>
struct LooksUpKnotRows : std::false_type {};
template <class I>
struct LooksUpKnotRows<I, std::void_t<decltype(gather256_knot_rows(std::declval<const NoiseTables&>(),
                                                                   std::declval<I>(), std::declval<I>(),
                                                                   std::declval<I>()))>> : std::true_type {};

// The two knots (0, j, k) and (1, j, k) of a row along x, at slots
// (i + phi(j + phi(k))) mod n.
template <class Axis, class I>
struct KnotRow {
  const Axis& x_axis;
  I hash_jk;
  I slot(int di) const { return cell_slot(x_axis, hash_jk, di); }
  auto entries(const float* table) const { return entries_at_cells(table, x_axis, hash_jk); }
  // The knots' gradients G[phi(slot)]: x at both knots, then y, then z
  // (the JIT's lanes read a cell's rows at once instead:
  // for_each_noise_gradient_row).
  std::array<std::array<decltype(gather256(static_cast<const float*>(nullptr), I{})), 2>, 3> gradients(
      const NoiseTables& tables) const {
    return {entries(tables.hashed_gradient_x.data()), entries(tables.hashed_gradient_y.data()),
            entries(tables.hashed_gradient_z.data())};
  }
};

// The offsets from p of the 2^3 knots around it, a row along x at a
// time, in the order k, then j: visit(dk, dj, u, v, w) with (u[i], v, w) =
// p - (i, j, k).
//
// The knot loops are written out (each_of_0_and_1): a kernel's optimizer
// left the outer one rolled around a body too large to unroll by its
// measure, which kept the noise tables spilled and reloaded per knot.
template <class F, class Axis, class Visit>
void for_each_row_offset(F x, F y, F z, const Axis& ax, const Axis& ay, const Axis& az, Visit visit) {
  F fx = x - ax.corner(), fy = y - ay.corner(), fz = z - az.corner();
  const std::array<F, 2> u{fx - 0.0f, fx - 1.0f};
  each_of_0_and_1([&](auto dk) {
    F w = fz - float(dk);
    each_of_0_and_1([&](auto dj) { visit(dk, dj, u, fy - float(dj), w); });
  });
}

// Visits the 2^3 knots around p (1989 section 2.3) a row at a time, in the
// order k, j, then i: visit(row, u, v, w) with the knots' offsets (u[i],
// v, w) = p - (i, j, k), each knot's gradient being
// G[phi(i + phi(j + phi(k)))] = hashed_gradient[row.slot(i)]. The axes say
// how cells hash: as they are, or wrapped by a period. `outer_hash`, added
// to k before its phi, is how a fourth axis extends the hash
// (nodes/semantics/noise4.h); 0 for 3D.
template <class F, class Axis, class Visit>
void for_each_noise_row(const NoiseTables& tables, F x, F y, F z, const Axis& ax, const Axis& ay, const Axis& az,
                        IntOf<F> outer_hash, Visit visit) {
  const auto hash_k = entries_at_cells(tables.permutation.data(), az, outer_hash);  // phi(k + outer_hash)
  const std::array hash_jk{entries_at_cells(tables.permutation.data(), ay, hash_k[0]),  // phi(j + phi(k))
                           entries_at_cells(tables.permutation.data(), ay, hash_k[1])};
  for_each_row_offset(x, y, z, ax, ay, az, [&](auto dk, auto dj, const std::array<F, 2>& u, F v, F w) {
    visit(KnotRow<Axis, IntOf<F>>{ax, hash_jk[dk][dj]}, u, v, w);
  });
}

// The hash indices of an axis's two cells around a coordinate, for the
// knot-rows lookups of an axis that wraps (gather256_knot_rows with
// pairs of indices).
template <class Axis>
auto cell_indices(const Axis& axis) {
  return std::array{axis.index(0), axis.index(1)};
}

// The rows of for_each_noise_row (3D) with their knots' gradients:
// visit(gradients, u, v, w), the gradients as KnotRow::gradients gives
// them. Lanes that can look up all four rows in one go do (the JIT,
// reading memory lane by lane, then hashes each lane in general
// registers: codegen/table_lookups.cpp), from each axis's index on the
// lattice and from both cells' indices where an axis wraps.
template <class F, class Axis, class Visit>
void for_each_noise_gradient_row(const NoiseTables& tables, F x, F y, F z, const Axis& ax, const Axis& ay,
                                 const Axis& az, Visit visit) {
  if constexpr (LooksUpKnotRows<IntOf<F>>::value) {
    const auto rows = [&] {
      if constexpr (Axis::next_cell_hashes_next)
        return gather256_knot_rows(tables, ax.index(0), ay.index(0), az.index(0));
      else
        return gather256_knot_rows(tables, cell_indices(ax), cell_indices(ay), cell_indices(az));
    }();
    for_each_row_offset(x, y, z, ax, ay, az, [&](auto dk, auto dj, const std::array<F, 2>& u, F v, F w) {
      visit(rows[2 * dk + dj], u, v, w);
    });
  } else {
    for_each_noise_row(tables, x, y, z, ax, ay, az, IntOf<F>{} + 0,
                       [&](const auto& row, const std::array<F, 2>& u, F v, F w) {
                         visit(row.gradients(tables), u, v, w);
                       });
  }
}

// The same knots one at a time: visit(slot, u, v, w).
template <class F, class Axis, class Visit>
void for_each_noise_knot(const NoiseTables& tables, F x, F y, F z, const Axis& ax, const Axis& ay, const Axis& az,
                         IntOf<F> outer_hash, Visit visit) {
  for_each_noise_row(tables, x, y, z, ax, ay, az, outer_hash,
                     [&](const auto& row, const std::array<F, 2>& u, F v, F w) {
                       each_of_0_and_1([&](auto di) { visit(row.slot(di), u[di], v, w); });
                     });
}

template <class F, class Axis, class Visit>
void for_each_noise_knot(const NoiseTables& tables, F x, F y, F z, const Axis& ax, const Axis& ay, const Axis& az,
                         Visit visit) {
  for_each_noise_knot(tables, x, y, z, ax, ay, az, IntOf<F>{} + 0, visit);
}

template <class F, class Visit>
void for_each_noise_knot(const NoiseTables& tables, F x, F y, F z, Visit visit) {
  for_each_noise_knot(tables, x, y, z, lattice_axis(x), lattice_axis(y), lattice_axis(z), visit);
}

// sum over the 8 knots of w(u) w(v) w(w) (G . (u,v,w)), on the given axes.
template <class F, class Axis>
F noise_on_axes(const NoiseTables& tables, F x, F y, F z, const Axis& ax, const Axis& ay, const Axis& az) {
  F sum = splat<F>(0.0f);
  for_each_noise_gradient_row(tables, x, y, z, ax, ay, az,
                              [&](const auto& gradients, const std::array<F, 2>& u, F v, F w) {
                                const auto& [gx, gy, gz] = gradients;
                                each_of_0_and_1([&](auto di) {
                                  F slope = gx[di] * u[di] + gy[di] * v + gz[di] * w;
                                  sum = sum + noise_weight(u[di]) * noise_weight(v) * noise_weight(w) * slope;
                                });
                              });
  return sum;
}

template <class F>
F noise(const NoiseTables& tables, F x, F y, F z) {
  return noise_on_axes(tables, x, y, z, lattice_axis(x), lattice_axis(y), lattice_axis(z));
}

// noise, repeating every period (whole cells, per axis): pnoise(p + period
// e_i) = pnoise(p) exactly where p + period e_i is exact.
template <class F>
F pnoise(const NoiseTables& tables, F x, F y, F z, F px, F py, F pz) {
  return noise_on_axes(tables, x, y, z, periodic_axis(x, noise_period(px)), periodic_axis(y, noise_period(py)),
                       periodic_axis(z, noise_period(pz)));
}

// The analytic gradient of noise (Perlin 1985 Dnoise): product rule on
// each knot's w(u) w(v) w(w) (G . (u,v,w)).
template <class F>
Vec3<F> dnoise(const NoiseTables& tables, F x, F y, F z) {
  Vec3<F> sum{splat<F>(0.0f), splat<F>(0.0f), splat<F>(0.0f)};
  for_each_noise_gradient_row(tables, x, y, z, lattice_axis(x), lattice_axis(y), lattice_axis(z),
                              [&](const auto& gradients, const std::array<F, 2>& knot_u, F v, F w) {
                                const auto& [row_gx, row_gy, row_gz] = gradients;
                                each_of_0_and_1([&](auto di) {
                                  F u = knot_u[di], gx = row_gx[di], gy = row_gy[di], gz = row_gz[di];
                                  F slope = gx * u + gy * v + gz * w;
                                  F wu = noise_weight(u), wv = noise_weight(v), ww = noise_weight(w);
                                  F weight = wu * wv * ww;
                                  sum.x = sum.x + noise_weight_derivative(u) * wv * ww * slope + weight * gx;
                                  sum.y = sum.y + wu * noise_weight_derivative(v) * ww * slope + weight * gy;
                                  sum.z = sum.z + wu * wv * noise_weight_derivative(w) * slope + weight * gz;
                                });
                              });
  return sum;
}

// Perlin 2002, "Improving Noise": the fade curve 6t^5 - 15t^4 + 10t^3.
template <class F>
F improved_fade(F t) {
  return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}

template <class F>
F improved_lerp(F t, F a, F b) {
  return a + t * (b - a);
}

// One of 12 edge directions of the cube, picked by the low 4 bits of hash.
template <class F, class I>
F improved_gradient(I hash, F x, F y, F z) {
  I h = hash & 15;
  F u = select(h < 8, x, y);
  F v = select(h < 4, y, select(either(h == 12, h == 14), x, z));
  return select((h & 1) == 0, u, -u) + select((h & 2) == 0, v, -v);
}

// Follows the structure of Perlin's 2002 reference implementation exactly,
// with the lattice indices X + 1, Y + 1, Z + 1 of its next cells taken from
// the axes: on a LatticeAxis they are those sums (the same lookups as the
// reference), on a PeriodicAxis the next cell wrapped by the period.
template <class F, class Axis>
F improved_noise_on_axes(F x, F y, F z, const Axis& ax, const Axis& ay, const Axis& az) {
  const std::int32_t* p = improved_noise_permutation.data();
  auto X = ax.index(0), Y = ay.index(0), Z = az.index(0);
  auto X1 = ax.index(1), Y1 = ay.index(1), Z1 = az.index(1);
  x = x - ax.corner();
  y = y - ay.corner();
  z = z - az.corner();
  F u = improved_fade(x), v = improved_fade(y), w = improved_fade(z);
  // The reference's A = p[X] + Y, AA = p[A] + Z, AB = p[A + 1] + Z, and
  // p[AA + 1] its last lookup: here hash_ay = p[p[X] + Y], and so on.
  auto A = gather(p, X), hash_ay = gather(p, A + Y), hash_ay1 = gather(p, A + Y1);
  auto B = gather(p, X1), hash_by = gather(p, B + Y), hash_by1 = gather(p, B + Y1);
  auto AA = hash_ay + Z, BA = hash_by + Z, AB = hash_ay1 + Z, BB = hash_by1 + Z;
  auto AA1 = hash_ay + Z1, BA1 = hash_by + Z1, AB1 = hash_ay1 + Z1, BB1 = hash_by1 + Z1;
  return improved_lerp(
      w,
      improved_lerp(v,
                    improved_lerp(u, improved_gradient(gather(p, AA), x, y, z),
                                  improved_gradient(gather(p, BA), x - 1.0f, y, z)),
                    improved_lerp(u, improved_gradient(gather(p, AB), x, y - 1.0f, z),
                                  improved_gradient(gather(p, BB), x - 1.0f, y - 1.0f, z))),
      improved_lerp(v,
                    improved_lerp(u, improved_gradient(gather(p, AA1), x, y, z - 1.0f),
                                  improved_gradient(gather(p, BA1), x - 1.0f, y, z - 1.0f)),
                    improved_lerp(u, improved_gradient(gather(p, AB1), x, y - 1.0f, z - 1.0f),
                                  improved_gradient(gather(p, BB1), x - 1.0f, y - 1.0f, z - 1.0f))));
}

template <class F>
F noise_improved(F x, F y, F z) {
  return improved_noise_on_axes(x, y, z, lattice_axis(x), lattice_axis(y), lattice_axis(z));
}

// Improved noise repeating every period (whole cells, per axis); a period
// of 256, its permutation's own, gives noise_improved bit for bit.
template <class F>
F pnoise_improved(F x, F y, F z, F px, F py, F pz) {
  return improved_noise_on_axes(x, y, z, periodic_axis(x, noise_period(px)), periodic_axis(y, noise_period(py)),
                                periodic_axis(z, noise_period(pz)));
}

// Octave i (scale 2^-i) takes part while i < octaves and, as in the loop
// "while (scale > pixelsize)" of the 1985 appendix, scale > filter_width.
// The trip count differs per lane, so lanes drop out through a mask.
// `noise_at(frequency)` is the octave's noise of p * frequency.
template <class F, class NoiseAt>
F turbulence_of(F octaves, F filter_width, NoiseAt noise_at) {
  F sum = splat<F>(0.0f);
  float scale = 1.0f;
  loop_while(
      max_octaves,
      [&](const F& octave, const F&, const auto& scale) { return both(octave < octaves, filter_width < scale); },
      [&](const auto& active, F& sum, auto& scale) {
        F n = noise_at(1.0f / scale);  // a power of two: p * frequency is exact
        sum = sum + select(active, abs(n) * scale, splat<F>(0.0f));
        scale = scale * 0.5f;
      },
      sum, scale);
  return sum;
}

template <class F>
F turbulence(const NoiseTables& tables, F x, F y, F z, F octaves, F filter_width) {
  return turbulence_of(octaves, filter_width, [&](auto f) { return noise(tables, x * f, y * f, z * f); });
}

// Turbulence repeating every period: octave i is pnoise of 2^i p with
// period 2^i period, so every octave repeats where the first does.
template <class F>
F pturbulence(const NoiseTables& tables, F x, F y, F z, F px, F py, F pz, F octaves, F filter_width) {
  const F period_x = noise_period(px), period_y = noise_period(py), period_z = noise_period(pz);
  return turbulence_of(octaves, filter_width, [&](auto f) {
    return noise_on_axes(tables, x * f, y * f, z * f, periodic_axis(x * f, period_x * f),
                         periodic_axis(y * f, period_y * f), periodic_axis(z * f, period_z * f));
  });
}

// Fractional Brownian motion: octave i has frequency lacunarity^i and
// amplitude gain^i; octaves take part until the first one whose period
// 1 / frequency is not above filter_width (a lane never resumes: with a
// lacunarity below 1 the frequency could fall again).
// `noise_at(frequency)` is the octave's noise of p * frequency.
template <class F, class NoiseAt>
F fbm_of(F octaves, F lacunarity, F gain, F filter_width, NoiseAt noise_at) {
  F sum = splat<F>(0.0f);
  F frequency = splat<F>(1.0f);
  F amplitude = splat<F>(1.0f);
  auto active = splat<F>(0.0f) < octaves;
  loop_while(
      max_octaves,
      [&](const F& octave, const F&, const F& frequency, const F&, const auto& active) {
        return both(active, both(octave < octaves, frequency * filter_width < 1.0f));
      },
      [&](const auto& now, F& sum, F& frequency, F& amplitude, auto& active) {
        active = now;
        F n = noise_at(frequency);
        sum = sum + select(active, n * amplitude, splat<F>(0.0f));
        frequency = frequency * lacunarity;
        amplitude = amplitude * gain;
      },
      sum, frequency, amplitude, active);
  return sum;
}

template <class F>
F fbm(const NoiseTables& tables, F x, F y, F z, F octaves, F lacunarity, F gain, F filter_width) {
  return fbm_of(octaves, lacunarity, gain, filter_width,
                [&](F f) { return noise(tables, x * f, y * f, z * f); });
}

// fbm repeating every period. The lacunarity is rounded to a whole number
// (at least 2), so that octave i, pnoise of lacunarity^i p with period
// lacunarity^i period, repeats where the first octave does.
template <class F>
F pfbm(const NoiseTables& tables, F x, F y, F z, F px, F py, F pz, F octaves, F lacunarity, F gain,
       F filter_width) {
  const F period_x = noise_period(px), period_y = noise_period(py), period_z = noise_period(pz);
  const F whole = max(floor(lacunarity + 0.5f), splat<F>(2.0f));
  return fbm_of(octaves, whole, gain, filter_width, [&](F f) {
    return noise_on_axes(tables, x * f, y * f, z * f, periodic_axis(x * f, period_x * f),
                         periodic_axis(y * f, period_y * f), periodic_axis(z * f, period_z * f));
  });
}

}  // namespace shadetree::semantics

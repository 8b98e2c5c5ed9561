// Cellular noise (Worley 1996, "A Cellular Texture Basis Function"),
// written once over a lane type F.
#pragma once

#include "nodes/lane_scalar.h"
#include "nodes/noise_tables.h"
#include "nodes/semantics/noise.h"

namespace shadetree::semantics {

using namespace shadetree::lanes;

// F1 and F2: the distances from p to the nearest and second-nearest
// feature points.
template <class F>
struct CellularDistances {
  F nearest, second;
};

// Worley 1996 section 2, with one feature point per unit cell: the point of
// cell (i, j, k) lies at (i, j, k) + 1/2 + jitter (h - 1/2), where h is
// three hashes of the cell through the permutation (phi of 1989 section
// 2.3) scaled to [0, 1). With jitter in [0, 1] every point stays in its
// cell, so the 27 cells around p hold the nearest point; F2 is exact
// unless the second-nearest point lies further out, which the 27 cells
// make rare. jitter 0 puts every point at its cell's centre.
// The axes say how cells hash (noise.h): as they are, or wrapped by a period.
template <class F, class Axis>
CellularDistances<F> cellular_on_axes(const NoiseTables& tables, F x, F y, F z, F jitter, const Axis& ax,
                                      const Axis& ay, const Axis& az) {
  const F fx = x - ax.corner(), fy = y - ay.corner(), fz = z - az.corner();
  jitter = min(max(jitter, splat<F>(0.0f)), splat<F>(1.0f));
  F nearest = splat<F>(1e30f), second = splat<F>(1e30f);
  for (int dk = -1; dk <= 1; ++dk) {
    auto hash_k = noise_phi(tables, az.index(dk));
    for (int dj = -1; dj <= 1; ++dj) {
      auto hash_jk = noise_phi(tables, ay.index(dj) + hash_k);
      for (int di = -1; di <= 1; ++di) {
        auto hash_x = noise_phi(tables, ax.index(di) + hash_jk);
        auto hash_y = noise_phi(tables, hash_x + 1);
        auto hash_z = noise_phi(tables, hash_y + 1);
        auto offset = [&](auto hash, int cell, F along) {
          return float(cell) + 0.5f + jitter * (to_float(hash) * (1.0f / noise_table_size) - 0.5f) - along;
        };
        const F u = offset(hash_x, di, fx), v = offset(hash_y, dj, fy), w = offset(hash_z, dk, fz);
        const F distance = u * u + v * v + w * w;
        second = select(distance < nearest, nearest, min(second, distance));
        nearest = min(nearest, distance);
      }
    }
  }
  return {sqrt(nearest), sqrt(second)};
}

template <class F>
CellularDistances<F> cellular(const NoiseTables& tables, F x, F y, F z, F jitter) {
  return cellular_on_axes(tables, x, y, z, jitter, lattice_axis(x), lattice_axis(y), lattice_axis(z));
}

// Cellular noise repeating every period (whole cells, per axis): the
// feature point of cell c is that of cell c mod period.
template <class F>
CellularDistances<F> pcellular(const NoiseTables& tables, F x, F y, F z, F px, F py, F pz, F jitter) {
  return cellular_on_axes(tables, x, y, z, jitter, periodic_axis(x, noise_period(px)),
                          periodic_axis(y, noise_period(py)), periodic_axis(z, noise_period(pz)));
}

}  // namespace shadetree::semantics

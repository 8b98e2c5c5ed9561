// Splines and tables over constant knot data, written once over a lane type
// F. Knot data is a flat array: knot k, component c at [k * components + c].
#pragma once

#include <tuple>
#include <utility>

#include "nodes/lane_scalar.h"
#include "nodes/semantics/vec3.h"

namespace shadetree::semantics {

using namespace shadetree::lanes;

enum class SplineBasis : int { catmull_rom = 0, linear = 1, step = 2 };

template <class F>
F unit_clamp(F x) {
  return min(max(x, splat<F>(0.0f)), splat<F>(1.0f));
}

// One component of a spline through `count` knots over x in [0,1].
// Catmull-Rom follows Perlin 1985's spline(): the curve passes through
// knots 1 .. count-2 and the end knots only steer the tangents.
template <class F>
F spline(const float* knots, int count, int components, int component, SplineBasis basis, F x) {
  auto knot = [&](auto index) { return gather_small(knots + component, count, components, index); };
  x = unit_clamp(x);
  if (basis == SplineBasis::step) {
    auto index = to_int(min(floor(x * float(count)), splat<F>(float(count - 1))));
    return knot(index);
  }
  const int segments = basis == SplineBasis::catmull_rom ? count - 3 : count - 1;
  if (segments <= 0) return knot(to_int(splat<F>(0.0f)));
  F t = x * float(segments);
  F segment = min(floor(t), splat<F>(float(segments - 1)));
  F f = t - segment;
  auto index = to_int(segment);
  if (basis == SplineBasis::linear) {
    F k0 = knot(index), k1 = knot(index + 1);
    return k0 + (k1 - k0) * f;
  }
  F k0 = knot(index), k1 = knot(index + 1), k2 = knot(index + 2), k3 = knot(index + 3);
  F f2 = f * f, f3 = f2 * f;
  return ((f2 * 2.0f - f3 - f) * k0 + (f3 * 3.0f - f2 * 5.0f + 2.0f) * k1 + (f2 * 4.0f - f3 * 3.0f + f) * k2 +
          (f3 - f2) * k3) *
         0.5f;
}

// Gilet & Dischler 2010 section 4.1: a 1D shape transfer function, control
// values equally spaced over data[0] .. data[1], linearly interpolated.
template <class F>
F table1d(const float* data, int count, F x) {
  return spline(data + 2, count, 1, 0, SplineBasis::linear, (x - data[0]) / (data[1] - data[0]));
}

// Integral from 0 to u (in entries) of the piecewise-constant table, from
// prefix sums (prefix[k] = sum of the first k entries); beyond the ends the
// end entries extend.
template <class F>
F table_integral(const float* entries, const float* prefix, int count, int components, int component, F u) {
  F cell = min(max(floor(u), splat<F>(0.0f)), splat<F>(float(count - 1)));
  auto index = to_int(cell);
  return gather(prefix, index * components + component) +
         (u - cell) * gather(entries, index * components + component);
}

// Rhoades et al. 1992: antialias a colour table lookup by returning the
// table's average over an interval of filter_width around x instead of a
// point sample.
template <class F>
F color_table(const float* entries, const float* prefix, int count, int components, int component, F x,
              F filter_width) {
  F u = x * float(count);
  F width = abs(filter_width) * float(count);
  auto point_index = to_int(min(max(floor(u), splat<F>(0.0f)), splat<F>(float(count - 1))));
  F point = gather(entries, point_index * components + component);
  F safe_width = select(width > 0.0f, width, splat<F>(1.0f));
  F average = (table_integral(entries, prefix, count, components, component, u + width * 0.5f) -
               table_integral(entries, prefix, count, components, component, u - width * 0.5f)) /
              safe_width;
  return select(width > 0.0f, average, point);
}

// Gilet & Dischler 2010 section 4.2: a 2D shape transfer function, here
// bilinear over a rows x columns grid covering [0,1]^2.
template <class F>
F table2d(const float* values, int rows, int columns, F x, F y) {
  auto axis = [](F coordinate, int size) {
    F position = unit_clamp(coordinate) * float(size - 1);
    F cell = min(floor(position), splat<F>(float(size > 1 ? size - 2 : 0)));
    return std::pair{to_int(cell), position - cell};
  };
  auto [column, fx] = axis(x, columns);
  auto [row, fy] = axis(y, rows);
  int column_step = columns > 1 ? 1 : 0, row_step = rows > 1 ? columns : 0;
  auto base = row * columns + column;
  F v00 = gather(values, base), v01 = gather(values, base + column_step);
  F v10 = gather(values, base + row_step), v11 = gather(values, base + row_step + column_step);
  F bottom = v00 + (v01 - v00) * fx;
  F top = v10 + (v11 - v10) * fx;
  return bottom + (top - bottom) * fy;
}

enum class ImageWrap : int { repeat = 0, clamp = 1 };

// Bilinear lookup of an RGB image of `width` x `height` pixels, bottom row
// first, at (u, v): pixel (i, j) is centred at ((i + 0.5) / width,
// (j + 0.5) / height), so (0, 0) is the lower-left corner, as uv and P.xy
// of a texture. Perlin 1985: "any stored texture algorithm may be cast as
// a table lookup function composed with a projection function".
template <class F>
Vec3<F> image(const float* rgb, int width, int height, ImageWrap wrap, F u, F v) {
  using I = IntOf<F>;
  // Each axis: the two pixels to blend and the weight of the second. The
  // coordinate is first brought into [0, 1] (NaN to 0), so that no input
  // can index outside the image.
  auto axis = [wrap](F coordinate, int size) {
    F t = wrap == ImageWrap::repeat ? unit_clamp(coordinate - floor(coordinate)) : unit_clamp(coordinate);
    F position = t * float(size) - 0.5f;
    F cell = floor(position);
    I first = to_int(cell), second = first + 1;
    if (wrap == ImageWrap::repeat) {
      first = select(first < 0, I{} + (size - 1), first);
      second = select(second >= size, I{}, second);
      // No-ops on lanes; over intervals, where select takes the hull of
      // both sides when it cannot tell, they keep the indices inside the
      // image, as gather needs.
      first = max(first, I{});
      second = min(second, I{} + (size - 1));
    } else {
      first = max(first, I{});
      second = min(second, I{} + (size - 1));
    }
    return std::tuple{first, second, position - cell};
  };
  auto [left, right, fx] = axis(u, width);
  auto [bottom, top, fy] = axis(v, height);
  F channels[3];
  for (int c = 0; c < 3; ++c) {
    auto texel = [&](I row, I column) { return gather(rgb, (row * width + column) * 3 + c); };
    F lower = texel(bottom, left) + (texel(bottom, right) - texel(bottom, left)) * fx;
    F upper = texel(top, left) + (texel(top, right) - texel(top, left)) * fx;
    channels[c] = lower + (upper - lower) * fy;
  }
  return {channels[0], channels[1], channels[2]};
}

}  // namespace shadetree::semantics

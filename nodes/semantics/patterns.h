// Pattern generators of the Pixel-Planes 5 T-code set (Rhoades et al. 1992):
// Gardner's sum of sines, the antialiased square wave, a Julia set, and a
// checkerboard. Written once over a lane type F.
#pragma once

#include "nodes/lane_scalar.h"
#include "nodes/limits.h"
#include "nodes/semantics/trigonometry.h"

namespace shadetree::semantics {

using namespace shadetree::lanes;

// Gardner 1984 (cited by Rhoades et al. 1992 for cloudy skies): two series
// of sines, each term's phase shifted by a slower sine of the other
// coordinate, frequencies doubling and amplitudes falling by 0.707 per
// term; their product is normalized to [0,1].
template <class F>
F sines(F x, F y, F frequency, F octaves) {
  constexpr float half_pi = 1.57079632679f;
  F series_x = splat<F>(0.0f), series_y = splat<F>(0.0f), total_amplitude = splat<F>(0.0f);
  F omega = frequency;
  float amplitude = 1.0f;
  loop_while(
      max_octaves, [&](const F& term, const F&, const F&, const F&, const F&, const auto&) { return term < octaves; },
      [&](const auto& active, F& series_x, F& series_y, F& total_amplitude, F& omega, auto& amplitude) {
        F phase_x = sine_of(omega * y * 0.5f) * half_pi;
        F phase_y = sine_of(omega * x * 0.5f) * half_pi;
        series_x = series_x + select(active, (sine_of(omega * x + phase_x) + 1.0f) * amplitude, splat<F>(0.0f));
        series_y = series_y + select(active, (sine_of(omega * y + phase_y) + 1.0f) * amplitude, splat<F>(0.0f));
        total_amplitude = total_amplitude + select(active, splat<F>(2.0f) * amplitude, splat<F>(0.0f));
        omega = omega * 2.0f;
        amplitude = amplitude * 0.707f;
      },
      series_x, series_y, total_amplitude, omega, amplitude);
  F norm = total_amplitude * total_amplitude;
  return select(norm > 0.0f, series_x * series_y / norm, splat<F>(0.0f));
}

// Integral from 0 to t of the unit square wave that is 1 on [k, k + duty).
template <class F>
F square_wave_integral(F t, F duty) {
  F cell = floor(t);
  return cell * duty + min(t - cell, duty);
}

// Rhoades et al. 1992: the square wave convolved analytically with a box
// of the filter width. Both ends are taken relative to the period the box
// starts in, so that the difference of integrals does not cancel
// catastrophically far from the origin.
template <class F>
F swave(F x, F filter_width, F frequency, F duty, F phase) {
  duty = min(max(duty, splat<F>(0.0f)), splat<F>(1.0f));
  F t = x * frequency + phase;
  F width = abs(filter_width * frequency);
  F unfiltered = select(t - floor(t) < duty, splat<F>(1.0f), splat<F>(0.0f));
  F start = t - width * 0.5f;
  F base = floor(start);
  F filtered = (square_wave_integral(start - base + width, duty) - square_wave_integral(start - base, duty)) /
               select(width > 0.0f, width, splat<F>(1.0f));
  return select(width > 0.0f, filtered, unfiltered);
}

// Julia set of z -> z^2 + c from z0 = p: the fraction of the iteration
// limit survived before |z| > 2 (1 for points of the filled set).
template <class F>
F julia(F zx, F zy, F cx, F cy, F iterations) {
  iterations = min(iterations, splat<F>(float(max_julia_iterations)));
  F survived = splat<F>(0.0f);
  // A lane stays out once out: an escaped z is frozen, so |z| stays > 2.
  loop_while(
      max_julia_iterations,
      [&](const F& i, const F& zx, const F& zy, const F&) { return both(i < iterations, zx * zx + zy * zy <= 4.0f); },
      [&](const auto& alive, F& zx, F& zy, F& survived) {
        F next_x = zx * zx - zy * zy + cx;
        F next_y = zx * zy * 2.0f + cy;
        zx = select(alive, next_x, zx);
        zy = select(alive, next_y, zy);
        survived = survived + select(alive, splat<F>(1.0f), splat<F>(0.0f));
      },
      zx, zy, survived);
  return select(iterations > 0.0f, survived / iterations, splat<F>(0.0f));
}

// 1 where floor(x) + floor(y) + floor(z) is odd, else 0.
template <class F>
F checker(F x, F y, F z) {
  F sum = floor(x) + floor(y) + floor(z);
  return sum - floor(sum * 0.5f) * 2.0f;
}

}  // namespace shadetree::semantics

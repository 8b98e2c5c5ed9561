// Written by hand from Perlin 1985 and Perlin & Hoffert 1989 rather than
// from nodes/semantics, as a C++ programmer would write these textures:
// the same tables and formulas, scalar loops, whatever the compiler makes
// of them, with libm's sin and pow. The numbers in the loops below are the
// graphs' constants and their params' defaults. SCALAR_YARDSTICKS_COMPILER
// names the namespace of this build (gcc or clang: CMakeLists.txt compiles
// the file with each).
#include "bench/scalar_yardsticks.h"

#include <algorithm>
#include <cmath>

#include "nodes/noise_tables.h"

namespace shadetree::yardstick::SCALAR_YARDSTICKS_COMPILER {
namespace {

const NoiseTables& tables = noise_tables(default_noise_seed);

// Both graphs' octaves param at its default; the pixel size clamps it.
constexpr int turbulence_octaves = 8;

// Perlin & Hoffert 1989 section 2.3: the drop-off 2|t|^3 - 3|t|^2 + 1.
float weight(float t) {
  t = std::fabs(t);
  return (t * 2.0f - 3.0f) * t * t + 1.0f;
}

// 1989 section 2.3: the knot (i, j, k) has the gradient
// G[phi(i + phi(j + phi(k)))]; hashed_gradient is G[phi(.)], so the last
// hash and the gradient are one lookup. The graphs' domains are small, so
// a cell fits an int.
float noise_at(float x, float y, float z) {
  const float fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  const int ix = static_cast<int>(fx), iy = static_cast<int>(fy), iz = static_cast<int>(fz);
  const float u = x - fx, v = y - fy, w = z - fz;
  const float wu[2] = {weight(u), weight(u - 1.0f)};
  const float wv[2] = {weight(v), weight(v - 1.0f)};
  const float ww[2] = {weight(w), weight(w - 1.0f)};
  float sum = 0.0f;
  for (int k = 0; k < 2; ++k) {
    const int hash_k = tables.permutation[(iz + k) & 255];
    for (int j = 0; j < 2; ++j) {
      const int hash_jk = tables.permutation[(iy + j + hash_k) & 255];
      for (int i = 0; i < 2; ++i) {
        const int slot = (ix + i + hash_jk) & 255;
        const float slope = tables.hashed_gradient_x[slot] * (u - i) + tables.hashed_gradient_y[slot] * (v - j) +
                            tables.hashed_gradient_z[slot] * (w - k);
        sum += wu[i] * wv[j] * ww[k] * slope;
      }
    }
  }
  return sum;
}

// The 1985 appendix: octaves while the scale is above the pixel size.
float turbulence_at(float x, float y, float z, float pixel_size) {
  float sum = 0.0f;
  float scale = 1.0f;
  for (int octave = 0; octave < turbulence_octaves && scale > pixel_size; ++octave, scale *= 0.5f)
    sum += std::fabs(noise_at(x / scale, y / scale, z / scale)) * scale;
  return sum;
}

using Knots = float[8][3];

// Perlin 1985's spline(): Catmull-Rom through knots 1..6 over x in [0,1],
// the end knots steering the tangents.
void catmull_rom(const Knots& knots, float x, float* rgb) {
  const float t = std::clamp(x, 0.0f, 1.0f) * 5.0f;
  const int segment = std::min(static_cast<int>(t), 4);
  const float f = t - segment, f2 = f * f, f3 = f2 * f;
  for (int c = 0; c < 3; ++c)
    rgb[c] = ((f2 * 2.0f - f3 - f) * knots[segment][c] + (f3 * 3.0f - f2 * 5.0f + 2.0f) * knots[segment + 1][c] +
              (f2 * 4.0f - f3 * 3.0f + f) * knots[segment + 2][c] + (f3 - f2) * knots[segment + 3][c]) *
             0.5f;
}

const Knots turbulence_knots = {{0.02f, 0.02f, 0.08f}, {0.02f, 0.02f, 0.08f}, {0.08f, 0.12f, 0.35f},
                                {0.1f, 0.4f, 0.65f},    {0.35f, 0.72f, 0.82f}, {0.8f, 0.93f, 0.95f},
                                {1.0f, 1.0f, 1.0f},     {1.0f, 1.0f, 1.0f}};

const Knots marble_knots = {{0.95f, 0.93f, 0.9f}, {0.95f, 0.93f, 0.9f}, {0.8f, 0.78f, 0.76f}, {0.62f, 0.6f, 0.6f},
                            {0.4f, 0.38f, 0.42f},  {0.2f, 0.18f, 0.24f}, {0.1f, 0.08f, 0.12f}, {0.1f, 0.08f, 0.12f}};

}  // namespace

void noise(const float* x, const float* y, const float* z, const float*, float* red, float* green, float* blue,
           std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) {
    const float grey = (noise_at(x[i] * 8.0f, y[i] * 8.0f, z[i] * 8.0f) + 1.0f) * 0.5f;
    red[i] = green[i] = blue[i] = grey;
  }
}

void turbulence(const float* x, const float* y, const float* z, const float* filter_width, float* red,
                float* green, float* blue, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) {
    // scale 4, range 0.7, contrast 0.8
    const float sum = turbulence_at(x[i] * 4.0f, y[i] * 4.0f, z[i] * 4.0f, filter_width[i] * 4.0f);
    const float shaped = std::pow(std::clamp(sum / 0.7f, 0.0f, 1.0f), 0.8f);
    float rgb[3];
    catmull_rom(turbulence_knots, shaped, rgb);
    red[i] = rgb[0];
    green[i] = rgb[1];
    blue[i] = rgb[2];
  }
}

void marble(const float* x, const float* y, const float* z, const float* filter_width, float* red, float* green,
            float* blue, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) {
    // scale 6, turbulence_amount 7
    const float layers = std::sin(x[i] * 6.0f + turbulence_at(x[i], y[i], z[i], filter_width[i]) * 7.0f);
    const float unit = (layers + 1.0f) * 0.5f;
    float rgb[3];
    catmull_rom(marble_knots, unit * unit * unit, rgb);  // pow(unit, 3) as anyone writes a cube
    red[i] = rgb[0];
    green[i] = rgb[1];
    blue[i] = rgb[2];
  }
}

}  // namespace shadetree::yardstick::SCALAR_YARDSTICKS_COMPILER

// Written by hand from Perlin 1985 and Perlin & Hoffert 1989 rather than
// from nodes/semantics, as a C++ programmer would write marble: the same
// tables and formulas, scalar code, whatever the compiler makes of it.
#include "bench/marble_yardstick.h"

#include <cmath>

#include "nodes/noise_tables.h"

namespace shadetree::yardstick {
namespace {

const NoiseTables& tables = noise_tables(default_noise_seed);

inline float weight(float t) {
  t = std::fabs(t);
  return (t * 2.0f - 3.0f) * t * t + 1.0f;
}

float noise(float x, float y, float z) {
  const float fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  const int ix = static_cast<int>(fx) & 255, iy = static_cast<int>(fy) & 255, iz = static_cast<int>(fz) & 255;
  float sum = 0.0f;
  for (int k = 0; k < 2; ++k) {
    const int hk = tables.permutation[(iz + k) & 255];
    const float w = z - fz - k;
    for (int j = 0; j < 2; ++j) {
      const int hj = tables.permutation[(iy + j + hk) & 255];
      const float v = y - fy - j;
      for (int i = 0; i < 2; ++i) {
        const int g = tables.permutation[(ix + i + hj) & 255];
        const float u = x - fx - i;
        sum += weight(u) * weight(v) * weight(w) *
               (tables.gradient_x[g] * u + tables.gradient_y[g] * v + tables.gradient_z[g] * w);
      }
    }
  }
  return sum;
}

float turbulence(float x, float y, float z, float pixel_size) {
  float sum = 0.0f;
  float scale = 1.0f;
  for (int octave = 0; octave < 8 && scale > pixel_size; ++octave, scale *= 0.5f)
    sum += std::fabs(noise(x / scale, y / scale, z / scale)) * scale;
  return sum;
}

const float knots[8][3] = {{0.95f, 0.93f, 0.9f}, {0.95f, 0.93f, 0.9f}, {0.8f, 0.78f, 0.76f}, {0.62f, 0.6f, 0.6f},
                           {0.4f, 0.38f, 0.42f},  {0.2f, 0.18f, 0.24f}, {0.1f, 0.08f, 0.12f}, {0.1f, 0.08f, 0.12f}};

void marble_color(float t, float* rgb) {
  t = std::fmin(std::fmax(t, 0.0f), 1.0f) * 5.0f;
  const int segment = std::min(static_cast<int>(t), 4);
  const float f = t - segment, f2 = f * f, f3 = f2 * f;
  for (int c = 0; c < 3; ++c) {
    const float* k0 = knots[segment];
    rgb[c] = 0.5f * ((-f3 + 2 * f2 - f) * k0[c] + (3 * f3 - 5 * f2 + 2) * knots[segment + 1][c] +
                     (-3 * f3 + 4 * f2 + f) * knots[segment + 2][c] + (f3 - f2) * knots[segment + 3][c]);
  }
}

}  // namespace

void marble(const float* x, const float* y, const float* z, const float* filter_width, float* red, float* green,
            float* blue, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) {
    const float layers = std::sin(x[i] * 6.0f + turbulence(x[i], y[i], z[i], filter_width[i]) * 7.0f);
    float rgb[3];
    marble_color(std::pow((layers + 1.0f) * 0.5f, 3.0f), rgb);
    red[i] = rgb[0];
    green[i] = rgb[1];
    blue[i] = rgb[2];
  }
}

}  // namespace shadetree::yardstick

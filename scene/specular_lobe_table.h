// The Blinn-Phong lobe base^exponent of one exponent, for a render that
// need not be the reference: read from a table instead of libm's powf,
// which took 4.6% of a cached tribble's time and 6.4% of furry_donut's
// (docs/architecture.md, "The lobe from a table"). Bases below the floor
// give +0, as they add less than 2^-16 of a light.
#pragma once

#include <cmath>
#include <vector>

namespace shadetree {

class SpecularLobeTable {
 public:
  // Where base^exponent falls below 2^-16: 0 for the exponent 0.
  static float floor_of(float exponent) { return exponent > 0.0f ? std::exp2(-16.0f / exponent) : 0.0f; }

  // Entries over [floor, 1], linearly interpolated: |table - pow| <= h^2
  // / 8 max|f''| with h = (1 - floor) / (entries - 1). For an exponent e
  // of at least 2, f'' = e (e - 1) x^(e - 2) is largest at 1, and the
  // floor rises with e, so that h^2 e^2 / 8 tends to (16 ln 2 / (entries
  // - 1))^2 / 8 = 2^-18; between 1 and 2 it is largest at the floor. The
  // table is within 2^-17 of pow, half the floor, for every exponent from
  // 1 to roughness 0.02's (tests/specular_lobe_table_test.cpp). Below 1,
  // f'' is unbounded at the floor: such a lobe takes powf.
  explicit SpecularLobeTable(float exponent);

  float operator()(float base) const {
    if (!(base >= floor_)) return 0.0f;
    if (values_.empty()) return std::pow(base, exponent_);
    const float at = (base - floor_) * per_step_;
    const int k = at < static_cast<float>(entries - 1) ? static_cast<int>(at) : entries - 2;
    const float fraction = at - static_cast<float>(k);
    return values_[k] + fraction * (values_[k + 1] - values_[k]);
  }

  float floor() const { return floor_; }

  static constexpr int entries = 2048;

 private:
  float exponent_, floor_, per_step_ = 0.0f;
  std::vector<float> values_;  // none: powf
};

}  // namespace shadetree

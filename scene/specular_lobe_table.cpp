#include "scene/specular_lobe_table.h"

namespace shadetree {

SpecularLobeTable::SpecularLobeTable(float exponent) : exponent_(exponent), floor_(floor_of(exponent)) {
  if (!(exponent == 0.0f || exponent >= 1.0f) || !std::isfinite(exponent)) return;
  per_step_ = static_cast<float>(entries - 1) / (1.0f - floor_);
  values_.resize(entries);
  for (int k = 0; k < entries; ++k) {
    const double base = floor_ + (1.0 - floor_) * k / (entries - 1);
    values_[static_cast<std::size_t>(k)] = static_cast<float>(std::pow(base, static_cast<double>(exponent)));
  }
}

}  // namespace shadetree

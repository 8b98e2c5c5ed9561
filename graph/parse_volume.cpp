#include "graph/parse_volume.h"

#include <cmath>

namespace shadetree {
namespace {

float diagonal(const VolumeDesc& volume) {
  float sum = 0.0f;
  for (int axis = 0; axis < 3; ++axis) {
    const float extent = volume.bounds_max[axis] - volume.bounds_min[axis];
    sum += extent * extent;
  }
  return std::sqrt(sum);
}

}  // namespace

VolumeDesc parse_volume(const JsonReader& reader, const json& volume) {
  auto fail = [&](const std::string& message) { reader.fail({}, {}, message); };
  if (!volume.is_object()) fail("render volume must be an object with \"bounds\"");
  reader.check_fields(volume, {"bounds", "step", "reference_step", "jitter", "doc"}, {}, "render volume");
  VolumeDesc result;
  if (!volume.contains("bounds"))
    fail("render volume has no \"bounds\" (a volume must be bounded: {\"min\": [x, y, z], \"max\": [x, y, z]})");
  const json& bounds = volume["bounds"];
  if (!bounds.is_object()) fail("render volume bounds must be {\"min\": [x, y, z], \"max\": [x, y, z]}");
  reader.check_fields(bounds, {"min", "max"}, {}, "render volume bounds");
  for (const char* corner : {"min", "max"}) {
    if (!bounds.contains(corner)) fail(std::string("render volume bounds have no \"") + corner + "\"");
    const std::vector<float> values = reader.numbers(bounds[corner], {}, std::string("render volume bounds ") + corner);
    if (values.size() != 3) fail(std::string("render volume bounds ") + corner + " must be [x, y, z]");
    auto& target = std::string(corner) == "min" ? result.bounds_min : result.bounds_max;
    for (int axis = 0; axis < 3; ++axis) target[axis] = values[static_cast<std::size_t>(axis)];
  }
  for (int axis = 0; axis < 3; ++axis)
    if (!(result.bounds_min[axis] < result.bounds_max[axis]))
      fail("render volume bounds are empty: min must be below max on every axis");
  if (!std::isfinite(diagonal(result))) fail("render volume bounds are too large for 32-bit floats");
  if (volume.contains("step")) {
    result.step = reader.number(volume["step"], {}, "render volume step");
    if (std::string problem = step_problem(result, result.step); !problem.empty()) fail("render volume " + problem);
  }
  if (volume.contains("reference_step")) {
    result.reference_step = reader.number(volume["reference_step"], {}, "render volume reference_step");
    if (!(result.reference_step > 0.0f)) fail("render volume reference_step must be positive");
  }
  if (volume.contains("jitter")) {
    if (!volume["jitter"].is_boolean()) fail("render volume jitter must be true or false");
    result.jitter = volume["jitter"].get<bool>();
  }
  return result;
}

float march_step(const VolumeDesc& volume) {
  return volume.step > 0.0f ? volume.step : diagonal(volume) / default_steps_across;
}

float reference_step(const VolumeDesc& volume) {
  return volume.reference_step > 0.0f ? volume.reference_step : diagonal(volume) / default_steps_across;
}

std::string step_problem(const VolumeDesc& volume, float step) {
  if (!(step > 0.0f)) return "step must be positive";
  if (diagonal(volume) / step > max_steps_across)
    return "step " + std::to_string(step) + " is too small: it would take more than " +
           std::to_string(static_cast<long>(max_steps_across)) + " samples to cross the bounds";
  return {};
}

}  // namespace shadetree

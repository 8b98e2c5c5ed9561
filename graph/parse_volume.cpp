#include "graph/parse_volume.h"

#include <algorithm>
#include <cmath>

#include "graph/format_fields.h"

namespace shadetree {
namespace {

// In double: the squares of tiny extents would underflow in float.
float diagonal(const VolumeDesc& volume) {
  double sum = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double extent = static_cast<double>(volume.bounds_max[axis]) - volume.bounds_min[axis];
    sum += extent * extent;
  }
  return static_cast<float>(std::sqrt(sum));
}

// Why the bounds are too thin to march in 32-bit floats, or empty: every
// axis at least min_volume_extent across and at least
// min_volume_relative_extent of the box's distance from the origin, so
// that a step across it still moves P.
std::string thinness_problem(const VolumeDesc& volume) {
  float farthest = 0.0f;
  for (int axis = 0; axis < 3; ++axis)
    farthest = std::max({farthest, std::fabs(volume.bounds_min[axis]), std::fabs(volume.bounds_max[axis])});
  for (int axis = 0; axis < 3; ++axis) {
    const float extent = volume.bounds_max[axis] - volume.bounds_min[axis];
    if (extent < min_volume_extent || extent < min_volume_relative_extent * farthest)
      return "render volume bounds are too thin to march in 32-bit floats: every axis must be at least " +
             std::to_string(min_volume_extent) + " across, and " + std::to_string(min_volume_relative_extent) +
             " times the box's distance from the origin";
  }
  return {};
}

}  // namespace

VolumeDesc parse_volume(const JsonReader& reader, const json& volume) {
  auto fail = [&](const std::string& message) { reader.fail({}, {}, message); };
  if (!volume.is_object()) fail("render volume must be an object with \"bounds\"");
  check_format_fields(reader, volume, volume_fields(), GraphKind::volume, "render volume");
  VolumeDesc result;
  if (!volume.contains("bounds"))
    fail("render volume has no \"bounds\" (a volume must be bounded: {\"min\": [x, y, z], \"max\": [x, y, z]})");
  const json& bounds = volume["bounds"];
  if (!bounds.is_object()) fail("render volume bounds must be {\"min\": [x, y, z], \"max\": [x, y, z]}");
  check_format_fields(reader, bounds, bounds_fields(), GraphKind::volume, "render volume bounds");
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
  if (std::string problem = thinness_problem(result); !problem.empty()) fail(problem);
  if (volume.contains("step")) {
    result.step = reader.number(volume["step"], {}, "render volume step");
    if (std::string problem = step_problem(result, result.step, "step"); !problem.empty()) fail("render volume " + problem);
  }
  if (volume.contains("reference_step")) {
    result.reference_step = reader.number(volume["reference_step"], {}, "render volume reference_step");
    // Shadow rays march at the reference step: bounded as the step is.
    if (std::string problem = step_problem(result, result.reference_step, "reference_step"); !problem.empty())
      fail("render volume " + problem);
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

std::string step_problem(const VolumeDesc& volume, float step, const std::string& what) {
  if (!(step > 0.0f) || !std::isfinite(step)) return what + " must be positive and finite";
  if (diagonal(volume) / step > max_steps_across)
    return what + " " + std::to_string(step) + " is too small: it would take more than " +
           std::to_string(static_cast<long>(max_steps_across)) + " samples to cross the bounds";
  return {};
}

}  // namespace shadetree

// The "volume" of a volume graph's render section: JSON -> VolumeDesc
// (graph/scene.h), checked for shape and range.
#pragma once

#include "graph/json_reader.h"
#include "graph/scene.h"

namespace shadetree {

VolumeDesc parse_volume(const JsonReader& reader, const json& volume);

// The step a volume is marched at (its own, or the default for its
// bounds), and its reference step (its own, or the default step: not the
// march step, so that a finer march does not make the volume denser).
float march_step(const VolumeDesc& volume);
float reference_step(const VolumeDesc& volume);

// Why `step` would be refused for `volume`, or empty: it must be positive,
// finite and cross the bounds' diagonal in at most max_steps_across steps
// (the budget of every ray, primary or shadow). `what` names it.
std::string step_problem(const VolumeDesc& volume, float step, const std::string& what);

}  // namespace shadetree

// The "scene" of a render section: JSON -> SceneDesc (graph/scene.h).
#pragma once

#include "graph/json_reader.h"
#include "graph/scene.h"

namespace shadetree {

SceneDesc parse_scene(const JsonReader& reader, const json& scene);

}  // namespace shadetree

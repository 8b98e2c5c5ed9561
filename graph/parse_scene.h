// The "scene" of a render section: JSON -> SceneDesc (graph/scene.h).
#pragma once

#include "graph/json_reader.h"
#include "graph/scene.h"
#include "nodes/graph_kind.h"

namespace shadetree {

// A surface graph's scene needs objects; a volume graph's holds none (for
// now: its volume is render.volume).
SceneDesc parse_scene(const JsonReader& reader, const json& scene, GraphKind kind);

}  // namespace shadetree

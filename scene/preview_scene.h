// The scene a surface graph without one renders in, as in every material
// editor: one object (a sphere by default, the "material ball") under the
// default lights, framed by the camera.
#pragma once

#include <string>

#include "graph/diagnostic.h"
#include "graph/graph.h"
#include "graph/scene.h"

namespace shadetree {

// `object`: sphere, torus, plane or box, or the path of a mesh file (OBJ
// or PLY), which is scaled and centred to fit the unit sphere.
Result<SceneDesc> preview_scene(const std::string& object);

// A surface graph's own scene, else the preview sphere.
Result<SceneDesc> surface_scene_desc(const Graph& graph);

}  // namespace shadetree

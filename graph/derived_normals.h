// Normals derived by differentiation (ir/differentiate.h), added to a
// graph as nodes before it is checked: a texture's from its height (bake's
// normal maps), a volume's from its density (the ray marcher's lighting
// normal, instead of two probe samples). The nodes' ids hold a '.', which
// no node of a file may have, so they cannot meet the graph's own.
#pragma once

#include "graph/graph.h"

namespace shadetree {

// A texture graph with a "normal" output where it has a "height" and no
// "normal": normalize(-strength dh/dx, -strength dh/dy, 1), +z out of the
// texture, x along its columns and y up its rows.
Graph with_normal_from_height(Graph graph, float strength);

// A volume graph with a "normal" output where it has none, the outward
// normal of its density, -grad d / |grad d| (0 where the gradient is), and
// no other output than its density.
Graph with_normal_from_density(Graph graph);

}  // namespace shadetree

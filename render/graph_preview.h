// A graph's picture at any size through the driver of its kind, on its
// render section's settings: a texture over its domain, a surface graph on
// its scene (or the material ball), a volume through the ray marcher. For
// the editor's previews, where every kind must render from one call.
#pragma once

#include <atomic>

#include "graph/diagnostic.h"
#include "ir/kernel.h"
#include "nodes/image.h"
#include "pipeline/compile_graph.h"

namespace shadetree {

// A draft volume preview's steps, in units of the volume's march step and,
// for its shadow rays, of its reference step. Its density stays as it is:
// opacity is defined per reference step.
inline constexpr float draft_step_factor = 4.0f;

struct PreviewRequest {
  int width = 256;
  int height = 256;
  float frame = 0.0f;
  int threads = 0;  // 0: all cores
  bool draft = false;  // volumes march, shadows too, at draft_step_factor x their steps (the editor's previews while editing)
  const std::atomic<bool>* cancel = nullptr;  // see for_each_tile (render/image_tiles.h)
};

// RGB, or RGBA for a texture graph with an alpha output.
Result<Image> render_preview(const LoadedGraph& loaded, const Kernel& kernel, const PreviewRequest& request);

}  // namespace shadetree

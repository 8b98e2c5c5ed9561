// A graph's picture at any size through the driver of its kind (the kinds
// table, render/graph_kinds.h), on its render section's settings: for the
// editor's previews, where every kind must render from one call.
#pragma once

#include <atomic>

#include "graph/diagnostic.h"
#include "ir/kernel.h"
#include "nodes/image.h"
#include "pipeline/compile_graph.h"
#include "schedule/image_tiles.h"

namespace shadetree {

struct PreviewRequest {
  int width = 256;
  int height = 256;
  float frame = 0.0f;
  int threads = 0;  // 0: all cores
  bool draft = false;  // volumes march coarser steps (RenderRequest::draft), the editor's previews while editing
  const std::atomic<bool>* cancel = nullptr;  // see for_each_tile (schedule/image_tiles.h)
  TileSink tile_done;  // volume: told of each tile as it is done (RenderRequest::tile_done)
};

// RGB, or RGBA for a texture graph with an alpha output.
Result<Image> render_preview(const LoadedGraph& loaded, const Kernel& kernel, const PreviewRequest& request);

}  // namespace shadetree

#include "render/graph_preview.h"

#include "render/graph_kinds.h"

namespace shadetree {

Result<Image> render_preview(const LoadedGraph& loaded, const Kernel& kernel, const PreviewRequest& request) {
  RenderRequest render;
  render.size = {request.width, request.height};
  render.threads = request.threads;
  render.draft = request.draft;
  render.cancel = request.cancel;
  render.tile_done = request.tile_done;
  Result<std::unique_ptr<FrameRenderer>> frames = prepare_render(*loaded.graph, render);
  if (!frames) return frames.error();
  return (*frames)->render(kernel, loaded.params, request.frame, {}, nullptr);
}

}  // namespace shadetree

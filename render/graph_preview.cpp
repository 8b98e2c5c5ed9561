#include "render/graph_preview.h"

#include "graph/parse_volume.h"
#include "render/camera.h"
#include "render/preview_scene.h"
#include "render/scene.h"
#include "render/surface_driver.h"
#include "render/texture_driver.h"
#include "render/volume_driver.h"

namespace shadetree {

Result<Image> render_preview(const LoadedGraph& loaded, const Kernel& kernel, const PreviewRequest& request) {
  const Graph& graph = *loaded.graph;
  if (graph.kind == GraphKind::texture) {
    TextureView view = TextureView::from_settings(graph.render);
    view.width = request.width;
    view.height = request.height;
    view.frame = request.frame;
    TextureRenderOptions options;
    options.threads = request.threads;
    options.cancel = request.cancel;
    return render_texture(kernel, loaded.params, view, options);
  }
  if (graph.kind == GraphKind::volume) {
    if (!graph.render.volume)
      return invalid_input("a volume graph needs render.volume with \"bounds\" to be previewed");
    Result<Scene> scene = Scene::build(volume_scene(graph.render.scene), graph.file, {});
    if (!scene) return scene.error();
    VolumeView view{request.width, request.height, request.frame};
    VolumeRenderOptions options;
    options.threads = request.threads;
    if (request.draft) {
      options.step = draft_step_factor * march_step(*graph.render.volume);
      options.shadow_step = draft_step_factor * reference_step(*graph.render.volume);
    }
    options.cancel = request.cancel;
    return render_volume(kernel, loaded.params, *scene, *graph.render.volume,
                         Camera(scene->desc().camera, request.width, request.height), view, options);
  }
  Result<SceneDesc> desc = surface_scene_desc(graph);
  if (!desc) return desc.error();
  Result<Scene> scene = Scene::build(*desc, graph.file, {});
  if (!scene) return scene.error();
  SurfaceView view;
  view.width = request.width;
  view.height = request.height;
  view.frame = request.frame;
  SurfaceRenderOptions options;
  options.threads = request.threads;
  options.cancel = request.cancel;
  return render_surface(kernel, loaded.params, *scene, Camera(scene->desc().camera, request.width, request.height),
                        view, options);
}

}  // namespace shadetree

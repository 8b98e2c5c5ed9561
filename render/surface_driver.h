// The surface shader driver (Perlin 1985's Pixel Stream Editor on objects;
// Rhoades et al. 1992's deferred shading): per pixel, a primary ray finds
// the visible object, point, normal, uv and the pixel's footprint on the
// surface; then the surface graph runs once per visible sample, a whole
// tile's visible samples in one kernel call (no lanes spent on the
// background); then the driver lights what the graph returned.
#pragma once

#include <atomic>
#include <vector>

#include "ir/kernel.h"
#include "render/graph_kinds.h"
#include "scene/camera.h"
#include "schedule/image_tiles.h"
#include "schedule/progress.h"
#include "nodes/image.h"
#include "scene/scene.h"

namespace shadetree {

struct SurfaceView {
  int width = 512;
  int height = 512;
  float frame = 0.0f;
  int samples_per_pixel = 1;  // jittered, stratified where a square
};

struct SurfaceRenderOptions {
  int threads = 0;  // 0: all cores
  bool shadows = true;  // and the scene's "shadows"
  const Image* background = nullptr;  // RGB per pixel (an environment the camera sees); else the scene's colour
  ProgressCallback progress;  // may be empty
  const std::atomic<bool>* cancel = nullptr;  // see for_each_tile
  TileClaims* claims = nullptr;  // this process's tiles of the frame (for_each_tile); null: all
};

// Where the time went, summed over threads (seconds of one core).
struct SurfaceRenderStats {
  double visibility_seconds = 0;  // primary rays and footprints
  double shading_seconds = 0;     // the kernel
  double lighting_seconds = 0;    // lights and shadow rays
  long visible_samples = 0;
  long samples = 0;
};

// The uniform globals of a frame: time, frame and the key light's colour.
UniformInputs surface_uniforms(const Scene& scene, float frame);

// A surface graph's outputs (nodes/output_contract.h), lit unless the
// scene says "lighting": "none". RGB, averaged over the pixel's samples.
Result<Image> render_surface(const Kernel& kernel, const std::vector<float>& params, const Scene& scene,
                             const Camera& camera, const SurfaceView& view, const SurfaceRenderOptions& options,
                             SurfaceRenderStats* stats = nullptr);

// The surface row of the kinds table (render/graph_kinds.h): the scene
// of the request's preview object, else the graph's, else the preview
// sphere, built once, with its camera at the requested size.
Result<std::unique_ptr<FrameRenderer>> prepare_surface(const Graph& graph, const RenderRequest& request);

}  // namespace shadetree

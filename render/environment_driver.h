// The environment driver: a graph of the view direction I giving a colour,
// the sky a scene's rays see where they meet nothing. Rendered on its own
// as a latitude-longitude panorama (Blinn & Newell 1976's environment map
// layout), or, named by a surface or volume scene's "environment", as the
// background of each of its pixels.
#pragma once

#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "graph/diagnostic.h"
#include "graph/graph.h"
#include "graph/scene.h"
#include "ir/kernel.h"
#include "nodes/image.h"
#include "render/graph_kinds.h"
#include "scene/camera.h"
#include "schedule/image_tiles.h"
#include "schedule/progress.h"

namespace shadetree {

// What a direction gives an environment graph: I the unit direction, P the
// same point on the unit sphere (for solid textures), N = -I (facing the
// viewer), uv its longitude and latitude in [0, 1], and filter_width the
// angle one pixel spans, in radians (the size of a pixel on the sphere).
void store_environment_sample(SampleBuffers& buffers, std::size_t i, const glm::vec3& direction, float filter_width);

// The kinds table's sample_at_point for environments: `at` is the
// direction (normalized; zero looks down -z), the filter width a pixel of
// the panorama of `size`.
PointSample environment_sample_at(const Graph& graph, std::pair<int, int> size, const float at[3],
                                  SampleBuffers& buffers);

// The direction of panorama point (x, y), in pixels from the top-left
// corner of a width x height image: longitude 0 looks down -z and grows
// toward +x, latitude runs from +y (top row) to -y (bottom row).
glm::vec3 panorama_direction(float x, float y, int width, int height);

struct EnvironmentRenderOptions {
  int threads = 0;  // 0: all cores
  ProgressCallback progress;  // may be empty
  const std::atomic<bool>* cancel = nullptr;  // see for_each_tile
  TileClaims* claims = nullptr;  // this process's tiles of the frame (for_each_tile); null: all
};

// The graph's colour over the whole sphere of directions, as a panorama.
Result<Image> render_environment(const Kernel& kernel, const std::vector<float>& params, int width, int height,
                                 float frame, const EnvironmentRenderOptions& options);

// An environment graph compiled (by the JIT) as a scene's background.
class EnvironmentBackground {
 public:
  // The environment `scene` names, or null where it names none.
  static Result<std::shared_ptr<const EnvironmentBackground>> of_scene(const SceneDesc& scene,
                                                                        const std::string& graph_file,
                                                                        const std::vector<std::string>& search_paths);

  // `file` as a scene names it, found as the scene's meshes are
  // (io/resource_path.h), and refused unless it is an environment graph.
  static Result<std::shared_ptr<const EnvironmentBackground>> load(const std::string& file,
                                                                    const std::string& graph_file,
                                                                    const std::vector<std::string>& search_paths);

  // What the ray through each pixel's centre sees: RGB, width x height.
  Result<Image> seen_by(const Camera& camera, int width, int height, float frame,
                        const EnvironmentRenderOptions& options) const;

 private:
  std::vector<float> params_;
  std::unique_ptr<Kernel> kernel_;
};

// What `camera` sees of `environment` at `frame` (width x height, RGB), or
// nothing where the scene names no environment (null): the per-pixel
// background of the surface and volume drivers.
Result<std::optional<Image>> environment_seen_by(const EnvironmentBackground* environment, const Camera& camera,
                                                 int width, int height, float frame,
                                                 const EnvironmentRenderOptions& options);

// The environment row of the kinds table (render/graph_kinds.h): the
// panorama at the requested size.
Result<std::unique_ptr<FrameRenderer>> prepare_environment(const Graph& graph, const RenderRequest& request);

}  // namespace shadetree

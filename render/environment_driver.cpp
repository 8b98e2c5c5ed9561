#include "render/environment_driver.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "io/graph_files.h"
#include "io/resource_path.h"
#include "jit/jit_kernel.h"
#include "pipeline/compile_graph.h"
#include "schedule/image_tiles.h"
#include "schedule/thread_bindings.h"

namespace shadetree {
namespace {

constexpr int tile_size = 64;
constexpr float pi = std::numbers::pi_v<float>;

struct DirectionSample {
  glm::vec3 direction;
  float filter_width;
};

// The graph's colour for the direction of every pixel, a tile at a time.
template <class DirectionAt>
Result<Image> render_directions(const Kernel& kernel, const std::vector<float>& params, int width, int height,
                                float frame, const EnvironmentRenderOptions& options, DirectionAt direction_at) {
  const OutputLayout& layout = kernel.outputs();
  if (layout.kind != GraphKind::environment || !layout.provides(OutputId::color))
    return invalid_input("the environment driver needs an environment graph with an output \"color\"");
  Image image;
  image.width = width;
  image.height = height;
  image.channels = 3;
  image.pixels.assign(static_cast<std::size_t>(width) * height * 3, 0.0f);
  UniformInputs uniforms;
  uniforms.set(GlobalId::time, frame / frames_per_second);
  uniforms.set(GlobalId::frame, frame);
  ThreadBindings bindings(kernel, params.data(), uniforms);
  auto render_tile = [&](const Tile& tile) -> long {
    const std::size_t count = static_cast<std::size_t>(tile.width) * tile.height;
    SampleBuffers input(count, kernel.reads());
    for (int y = 0; y < tile.height; ++y)
      for (int x = 0; x < tile.width; ++x) {
        const DirectionSample sample = direction_at(tile.x0 + x, tile.y0 + y);
        store_environment_sample(input, static_cast<std::size_t>(y) * tile.width + x, sample.direction,
                                 sample.filter_width);
      }
    OutputBuffers outputs(count, layout);
    bindings.local().run(input.inputs(), outputs.planes(), count);
    for (int y = 0; y < tile.height; ++y)
      for (int x = 0; x < tile.width; ++x) {
        float* pixel = image.pixels.data() + (static_cast<std::size_t>(tile.y0 + y) * width + tile.x0 + x) * 3;
        for (int c = 0; c < 3; ++c)
          pixel[c] = outputs.plane(layout.plane(OutputId::color, c))[static_cast<std::size_t>(y) * tile.width + x];
      }
    return static_cast<long>(count);
  };
  if (Status done = for_each_tile(width, height, tile_size, options.threads, render_tile, options.progress,
                                  options.cancel, options.claims);
      !done)
    return done.error();
  return image;
}

class EnvironmentFrames : public FrameRenderer {
 public:
  EnvironmentFrames(int width, int height, const RenderRequest& request) : width_(width), height_(height) {
    options_.threads = request.threads;
    options_.cancel = request.cancel;
  }

  Result<Image> render_frame(const Kernel& kernel, const std::vector<float>& params, float frame,
                             const ProgressCallback& progress, TileClaims* claims,
                             FrameReport& report) const override {
    EnvironmentRenderOptions options = options_;
    options.progress = progress;
    options.claims = claims;
    report.kernel_samples = static_cast<long>(width_) * height_;
    report.what = std::to_string(width_) + "x" + std::to_string(height_) + " panorama, " +
                  std::to_string(report.kernel_samples) + " directions";
    return render_environment(kernel, params, width_, height_, frame, options);
  }

 private:
  int width_, height_;
  EnvironmentRenderOptions options_;
};

// Longitude and latitude of a unit direction, each over [0, 1].
glm::vec2 longitude_latitude(const glm::vec3& direction) {
  return {(std::atan2(direction.x, -direction.z) + pi) / (2.0f * pi),
          std::asin(std::clamp(direction.y, -1.0f, 1.0f)) / pi + 0.5f};
}

}  // namespace

void store_environment_sample(SampleBuffers& buffers, std::size_t i, const glm::vec3& direction, float filter_width) {
  for (GlobalId id : {GlobalId::I, GlobalId::P})
    if (buffers.has(id))
      for (int c = 0; c < 3; ++c) buffers.plane(id, c)[i] = direction[c];
  if (buffers.has(GlobalId::N))
    for (int c = 0; c < 3; ++c) buffers.plane(GlobalId::N, c)[i] = -direction[c];
  if (buffers.has(GlobalId::uv)) {
    const glm::vec2 uv = longitude_latitude(direction);
    for (int c = 0; c < 2; ++c) buffers.plane(GlobalId::uv, c)[i] = uv[c];
  }
  if (buffers.has(GlobalId::filter_width)) buffers.plane(GlobalId::filter_width)[i] = filter_width;
}

PointSample environment_sample_at(const Graph&, std::pair<int, int> size, const float at[3], SampleBuffers& buffers) {
  const glm::vec3 point(at[0], at[1], at[2]);
  const float length = glm::length(point);
  const glm::vec3 direction = length > 0.0f && std::isfinite(length) ? point / length : glm::vec3(0, 0, -1);
  const float filter_width = pi / static_cast<float>(size.second);
  store_environment_sample(buffers, 0, direction, filter_width);
  const glm::vec2 uv = longitude_latitude(direction);
  return {{direction.x, direction.y, direction.z}, {uv.x, uv.y}, filter_width};
}

glm::vec3 panorama_direction(float x, float y, int width, int height) {
  const float longitude = 2.0f * pi * x / static_cast<float>(width) - pi;
  const float latitude = 0.5f * pi - pi * y / static_cast<float>(height);
  return {std::sin(longitude) * std::cos(latitude), std::sin(latitude), -std::cos(longitude) * std::cos(latitude)};
}

Result<Image> render_environment(const Kernel& kernel, const std::vector<float>& params, int width, int height,
                                 float frame, const EnvironmentRenderOptions& options) {
  const float filter_width = pi / static_cast<float>(height);
  return render_directions(kernel, params, width, height, frame, options, [&](int x, int y) {
    return DirectionSample{panorama_direction(x + 0.5f, y + 0.5f, width, height), filter_width};
  });
}

Result<std::shared_ptr<const EnvironmentBackground>> EnvironmentBackground::load(
    const std::string& file, const std::string& graph_file, const std::vector<std::string>& search_paths) {
  Result<std::string> path = resolve_graph_resource(graph_file, file, search_paths, "scene environment");
  if (!path) return path.error();
  Result<LoadedGraph> loaded = load_and_compile(*path, {}, {}, graph_files(search_paths));
  if (!loaded) return loaded.error();
  if (loaded->graph->kind != GraphKind::environment)
    return Diagnostic{ExitStatus::invalid_input, graph_file, {}, {},
                      "scene environment " + file + " is " + a_graph_of(loaded->graph->kind) +
                          ", not an environment graph"};
  auto background = std::make_shared<EnvironmentBackground>();
  Result<std::unique_ptr<Kernel>> kernel = make_jit_kernel(loaded->ir);
  if (!kernel) return kernel.error();
  background->params_ = std::move(loaded->params);
  background->kernel_ = std::move(*kernel);
  return std::shared_ptr<const EnvironmentBackground>(std::move(background));
}

Result<std::shared_ptr<const EnvironmentBackground>> EnvironmentBackground::of_scene(
    const SceneDesc& scene, const std::string& graph_file, const std::vector<std::string>& search_paths) {
  if (scene.environment.empty()) return std::shared_ptr<const EnvironmentBackground>();
  return load(scene.environment, graph_file, search_paths);
}

Result<Image> EnvironmentBackground::seen_by(const Camera& camera, int width, int height, float frame,
                                             const EnvironmentRenderOptions& options) const {
  // A pixel's filter width is the angle between its ray and its neighbour's.
  return render_directions(*kernel_, params_, width, height, frame, options, [&](int x, int y) {
    const glm::vec3 direction = glm::normalize(camera.ray(x + 0.5f, y + 0.5f).direction);
    const glm::vec3 neighbour = glm::normalize(camera.ray(x + 1.5f, y + 0.5f).direction);
    return DirectionSample{direction, glm::length(neighbour - direction)};
  });
}

Result<std::optional<Image>> environment_seen_by(const EnvironmentBackground* environment, const Camera& camera,
                                                 int width, int height, float frame,
                                                 const EnvironmentRenderOptions& options) {
  if (!environment) return std::optional<Image>();
  Result<Image> seen = environment->seen_by(camera, width, height, frame, options);
  if (!seen) return seen.error();
  return std::optional<Image>(std::move(*seen));
}

Result<std::unique_ptr<FrameRenderer>> prepare_environment(const Graph& graph, const RenderRequest& request) {
  const auto [width, height] = request.size.value_or(std::pair{graph.render.width, graph.render.height});
  return std::unique_ptr<FrameRenderer>(std::make_unique<EnvironmentFrames>(width, height, request));
}

}  // namespace shadetree

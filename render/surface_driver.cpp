#include "render/surface_driver.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include <glm/geometric.hpp>

#include "render/environment_driver.h"
#include "scene/lighting.h"
#include "scene/preview_scene.h"
#include "render/pixel_hash.h"
#include "schedule/stage_clock.h"
#include "schedule/image_tiles.h"
#include "schedule/thread_bindings.h"

namespace shadetree {
namespace {

// 32 x 32 pixels: a kernel call of ~1000 visible samples per sample per
// pixel keeps the lanes full and the planes in cache.
constexpr int tile_size = 32;
constexpr float max_filter_width = 1e6f;  // at grazing angles the footprint is unbounded

// Where in pixel (column, row) sample `index` of `count` lies, in [0, 1)^2:
// the centre for one sample, else jittered, stratified on a grid where
// `count` is a square.
glm::vec2 sample_offset(int column, int row, int index, int count) {
  if (count == 1) return {0.5f, 0.5f};
  const std::uint32_t seed = pixel_hash(column, row, index);
  const glm::vec2 jitter(unit_float(seed), unit_float(hash32(seed)));
  const int grid = static_cast<int>(std::sqrt(static_cast<float>(count)));
  if (grid * grid != count) return jitter;
  return (glm::vec2(static_cast<float>(index % grid), static_cast<float>(index / grid)) + jitter) /
         static_cast<float>(grid);
}

// A visible sample: its pixel, its hit and the primary ray.
struct VisibleSample {
  int pixel = 0;  // in the tile
  SceneHit hit;
  glm::vec3 direction{0.0f};         // of the primary ray, unit, world
  glm::vec3 geometric_normal{0.0f};  // world, toward the viewer
  bool back_face = false;
  float filter_width = 0.0f;
};

// The pixel's footprint on the surface (ray differentials, Igehy 1999):
// where the rays through the neighbouring sample positions meet the
// tangent plane at the hit, in the units of object-space P.
float footprint(const Camera& camera, const SceneHit& hit, float x, float y, float step) {
  float width = 0.0f;
  for (const Ray& neighbour : {camera.ray(x + step, y), camera.ray(x, y + step)}) {
    const float facing = glm::dot(neighbour.direction, hit.world_normal);
    if (std::fabs(facing) < 1e-12f) return max_filter_width;
    const float t = glm::dot(hit.world_point - neighbour.origin, hit.world_normal) / facing;
    const glm::vec3 world_offset = neighbour.origin + t * neighbour.direction - hit.world_point;
    const glm::vec3 object_offset = glm::mat3(hit.object->world_to_object) * world_offset;
    width = std::max(width, glm::length(object_offset));
  }
  return std::isfinite(width) ? std::min(width, max_filter_width) : max_filter_width;
}

glm::vec3 read3(const OutputBuffers& outputs, const OutputLayout& layout, OutputId id, std::size_t i) {
  return {outputs.plane(layout.plane(id, 0))[i], outputs.plane(layout.plane(id, 1))[i],
          outputs.plane(layout.plane(id, 2))[i]};
}

void store3(SampleBuffers& buffers, GlobalId id, std::size_t i, const glm::vec3& value) {
  if (!buffers.has(id)) return;
  for (int c = 0; c < 3; ++c) buffers.plane(id, c)[i] = value[c];
}

class SurfaceFrames : public FrameRenderer {
 public:
  SurfaceFrames(Scene scene, std::shared_ptr<const EnvironmentBackground> environment, const SurfaceView& view,
                const RenderRequest& request)
      : scene_(std::move(scene)), environment_(std::move(environment)),
        camera_(scene_.desc().camera, view.width, view.height), view_(view) {
    options_.threads = request.threads;
    options_.shadows = request.shadows != ShadowMode::off;
    options_.cancel = request.cancel;
  }

  Result<Image> render_frame(const Kernel& kernel, const std::vector<float>& params, float frame,
                             const ProgressCallback& progress, TileClaims* claims,
                             FrameReport& report) const override {
    SurfaceView view = view_;
    view.frame = frame;
    SurfaceRenderOptions options = options_;
    options.progress = progress;
    options.claims = claims;
    Result<std::optional<Image>> background = environment_seen_by(
        environment_.get(), camera_, view.width, view.height, frame, {options.threads, {}, options.cancel});
    if (!background) return background.error();
    if (*background) options.background = &**background;
    SurfaceRenderStats stats;
    Result<Image> image = render_surface(kernel, params, scene_, camera_, view, options, &stats);
    report.kernel_samples = stats.visible_samples;
    report.kernel_seconds = stats.shading_seconds;
    report.figures = {{"visible_samples", static_cast<double>(stats.visible_samples)},
                      {"visibility_s", stats.visibility_seconds},
                      {"shading_s", stats.shading_seconds},
                      {"lighting_s", stats.lighting_seconds}};
    char text[256];
    std::snprintf(text, sizeof text, "%dx%d x %d spp, %ld visible samples", view.width, view.height,
                  view.samples_per_pixel, stats.visible_samples);
    report.what = text;
    std::snprintf(text, sizeof text,
                  "thread time: visibility %.3f s, shading %.3f s = %.2f M samples/s, lighting %.3f s",
                  stats.visibility_seconds, stats.shading_seconds,
                  stats.shading_seconds > 0 ? static_cast<double>(stats.visible_samples) / stats.shading_seconds / 1e6
                                            : 0.0,
                  stats.lighting_seconds);
    report.details = text;
    return image;
  }

 private:
  Scene scene_;
  std::shared_ptr<const EnvironmentBackground> environment_;  // null: the scene's background colour
  Camera camera_;
  SurfaceView view_;
  SurfaceRenderOptions options_;
};

}  // namespace

UniformInputs surface_uniforms(const Scene& scene, float frame) {
  UniformInputs uniforms;
  uniforms.set(GlobalId::time, frame / frames_per_second);
  uniforms.set(GlobalId::frame, frame);
  if (!scene.lights().empty())
    for (int c = 0; c < 3; ++c) uniforms.set(GlobalId::light_color, scene.lights()[0].radiance[c], c);
  return uniforms;
}

Result<Image> render_surface(const Kernel& kernel, const std::vector<float>& params, const Scene& scene,
                             const Camera& camera, const SurfaceView& view, const SurfaceRenderOptions& options,
                             SurfaceRenderStats* stats) {
  const OutputLayout& layout = kernel.outputs();
  if (layout.kind != GraphKind::surface || !layout.provides(OutputId::color))
    return invalid_input("the surface driver needs a surface graph with an output \"color\"");
  const int samples_per_pixel = std::max(1, view.samples_per_pixel);
  const bool lit = scene.desc().lighting == Lighting::lit;
  const bool shadows = options.shadows && scene.desc().shadows;
  const glm::vec3 colour(scene.desc().background[0], scene.desc().background[1], scene.desc().background[2]);
  auto background = [&](int column, int row) {
    if (!options.background) return colour;
    const Image& image = *options.background;
    const float* pixel = image.pixels.data() + (static_cast<std::size_t>(row) * image.width + column) * 3;
    return glm::vec3(pixel[0], pixel[1], pixel[2]);
  };
  const float step = 1.0f / std::sqrt(static_cast<float>(samples_per_pixel));

  Image image;
  image.width = view.width;
  image.height = view.height;
  image.channels = 3;
  image.pixels.assign(static_cast<std::size_t>(view.width) * view.height * 3, 0.0f);

  std::atomic<long long> visibility_ns{0}, shading_ns{0}, lighting_ns{0};
  std::atomic<long> visible_total{0};
  ThreadBindings bindings(kernel, params.data(), surface_uniforms(scene, view.frame));

  auto render_tile = [&](const Tile& tile) -> long {
    const int x0 = tile.x0, y0 = tile.y0, w = tile.width, h = tile.height;
    std::vector<glm::vec3> sums(static_cast<std::size_t>(w) * h, glm::vec3(0.0f));
    std::vector<VisibleSample> visible;
    {
      StageClock clock(visibility_ns);
      for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
          for (int s = 0; s < samples_per_pixel; ++s) {
            const glm::vec2 offset = sample_offset(x0 + x, y0 + y, s, samples_per_pixel);
            const float px = static_cast<float>(x0 + x) + offset.x, py = static_cast<float>(y0 + y) + offset.y;
            const Ray ray = camera.ray(px, py);
            std::optional<SceneHit> hit = scene.intersect(ray, 0.0f, std::numeric_limits<float>::infinity());
            if (!hit) {
              sums[static_cast<std::size_t>(y) * w + x] += background(x0 + x, y0 + y);
              continue;
            }
            VisibleSample& sample = visible.emplace_back();
            sample.pixel = y * w + x;
            sample.hit = *hit;
            sample.direction = ray.direction;
            // Two-sided: the graph and the lights see the side facing the
            // viewer (the inside of a vase, the underside of a plane).
            sample.back_face = glm::dot(hit->world_normal, ray.direction) > 0.0f;
            sample.geometric_normal = sample.back_face ? -hit->world_normal : hit->world_normal;
            sample.filter_width = footprint(camera, *hit, px, py, step);
          }
        }
      }
    }
    const std::size_t count = visible.size();
    visible_total += static_cast<long>(count);
    if (count > 0) {
      SampleBuffers inputs(count, kernel.reads());
      OutputBuffers outputs(count, layout);
      {
        StageClock clock(shading_ns);
        for (std::size_t i = 0; i < count; ++i) {
          const VisibleSample& sample = visible[i];
          const SceneObject& object = *sample.hit.object;
          const glm::mat3 to_object(object.world_to_object);
          store3(inputs, GlobalId::P, i, sample.hit.object_point);
          store3(inputs, GlobalId::N, i, sample.back_face ? -sample.hit.object_normal : sample.hit.object_normal);
          store3(inputs, GlobalId::I, i, glm::normalize(to_object * sample.direction));
          if (inputs.has(GlobalId::L)) {
            glm::vec3 l(0.0f, 1.0f, 0.0f);  // no lights: straight up
            if (!scene.lights().empty()) {
              float distance = 0.0f;
              l = direction_to_light(scene.lights()[0], sample.hit.world_point, &distance);
            }
            store3(inputs, GlobalId::L, i, glm::normalize(to_object * l));
          }
          if (inputs.has(GlobalId::uv)) {
            inputs.plane(GlobalId::uv, 0)[i] = sample.hit.uv.x;
            inputs.plane(GlobalId::uv, 1)[i] = sample.hit.uv.y;
          }
          if (inputs.has(GlobalId::surface)) inputs.plane(GlobalId::surface)[i] = static_cast<float>(object.id);
          if (inputs.has(GlobalId::filter_width)) inputs.plane(GlobalId::filter_width)[i] = sample.filter_width;
        }
        bindings.local().run(inputs.inputs(), outputs.planes(), count);
      }
      StageClock clock(lighting_ns);
      for (std::size_t i = 0; i < count; ++i) {
        const VisibleSample& sample = visible[i];
        SurfaceMaterial material;
        material.color = read3(outputs, layout, OutputId::color, i);
        glm::vec3 result = material.color;
        if (lit) {
          if (layout.provides(OutputId::specular)) material.specular = outputs.plane(layout.plane(OutputId::specular))[i];
          if (layout.provides(OutputId::roughness))
            material.roughness = outputs.plane(layout.plane(OutputId::roughness))[i];
          if (layout.provides(OutputId::emission)) material.emission = read3(outputs, layout, OutputId::emission, i);
          LitPoint point;
          point.point = sample.hit.world_point;
          point.geometric_normal = sample.geometric_normal;
          point.to_viewer = -sample.direction;
          point.shading_normal = sample.geometric_normal;
          if (layout.provides(OutputId::normal)) {
            // The graph's normal is in object space, like the N it read.
            const glm::vec3 normal = sample.hit.object->normal_to_world * read3(outputs, layout, OutputId::normal, i);
            const float length = glm::length(normal);
            if (length > 0.0f && std::isfinite(length)) point.shading_normal = normal / length;
          }
          result = light_point(scene, material, point, shadows);
        }
        if (layout.provides(OutputId::opacity)) {
          const float opacity = std::clamp(outputs.plane(layout.plane(OutputId::opacity))[i], 0.0f, 1.0f);
          result = opacity * result + (1.0f - opacity) * background(x0 + sample.pixel % w, y0 + sample.pixel / w);
        }
        sums[static_cast<std::size_t>(sample.pixel)] += result;
      }
    }
    const float weight = 1.0f / static_cast<float>(samples_per_pixel);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        float* pixel = image.pixels.data() + (static_cast<std::size_t>(y0 + y) * view.width + (x0 + x)) * 3;
        const glm::vec3 value = sums[static_cast<std::size_t>(y) * w + x] * weight;
        for (int c = 0; c < 3; ++c) pixel[c] = value[c];
      }
    return static_cast<long>(w) * h * samples_per_pixel;
  };
  if (Status done = for_each_tile(view.width, view.height, tile_size, options.threads, render_tile, options.progress,
                                  options.cancel, options.claims);
      !done)
    return done.error();
  if (stats) {
    stats->visibility_seconds = seconds(visibility_ns);
    stats->shading_seconds = seconds(shading_ns);
    stats->lighting_seconds = seconds(lighting_ns);
    stats->visible_samples = visible_total.load();
    stats->samples = static_cast<long>(view.width) * view.height * samples_per_pixel;
  }
  return image;
}

Result<std::unique_ptr<FrameRenderer>> prepare_surface(const Graph& graph, const RenderRequest& request) {
  std::vector<std::string> search_paths = request.search_paths;
  Result<SceneDesc> desc = surface_scene_desc(graph);
  if (!request.object.empty()) {
    desc = preview_scene(request.object);
    // A mesh named in the request is the user's own choice of file.
    if (desc && desc->objects[0].type == ObjectType::mesh)
      search_paths.push_back(std::filesystem::path(desc->objects[0].mesh_file).parent_path().string());
  }
  if (!desc) return desc.error();
  Result<Scene> scene = Scene::build(*desc, graph.file, search_paths);
  if (!scene) return scene.error();
  auto environment = EnvironmentBackground::of_scene(*desc, graph.file, search_paths);
  if (!environment) return environment.error();
  SurfaceView view;
  view.width = request.size ? request.size->first : graph.render.width;
  view.height = request.size ? request.size->second : graph.render.height;
  view.samples_per_pixel = request.samples_per_pixel;
  return std::unique_ptr<FrameRenderer>(std::make_unique<SurfaceFrames>(std::move(*scene), std::move(*environment), view, request));
}

}  // namespace shadetree

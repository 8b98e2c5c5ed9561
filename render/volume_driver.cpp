#include "render/volume_driver.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include <tbb/enumerable_thread_specific.h>

#include <glm/geometric.hpp>

#include "graph/parse_volume.h"
#include "platform/user_cache.h"
#include "interp/interval_program.h"
#include "render/density_gradient.h"
#include "render/environment_driver.h"
#include "schedule/image_tiles.h"
#include "scene/lighting.h"
#include "scene/specular_lobe_table.h"
#include "render/occupancy_grid.h"
#include "render/occupancy_grid_cache.h"
#include "render/pixel_hash.h"
#include "render/ray_lanes.h"
#include "render/transmittance_grid.h"
#include "schedule/stage_clock.h"
#include "schedule/thread_arena.h"
#include "schedule/thread_bindings.h"

namespace shadetree {
namespace {

constexpr int tile_size = 32;
// Samples fainter than this (opacity per reference step times the ray's
// remaining transmittance) send no shadow rays.
constexpr float shadow_weight_cutoff = 1.0f / 64.0f;

// What a ray of the march keeps beside its lanes (render/ray_lanes.h):
// where it sets out, what only some of its samples read, and what it
// gathered once it ends.
struct MarchingRay {
  RayFrame frame;  // its unit direction (its lanes' `along`) and two perpendiculars
  glm::vec3 origin{0.0f};
  float entry = 0.0f, exit = 0.0f;
  float jitter = 0.5f;
  int first_segment = 0;  // -1: the probe before the entry, for the first gradient
  // Each light as the ray's samples see it: a directional light's is the
  // ray's own, set at its first shaded sample and again after it bends; a
  // point light's is set at each shaded sample.
  LightSeen* lights_seen = nullptr;
  bool sees_lights = false;  // lights_seen holds the directional lights along `frame`
  float ior = 1.0f;  // the refractive index the ray is travelling through
  // The density's slopes across the ray at its last probed sample, which
  // its faint samples take (VolumeRenderOptions::faint_normals).
  glm::vec2 across_slopes{0.0f};
  bool probed = false;  // along `frame`, since the ray set out or last bent
  int pixel = 0;  // in the tile
  std::optional<SceneHit> backdrop;  // the opaque object the ray meets (its march ends there)
  // Once it has ended: what it gathered, and whether it had segments left.
  glm::vec3 color{0.0f};
  float alpha = 0.0f;
  bool segments_left = false;
};

// The three planes of a vector global in a batch's inputs, looked up once
// for a loop over its samples (none where the kernel does not read it).
class Planes3 {
 public:
  Planes3(SampleBuffers& buffers, GlobalId id) {
    if (buffers.has(id))
      for (int c = 0; c < 3; ++c) planes_[c] = buffers.plane(id, c);
  }
  void store(std::size_t i, const glm::vec3& value) const {
    if (!planes_[0]) return;
    for (int c = 0; c < 3; ++c) planes_[c][i] = value[c];
  }

 private:
  float* planes_[3] = {nullptr, nullptr, nullptr};
};


// The planes of one batch of samples and their outputs, with the planes
// that are the same for every sample filled once.
struct Batch {
  Batch(std::size_t capacity, const Kernel& kernel, float step)
      : inputs(capacity, kernel.reads()), outputs(capacity, kernel.outputs()) {
    if (inputs.has(GlobalId::filter_width)) std::fill_n(inputs.plane(GlobalId::filter_width), capacity, step);
  }
  SampleBuffers inputs;
  OutputBuffers outputs;
};

// The plane of the graph's opacity (default: its density) in a batch's
// outputs, and a sample's opacity in [0, 1] from it.
const float* opacity_plane(const OutputLayout& layout, const Batch& batch) {
  const OutputId id = layout.provides(OutputId::opacity) ? OutputId::opacity : OutputId::density;
  return batch.outputs.plane(layout.plane(id));
}
float unit_opacity(float opacity) { return std::clamp(opacity, 0.0f, 1.0f); }

// The vector lanes a kernel call on `count` samples occupies, `width` at a
// time (0: not counted).
std::size_t lane_slots_of(std::size_t count, int width) {
  if (width <= 0) return 0;
  const std::size_t lanes = static_cast<std::size_t>(width);
  return (count + lanes - 1) / lanes * lanes;
}

// The transmittance grid of each light that has one (render/transmittance_grid.h).
using LightGrids = std::vector<std::optional<TransmittanceGrid>>;

// Statistics of one thread's tiles, added to the totals once per tile.
struct TileCounts {
  long rays = 0, rays_ended_early = 0, density_samples = 0, gradient_samples = 0, shadow_samples = 0,
       shadow_lookups = 0, skipped_samples = 0, kernel_calls = 0, lane_slots = 0;
  long long kernel_ns = 0;    // in the kernel calls
  long long gradient_ns = 0;  // of those, in the calls of the gradients (probes or normal kernel)
  std::array<long long, march_stage_count> stage_ns{};  // the march's own, by MarchStage
};

// Nanoseconds since `start`.
long long nanoseconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start).count();
}

// The thread time of one stage of the march, without the kernel calls
// made in it (they are the kernel's time), into counts.stage_ns.
class MarchStageClock {
 public:
  MarchStageClock(TileCounts& counts, MarchStage stage)
      : counts_(counts),
        stage_(static_cast<std::size_t>(stage)),
        kernel_ns_before_(counts.kernel_ns),
        start_(std::chrono::steady_clock::now()) {}
  ~MarchStageClock() { counts_.stage_ns[stage_] += nanoseconds_since(start_) - (counts_.kernel_ns - kernel_ns_before_); }
  MarchStageClock(const MarchStageClock&) = delete;
  MarchStageClock& operator=(const MarchStageClock&) = delete;

 private:
  TileCounts& counts_;
  std::size_t stage_;
  long long kernel_ns_before_;
  std::chrono::steady_clock::time_point start_;
};

// A ray from a shaded sample toward a light, through the volume.
struct ShadowRay {
  glm::vec3 origin{0.0f}, direction{0.0f};
  float t = 0.0f, end = 0.0f;  // the next segment's start; where the ray leaves the box or meets the light
  float transmittance = 1.0f;
  int segments_left = 0;  // the march's budget: however t rounds, it ends
  float occupied_until = -std::numeric_limits<float>::infinity();  // no need to look for empty space before
  std::size_t slot = 0;  // in the step's transmittance list
  // The light's transmittance grid, whose lookup the ray tries again from
  // `lookups_from` on: the rest of its way to the light, where the grid's
  // rays agree, is read there instead of marched.
  const TransmittanceGrid* grid = nullptr;
  float lookups_from = 0.0f;

  // Where the sample of the next segment, `step` long but clipped at the end, lies.
  float sample_t(float step) const { return t + 0.5f * std::min(step, end - t); }
};

// An opaque object seen at a pixel, through what the volume in front of
// it lets through.
struct ObjectSample {
  int pixel = 0;  // in the tile
  SceneHit hit;
  glm::vec3 to_viewer{0.0f};
  float weight = 1.0f;  // 1 - the alpha of the volume in front
};

// A shadow ray left to march where a lookup met a shadow's edge marches
// this many of the grid's ray spacings before it tries to read the rest
// of its way to the light from the grid: clear of the bumps around where
// it started, which the grid's rays there may pass through. From 1.4 (a
// lookup's own normal offset) noisy_sphere_hiamp's 99th percentile
// difference from exact shadows at 128x128 was 4.1/255; from 6, under 4.
// The furry volumes march 25% more shadow samples for it than from 1.4.
constexpr float marched_spacings_before_lookups = 6.0f;

// What one step of the march knows of each live ray's sample, gathered
// once for every stage of the step (kept from step to step, so that no
// step allocates): where it lies, what the kernel found there, its normal
// and what reaches it of each light.
struct StepSamples {
  std::vector<float> t;
  std::vector<float> at[3];  // the sample's place, a plane per axis
  std::vector<glm::vec3> normal;
  std::vector<float> density, opacity;  // opacity in [0, 1]
  std::vector<std::size_t> soft;        // the samples lit by their normal
  std::vector<std::size_t> probed;      // of those (as indices into soft), the ones probed
  std::vector<float> transmittance;     // lights per sample
  std::vector<ShadowRay> shadow_rays;
  std::vector<std::size_t> shaded;      // the samples that add to their ray: a segment's, opacity above 0
  std::vector<glm::vec3> color;         // what each of those adds, lit, before its alpha

  glm::vec3 point(std::size_t i) const { return {at[0][i], at[1][i], at[2][i]}; }
};

// What one tile's march works in: the batches of its kernel calls (march
// samples, gradient probes, shadow samples), its kernel binding and its
// statistics.
struct TileScratch {
  TileScratch(std::size_t packet, std::size_t lights, const Kernel& kernel, float step, BoundKernel& bound,
              BoundKernel* normal_bound)
      : samples(packet, kernel, step),
        probes(2 * packet, kernel, step),
        shadows(packet * std::max<std::size_t>(lights, 1), kernel, step),
        lanes(step),
        bound(bound),
        normal_bound(normal_bound) {}
  Batch samples, probes, shadows;
  RayLanes lanes;
  StepSamples step;
  BoundKernel& bound;
  BoundKernel* normal_bound;  // of VolumeRenderOptions::normal_kernel, where there is one
  TileCounts counts;
};

class Marcher {
 public:
  Marcher(const Kernel& kernel, const Scene& scene, const VolumeDesc& volume, float step, float reference_step,
          float shadow_step, bool jitter, bool shadows, const OccupancyGrid* occupancy, const LightGrids& grids,
          const VolumeRenderOptions& options)
      : kernel_(kernel),
        layout_(kernel.outputs()),
        scene_(scene),
        lo_(volume.bounds_min[0], volume.bounds_min[1], volume.bounds_min[2]),
        hi_(volume.bounds_max[0], volume.bounds_max[1], volume.bounds_max[2]),
        step_(step),
        reference_step_(reference_step),
        shadow_step_(shadow_step),
        jitter_(jitter),
        lit_(scene.desc().lighting == Lighting::lit),
        shadows_(lit_ && shadows && !scene.lights().empty()),
        refracts_(kernel.outputs().provides(OutputId::ior)),
        own_normals_(kernel.outputs().provides(OutputId::normal)),
        occupancy_(occupancy),
        grids_(grids),
        options_(options),
        // At most a half: a ray that ends early has then met at least as
        // much as it extrapolates, and its alpha is no 0 to divide by.
        extrapolation_(std::clamp(options.extrapolation, 0.0f, 0.5f)),
        // A refracting ray bends about its normals: all of them probed.
        faint_normals_(refracts_ ? 0.0f : options.faint_normals),
        background_(scene.desc().background[0], scene.desc().background[1], scene.desc().background[2]),
        ambient_(scene.desc().ambient[0], scene.desc().ambient[1], scene.desc().ambient[2]),
        objects_shadow_(shadows_ && !scene.objects().empty()),
        exact_specular_(options.exact_specular) {}

  // What a pixel's ray sees behind the volume where it meets no object.
  glm::vec3 background(int column, int row) const {
    if (!options_.background) return background_;
    const Image& image = *options_.background;
    const float* pixel = image.pixels.data() + (static_cast<std::size_t>(row) * image.width + column) * 3;
    return {pixel[0], pixel[1], pixel[2]};
  }

  // The tile's pixels, RGB, row after row.
  void render_tile(const Tile& tile, const Camera& camera, BoundKernel& bound, BoundKernel* normal_bound,
                   std::vector<glm::vec3>& pixels, TileCounts& counts) const {
    std::optional<MarchStageClock> setting_up(std::in_place, counts, MarchStage::rays);
    const std::size_t lights = scene_.lights().size();
    pixels.resize(static_cast<std::size_t>(tile.width) * tile.height);
    for (int y = 0; y < tile.height; ++y)
      for (int x = 0; x < tile.width; ++x)
        pixels[static_cast<std::size_t>(y) * tile.width + x] = background(tile.x0 + x, tile.y0 + y);
    std::vector<MarchingRay> rays;
    std::vector<ObjectSample> objects;
    for (int y = 0; y < tile.height; ++y)
      for (int x = 0; x < tile.width; ++x) {
        const int column = tile.x0 + x, row = tile.y0 + y;
        const Ray ray = camera.ray(static_cast<float>(column) + 0.5f, static_cast<float>(row) + 0.5f);
        const std::optional<SceneHit> hit = first_object(ray, 0.0f);
        const std::optional<Span> span = clip_to_box(ray, lo_, hi_);
        if (!span || span->far <= 0.0f || (hit && hit->t <= span->near)) {
          if (hit) {
            objects.push_back(ObjectSample{y * tile.width + x, *hit, -ray.direction, 1.0f});
            pixels[static_cast<std::size_t>(y) * tile.width + x] = glm::vec3(0.0f);  // the object covers it
          }
          continue;
        }
        MarchingRay& marching = rays.emplace_back();
        marching.pixel = y * tile.width + x;
        marching.origin = ray.origin;
        marching.frame = ray_frame(ray.direction);
        marching.entry = std::max(span->near, 0.0f);
        marching.exit = hit ? std::min(span->far, hit->t) : span->far;
        marching.backdrop = hit;
        if (jitter_) marching.jitter = unit_float(pixel_hash(column, row, 0));
        marching.first_segment = probes_gradients() ? -1 : 0;
      }
    counts.rays += static_cast<long>(rays.size());
    std::vector<LightSeen> lights_seen(rays.size() * lights);
    for (std::size_t i = 0; i < rays.size(); ++i) rays[i].lights_seen = lights_seen.data() + i * lights;
    if (rays.empty() && objects.empty()) return;
    // Objects are shaded in batches of the packet size too; there are at
    // most as many as the rays and the pixels without volume.
    const std::size_t tile_rays = rays.size() + objects.size();
    const std::size_t packet = std::min(
        tile_rays, options_.packet_rays > 0 ? static_cast<std::size_t>(options_.packet_rays) : tile_rays);
    TileScratch scratch(packet, lights, kernel_, step_, bound, normal_bound);
    setting_up.reset();
    RayLanes& lanes = scratch.lanes;
    for (std::size_t first = 0; first < rays.size(); first += packet) {
      const std::size_t last = std::min(rays.size(), first + packet);
      for (std::size_t i = first; i < last; ++i) {
        const MarchingRay& ray = rays[i];
        lanes.add(ray.origin, ray.frame.along, ray.entry, ray.exit, ray.jitter, ray.first_segment,
                  static_cast<std::uint32_t>(i));
      }
      while (!lanes.empty()) march_once(lanes, rays, scratch);
      for (std::size_t i = first; i < last; ++i) {
        const MarchingRay& ray = rays[i];
        const std::size_t pixel = static_cast<std::size_t>(ray.pixel);
        // A ray that ended early (with segments left, not yet opaque):
        // the rest as bright as what it met.
        if (ray.segments_left && ray.alpha < 1.0f - options_.termination) {
          pixels[pixel] = ray.color / ray.alpha;
          ++counts.rays_ended_early;
          continue;
        }
        pixels[pixel] = ray.color;
        if (ray.backdrop && ray.alpha < 1.0f - options_.termination)
          objects.push_back(ObjectSample{ray.pixel, *ray.backdrop, -ray.frame.along, 1.0f - ray.alpha});
        else
          pixels[pixel] +=
              (1.0f - ray.alpha) * background(tile.x0 + ray.pixel % tile.width, tile.y0 + ray.pixel / tile.width);
      }
    }
    for (std::size_t first = 0; first < objects.size(); first += packet)
      shade_objects(objects, first, std::min(objects.size(), first + packet), pixels, scratch);
    const TileCounts& marched = scratch.counts;
    counts.density_samples += marched.density_samples;
    counts.gradient_samples += marched.gradient_samples;
    counts.gradient_ns += marched.gradient_ns;
    counts.shadow_samples += marched.shadow_samples;
    counts.shadow_lookups += marched.shadow_lookups;
    counts.skipped_samples += marched.skipped_samples;
    counts.kernel_calls += marched.kernel_calls;
    counts.lane_slots += marched.lane_slots;
    counts.kernel_ns += marched.kernel_ns;
    for (std::size_t stage = 0; stage < march_stage_count; ++stage) counts.stage_ns[stage] += marched.stage_ns[stage];
  }

 private:
  // The nearest opaque object on the ray past t_min.
  std::optional<SceneHit> first_object(const Ray& ray, float t_min) const {
    if (scene_.objects().empty()) return std::nullopt;
    return scene_.intersect(ray, t_min, std::numeric_limits<float>::infinity());
  }

  // The opaque objects of samples [first, last), lit by the scene's lights
  // through the volume (its shadow falls on them) and composited under
  // what the volume in front of them added to their pixels.
  void shade_objects(const std::vector<ObjectSample>& objects, std::size_t first, std::size_t last,
                     std::vector<glm::vec3>& pixels, TileScratch& scratch) const {
    const std::size_t lights = scene_.lights().size();
    std::vector<LitPoint> points(last - first);
    std::vector<float> transmittance((last - first) * lights, 1.0f);
    std::vector<ShadowRay> shadow_rays;
    for (std::size_t k = first; k < last; ++k) {
      const ObjectSample& sample = objects[k];
      LitPoint& point = points[k - first];
      point.point = sample.hit.world_point;
      point.to_viewer = sample.to_viewer;
      // Two-sided, as in the surface driver: the side facing the viewer.
      point.geometric_normal = glm::dot(sample.hit.world_normal, sample.to_viewer) < 0.0f ? -sample.hit.world_normal
                                                                                          : sample.hit.world_normal;
      point.shading_normal = point.geometric_normal;
    }
    if (shadows_) {
      MarchStageClock clock(scratch.counts, MarchStage::shadows);
      for (std::size_t k = first; k < last; ++k) {
        const LitPoint& point = points[k - first];
        const float offset = 1e-4f * (1.0f + glm::length(point.point));
        shadow_from(point.point, point.geometric_normal, offset, 0.0f, (k - first) * lights, transmittance,
                    shadow_rays, scratch.counts);
      }
      march_shadows(shadow_rays, transmittance, scratch);
    }
    MarchStageClock clock(scratch.counts, MarchStage::shading);
    for (std::size_t k = first; k < last; ++k) {
      const ObjectSample& sample = objects[k];
      SurfaceMaterial material;
      material.color = sample.hit.object->color;
      const glm::vec3 color =
          lit_ ? light_point(scene_, material, points[k - first], shadows_, transmittance.data() + (k - first) * lights)
               : material.color;
      pixels[static_cast<std::size_t>(sample.pixel)] += sample.weight * color;
    }
  }

  // A shadow ray from x toward light `light`, through the part of the box
  // between them; its transmittance goes to `slot`.
  void add_shadow_ray(const glm::vec3& x, std::size_t light, std::size_t slot, std::vector<ShadowRay>& rays) const {
    ShadowRay& shadow = rays.emplace_back();
    float distance = 0.0f;
    shadow.origin = x;
    shadow.direction = direction_to_light(scene_.lights()[light], x, &distance);
    const std::optional<Span> span = clip_to_box(Ray{x, shadow.direction}, lo_, hi_);
    shadow.t = std::max(span ? span->near : 0.0f, 0.0f);
    shadow.end = span ? std::min(span->far, distance) : 0.0f;
    shadow.slot = slot;
    if (light < grids_.size() && grids_[light]) {
      shadow.grid = &*grids_[light];
      shadow.lookups_from = shadow.t + marched_spacings_before_lookups * shadow.grid->spacing();
    }
  }

  // A shadow ray whose light has a grid, far enough along, reads the rest
  // of its way there where the grid's rays agree (a hair's shadow edge
  // lies behind it): true if it did, and is done.
  bool looked_up_the_rest(ShadowRay& ray, TileCounts& counts) const {
    if (!ray.grid || ray.t < ray.lookups_from) return false;
    ++counts.shadow_lookups;
    const float rest = ray.grid->at(ray.origin + ray.t * ray.direction);
    if (rest == TransmittanceGrid::edge) return false;
    ray.transmittance *= rest;
    return true;
  }

  // A shadow ray's segments whose samples lie in empty space let all the
  // light through (1 - alpha = 1 exactly): the ray steps over them as the
  // march would, one shadow step at a time, without sampling them.
  void skip_empty_space(ShadowRay& ray, TileCounts& counts) const {
    if (ray.sample_t(shadow_step_) < ray.occupied_until) return;
    const Clearance clearance =
        occupancy_->next_occupied(ray.origin, ray.direction, ray.sample_t(shadow_step_), ray.end);
    ray.occupied_until = clearance.until;
    // Once it looks the rest up, the ray tries at every step, skipping or not.
    while (ray.t < ray.end && ray.segments_left > 0 && ray.sample_t(shadow_step_) < clearance.from &&
           !(ray.grid && ray.t >= ray.lookups_from)) {
      ray.t += shadow_step_;
      --ray.segments_left;
      ++counts.skipped_samples;
    }
  }

  // A primary ray's segments whose samples lie in empty space add nothing
  // to it: it moves on to the last of them, whose sample is taken (it adds
  // nothing either) so that the next sample has the one before it for its
  // gradient, as without skipping. A refracting graph's empty space is
  // where its index is 1 as well (bound_empty_space), which bends no ray
  // travelling in index 1: such a ray skips it, any other samples it.
  void skip_empty_space(RayLanes& lanes, std::size_t lane, const std::vector<MarchingRay>& rays,
                        TileCounts& counts) const {
    const float t = lanes.sample_t(lane);
    if (lanes.segment[lane] < 0 || t < lanes.occupied_until[lane] || (refracts_ && bends(rays[lanes.record[lane]], 1.0f)))
      return;
    const Clearance clearance = occupancy_->next_occupied(lanes.origin_of(lane), lanes.along_of(lane), t, lanes.exit[lane]);
    lanes.occupied_until[lane] = clearance.until;
    counts.skipped_samples += lanes.advance_to_last_sample_before(lane, clearance.from);
  }

  // What reaches `point` of each light, from `offset` out along its
  // normal: looked up in the light's grid where it has one, else a shadow
  // ray to march (which reads the rest of its way from the grid once past
  // the shadow's edge); light l's goes to slot first + l. A lookup leaves from
  // at least `spacings` times the grid's ray spacing (a shadow map's normal
  // offset: from √2 spacings, the four light rays it interpolates pass on
  // the lit side of the point's tangent plane, where a lit surface does
  // not shadow them). A light the point's surface faces away from lights
  // nothing there (scene/lighting.h, `reaches`), so nothing is looked up or
  // marched toward it.
  void shadow_from(const glm::vec3& point, const glm::vec3& normal, float offset, float spacings, std::size_t first,
                   std::vector<float>& transmittance, std::vector<ShadowRay>& rays, TileCounts& counts) const {
    for (std::size_t l = 0; l < scene_.lights().size(); ++l) {
      float distance = 0.0f;
      if (!reaches(normal, direction_to_light(scene_.lights()[l], point, &distance))) continue;
      if (l < grids_.size() && grids_[l]) {
        ++counts.shadow_lookups;
        const float looked_up = grids_[l]->at(point + std::max(offset, spacings * grids_[l]->spacing()) * normal);
        if (looked_up != TransmittanceGrid::edge) {
          transmittance[first + l] = looked_up;
          continue;
        }
      }
      add_shadow_ray(point + offset * normal, l, first + l, rays);
    }
  }

  // The lights as `ray`'s sample at `point` sees them: the directional
  // ones as every sample of the ray does, the point lights as this one.
  const LightSeen* lights_seen_from(MarchingRay& ray, const glm::vec3& point) const {
    const glm::vec3 to_viewer = -ray.frame.along;
    for (std::size_t l = 0; l < scene_.lights().size(); ++l)
      if (!ray.sees_lights || scene_.lights()[l].type != LightType::directional)
        ray.lights_seen[l] = light_seen(scene_.lights()[l], point, to_viewer);
    ray.sees_lights = true;
    return ray.lights_seen;
  }

  // Gradients serve the lighting and the refraction.
  bool needs_gradients() const { return lit_ || refracts_; }
  // From the previous sample and two probes, which needs a sample before
  // the entry for the first gradient.
  bool probes_gradients() const { return needs_gradients() && !own_normals_ && !options_.normal_kernel; }

  // Whether a sample of index `ior` bends `ray`: where it differs from the
  // index the ray travels in.
  static bool bends(const MarchingRay& ray, float ior) { return std::fabs(ior - ray.ior) > 1e-4f; }

  // 1989 blue glass: where the refractive index of a sample differs from
  // the one the ray travels in, the ray bends by Snell's law about the
  // density gradient (or reflects, past the critical angle) and marches on
  // from the sample in its new direction, through the rest of the box.
  void refract(RayLanes& lanes, std::size_t lane, MarchingRay& ray, float t, const glm::vec3& outward, float ior) const {
    const glm::vec3 d = ray.frame.along;
    glm::vec3 n = outward;
    float cosine = -glm::dot(n, d);
    if (cosine < 0.0f) {
      n = -n;
      cosine = -cosine;
    }
    const float eta = ray.ior / ior;
    const float k = 1.0f - eta * eta * (1.0f - cosine * cosine);
    const glm::vec3 bent = k < 0.0f ? d + 2.0f * cosine * n : eta * d + (eta * cosine - std::sqrt(k)) * n;
    const float length = glm::length(bent);
    ray.ior = ior;
    if (!(length > 0.0f) || !std::isfinite(length)) return;
    const glm::vec3 origin = lanes.point(lane, t);
    const std::optional<Span> span = clip_to_box(Ray{origin, bent / length}, lo_, hi_);
    if (!span) return;
    ray.frame = ray_frame(bent / length);
    ray.sees_lights = false;
    ray.probed = false;
    ray.backdrop = first_object(Ray{origin, bent / length}, 0.0f);
    // A probe just behind, for the next gradient, then segments from here.
    lanes.set_out(lane, origin, ray.frame.along,
                  std::max(ray.backdrop ? std::min(span->far, ray.backdrop->t) : span->far, 0.0f));
  }

  // The graph's kernel (or `bound`, another of the graph's) on the first
  // `count` samples of `batch`.
  void run(Batch& batch, std::size_t count, TileScratch& scratch, BoundKernel* bound = nullptr) const {
    const auto start = std::chrono::steady_clock::now();
    (bound ? *bound : scratch.bound).run(batch.inputs.inputs(), batch.outputs.planes(), count);
    scratch.counts.kernel_ns += nanoseconds_since(start);
    scratch.counts.density_samples += static_cast<long>(count);
    scratch.counts.kernel_calls += 1;
    scratch.counts.lane_slots += static_cast<long>(lane_slots_of(count, options_.lane_width));
  }

  float output(const Batch& batch, OutputId id, std::size_t i) const {
    return batch.outputs.plane(layout_.plane(id))[i];
  }

  // 1989: alpha_k = 1 - (1 - opacity)^(length / reference step). A whole
  // segment at the reference step (every segment of a march at the
  // graph's own step, but the last) raises to the power 1, which leaves
  // the base as it is: std::pow returns it unchanged for every float in
  // [0, 1] (checked one by one), so it is not called.
  float segment_alpha(float opacity, float length) const {
    if (opacity >= 1.0f) return 1.0f;
    const float exponent = length / reference_step_;
    return 1.0f - (exponent == 1.0f ? 1.0f - opacity : std::pow(1.0f - opacity, exponent));
  }

  // Gilet & Dischler 2010's "Phong with shadows": from each shaded sample a
  // secondary march toward each light, at the reference step unless told
  // otherwise (so that the shadows do not change with the march step: a
  // draft's coarser march still has them), multiplying the light's
  // transmittance by 1 - alpha of every segment, until the ray leaves the
  // box, reaches the light or lets through less than the termination.
  void march_shadows(std::vector<ShadowRay>& rays, std::vector<float>& transmittance, TileScratch& scratch) const {
    const float shadow_step = shadow_step_;
    std::vector<ShadowRay*> live;
    for (ShadowRay& ray : rays) {
      ray.segments_left = static_cast<int>(std::min(std::ceil((ray.end - ray.t) / shadow_step), max_steps_across)) + 1;
      if (ray.t < ray.end) live.push_back(&ray);
    }
    while (!live.empty()) {
      if (occupancy_) {
        for (ShadowRay* ray : live) skip_empty_space(*ray, scratch.counts);
        live.erase(std::remove_if(live.begin(), live.end(),
                                  [](const ShadowRay* ray) { return ray->t >= ray->end || ray->segments_left <= 0; }),
                   live.end());
      }
      live.erase(std::remove_if(live.begin(), live.end(),
                                [&](ShadowRay* ray) { return looked_up_the_rest(*ray, scratch.counts); }),
                 live.end());
      if (live.empty()) break;
      const std::size_t count = live.size();
      const Planes3 points(scratch.shadows.inputs, GlobalId::P), views(scratch.shadows.inputs, GlobalId::I);
      for (std::size_t i = 0; i < count; ++i) {
        const ShadowRay& ray = *live[i];
        points.store(i, ray.origin + ray.sample_t(shadow_step) * ray.direction);
        views.store(i, ray.direction);
      }
      run(scratch.shadows, count, scratch);
      scratch.counts.shadow_samples += static_cast<long>(count);
      const float* opacities = opacity_plane(layout_, scratch.shadows);
      for (std::size_t i = 0; i < count; ++i) {
        ShadowRay& ray = *live[i];
        ray.transmittance *= 1.0f - segment_alpha(unit_opacity(opacities[i]), std::min(shadow_step, ray.end - ray.t));
        ray.t += shadow_step;
        --ray.segments_left;
      }
      live.erase(std::remove_if(live.begin(), live.end(),
                                [&](const ShadowRay* ray) {
                                  return ray->t >= ray->end || ray->segments_left <= 0 ||
                                         ray->transmittance < options_.termination;
                                }),
                 live.end());
    }
    for (const ShadowRay& ray : rays) transmittance[ray.slot] = ray.transmittance < options_.termination ? 0.0f : ray.transmittance;
  }

  // The transmittance toward each light of the samples of this step that
  // will be shaded (lights() per sample, 1 where not shadowed), in
  // step.transmittance. Shadow rays start two reference steps out along
  // the normal, clear of the sample itself, by a distance that does not
  // change with the march step.
  void light_transmittance(const RayLanes& lanes, TileScratch& scratch) const {
    StepSamples& step = scratch.step;
    const std::size_t lights = scene_.lights().size();
    step.transmittance.assign(lanes.size() * lights, 1.0f);
    if (!shadows_) return;
    MarchStageClock clock(scratch.counts, MarchStage::shadows);
    step.shadow_rays.clear();
    for (std::size_t i = 0; i < lanes.size(); ++i) {
      // A faint sample (its opacity per reference step, times what the ray
      // still lets through) is lit unshadowed: in a faint medium (glass,
      // thin smoke) every sample would otherwise send rays through all of
      // it. Per reference step, so that the choice does not follow the step.
      // (What a ray lets through is at most 1, so a faint opacity alone
      // tells, without reading the ray.)
      if (step.opacity[i] < shadow_weight_cutoff) continue;
      if (lanes.segment[i] < 0 || step.opacity[i] * (1.0f - lanes.alpha[i]) < shadow_weight_cutoff) continue;
      shadow_from(step.point(i), step.normal[i], 2.0f * reference_step_, std::sqrt(2.0f), i * lights,
                  step.transmittance, step.shadow_rays, scratch.counts);
    }
    march_shadows(step.shadow_rays, step.transmittance, scratch);
  }

  // step.normal[step.soft[k]] = the unit normal output of `batch`, run by
  // a kernel of `layout`, at sample at(k), where it has a direction.
  template <class At>
  void take_normals(const Batch& batch, const OutputLayout& layout, At at, StepSamples& step) const {
    const float* planes[3];
    for (int c = 0; c < 3; ++c) planes[c] = batch.outputs.plane(layout.plane(OutputId::normal, c));
    for (std::size_t k = 0; k < step.soft.size(); ++k) {
      glm::vec3 normal;
      for (int c = 0; c < 3; ++c) normal[c] = planes[c][at(k)];
      const float length = glm::length(normal);
      if (length > 0.0f && std::isfinite(length)) step.normal[step.soft[k]] = normal / length;
    }
  }

  // The density's exact gradient (graph/derived_normals.h): one sample of
  // the normal kernel per soft sample.
  void exact_normals(const RayLanes& lanes, TileScratch& scratch) const {
    StepSamples& step = scratch.step;
    if (step.soft.empty()) return;
    Batch& batch = scratch.probes;
    const Planes3 points(batch.inputs, GlobalId::P), views(batch.inputs, GlobalId::I);
    for (std::size_t k = 0; k < step.soft.size(); ++k) {
      points.store(k, step.point(step.soft[k]));
      views.store(k, lanes.along_of(step.soft[k]));
    }
    const long long kernel_ns_before = scratch.counts.kernel_ns;
    run(batch, step.soft.size(), scratch, scratch.normal_bound);
    scratch.counts.gradient_ns += scratch.counts.kernel_ns - kernel_ns_before;
    scratch.counts.gradient_samples += static_cast<long>(step.soft.size());
    take_normals(batch, options_.normal_kernel->outputs(), [](std::size_t k) { return k; }, step);
  }

  // 1989 section 3.1: the gradient from the previous sample along the ray
  // and two probes off it (render/density_gradient.h); a faint sample
  // takes its slopes across the ray from the ray's last probed sample
  // (VolumeRenderOptions::faint_normals).
  void probed_normals(const RayLanes& lanes, std::vector<MarchingRay>& rays, TileScratch& scratch) const {
    StepSamples& step = scratch.step;
    if (step.soft.empty()) return;
    step.probed.clear();
    for (std::size_t k = 0; k < step.soft.size(); ++k) {
      const std::size_t i = step.soft[k];
      if (!(rays[lanes.record[i]].probed && step.opacity[i] * (1.0f - lanes.alpha[i]) < faint_normals_))
        step.probed.push_back(k);
    }
    Batch& probes = scratch.probes;
    const Planes3 points(probes.inputs, GlobalId::P), views(probes.inputs, GlobalId::I);
    for (std::size_t n = 0; n < step.probed.size(); ++n) {
      const std::size_t i = step.soft[step.probed[n]];
      const MarchingRay& ray = rays[lanes.record[i]];
      points.store(2 * n, step.point(i) + step_ * ray.frame.across_v);
      points.store(2 * n + 1, step.point(i) + step_ * ray.frame.across_w);
      views.store(2 * n, ray.frame.along);
      views.store(2 * n + 1, ray.frame.along);
    }
    if (!step.probed.empty()) {
      const long long kernel_ns_before = scratch.counts.kernel_ns;
      run(probes, 2 * step.probed.size(), scratch);
      scratch.counts.gradient_ns += scratch.counts.kernel_ns - kernel_ns_before;
      scratch.counts.gradient_samples += static_cast<long>(2 * step.probed.size());
    }
    const float* probed = probes.outputs.plane(layout_.plane(OutputId::density));
    for (std::size_t n = 0; n < step.probed.size(); ++n) {
      const std::size_t i = step.soft[step.probed[n]];
      MarchingRay& ray = rays[lanes.record[i]];
      ray.across_slopes = across_slopes(step.density[i], probed[2 * n], probed[2 * n + 1], step_);
      ray.probed = true;
    }
    for (const std::size_t i : step.soft) {
      const MarchingRay& ray = rays[lanes.record[i]];
      const float along_slope =
          (step.density[i] - lanes.previous_density[i]) / std::max(step.t[i] - lanes.previous_t[i], 1e-30f);
      const glm::vec3 gradient = density_gradient(ray.frame, along_slope, ray.across_slopes);
      const float length = std::sqrt(gradient.x * gradient.x + gradient.y * gradient.y + gradient.z * gradient.z);
      if (length > 0.0f && std::isfinite(length))
        for (int c = 0; c < 3; ++c) step.normal[i][c] = -gradient[c] / length;
    }
  }

  // What each sample of the step that adds to its ray adds, before its
  // alpha (step.shaded, step.color): the graph's colour (white where it
  // has none), lit by the scene's lights where the volume is lit.
  void shade(const RayLanes& lanes, std::vector<MarchingRay>& rays, const Batch& samples, StepSamples& step) const {
    step.shaded.clear();
    for (std::size_t i = 0; i < lanes.size(); ++i)
      if (step.opacity[i] > 0.0f && lanes.segment[i] >= 0) step.shaded.push_back(i);
    step.color.resize(step.shaded.size());
    if (layout_.provides(OutputId::color)) {
      const float* planes[3];
      for (int c = 0; c < 3; ++c) planes[c] = samples.outputs.plane(layout_.plane(OutputId::color, c));
      for (std::size_t k = 0; k < step.shaded.size(); ++k)
        for (int c = 0; c < 3; ++c) step.color[k][c] = planes[c][step.shaded[k]];
    } else {
      std::fill(step.color.begin(), step.color.end(), glm::vec3(1.0f));
    }
    if (!lit_) return;
    const std::size_t lights = scene_.lights().size();
    for (std::size_t k = 0; k < step.shaded.size(); ++k) {
      const std::size_t i = step.shaded[k];
      MarchingRay& ray = rays[lanes.record[i]];
      SurfaceMaterial material;
      material.color = step.color[k];
      const glm::vec3& normal = step.normal[i];
      const float* transmittance = step.transmittance.data() + i * lights;
      const LightSeen* seen = lights_seen_from(ray, step.point(i));
      if (!objects_shadow_) {
        step.color[k] = light_unshadowed_by_objects(material, normal, transmittance, seen);
        continue;
      }
      LitPoint point;
      point.point = step.point(i);
      point.shading_normal = normal;
      point.geometric_normal = normal;
      point.to_viewer = -ray.frame.along;
      step.color[k] = light_point(scene_, material, point, shadows_, transmittance, seen);
    }
  }

  // light_point where no object can shadow the point, inlined, with the
  // material's constants taken once: the same terms (add_light_term), so the
  // same floats where the lobe's power is libm's.
  glm::vec3 light_unshadowed_by_objects(const SurfaceMaterial& material, const glm::vec3& normal,
                                        const float* transmittance, const LightSeen* seen) const {
    glm::vec3 result = ambient_ * material.color + material.emission;
    const auto power = [&](float base, float exponent) { return lobe(base, exponent); };
    for (std::size_t l = 0; l < scene_.lights().size(); ++l)
      if (lit_by(normal, normal, seen[l]))
        add_light_term(material, normal, seen[l], specular_exponent_, power,
                       transmittance[l] * scene_.lights()[l].radiance, result);
    return result;
  }

  // base^exponent for the specular lobe: libm's powf, as the reference
  // takes it; for a render that need not be the reference, from a table,
  // +0 below the floor where it adds less than 2^-16 of a light.
  float lobe(float base, float exponent) const {
    return exact_specular_ ? std::pow(base, exponent) : lobe_table_(base);
  }

  // Every live ray takes its next sample; rays that leave the volume or
  // become opaque are dropped (their record takes what they gathered).
  void march_once(RayLanes& lanes, std::vector<MarchingRay>& rays, TileScratch& scratch) const {
    Batch& samples = scratch.samples;
    StepSamples& step = scratch.step;
    const std::size_t count = lanes.size();
    std::optional<MarchStageClock> stepping(std::in_place, scratch.counts, MarchStage::stepping);
    if (occupancy_)
      for (std::size_t i = 0; i < count; ++i) skip_empty_space(lanes, i, rays, scratch.counts);
    place_samples(lanes, step);
    if (samples.inputs.has(GlobalId::P))
      for (int c = 0; c < 3; ++c) std::copy_n(step.at[c].data(), count, samples.inputs.plane(GlobalId::P, c));
    if (samples.inputs.has(GlobalId::I))
      for (int c = 0; c < 3; ++c) std::copy_n(lanes.along[c].data(), count, samples.inputs.plane(GlobalId::I, c));
    // The normal faces the viewer where the density has none (below).
    step.normal.resize(count);
    for (std::size_t i = 0; i < count; ++i) step.normal[i] = -lanes.along_of(i);
    run(samples, count, scratch);
    const float* densities = samples.outputs.plane(layout_.plane(OutputId::density));
    step.density.assign(densities, densities + count);
    step.opacity.resize(count);
    const float* opacities = opacity_plane(layout_, samples);
    for (std::size_t i = 0; i < count; ++i) step.opacity[i] = unit_opacity(opacities[i]);
    stepping.reset();

    // The outward normal where 0 < density < 1 (the samples lit by their
    // normal). Only a sample that adds to the ray is lit, so only its
    // normal is wanted, unless it may bend the ray: a hard surface's
    // opacity (a step of its density) is 0 through most of the soft shell,
    // where probing cost stf_bumps 38% of its samples.
    if (needs_gradients()) {
      MarchStageClock clock(scratch.counts, MarchStage::normals);
      step.soft.clear();
      for (std::size_t i = 0; i < count; ++i)
        if (step.density[i] > 0.0f && step.density[i] < 1.0f && (refracts_ || step.opacity[i] > 0.0f) &&
            lanes.segment[i] >= 0)
          step.soft.push_back(i);
      if (own_normals_)
        take_normals(samples, layout_, [&](std::size_t k) { return step.soft[k]; }, step);
      else if (scratch.normal_bound)
        exact_normals(lanes, scratch);
      else
        probed_normals(lanes, rays, scratch);
    }
    light_transmittance(lanes, scratch);

    MarchStageClock shading(scratch.counts, MarchStage::shading);
    shade(lanes, rays, samples, step);
    for (std::size_t k = 0; k < step.shaded.size(); ++k) {
      const std::size_t i = step.shaded[k];
      const glm::vec3& color = step.color[k];
      if (std::isfinite(color.x + color.y + color.z))
        lanes.composite(i, segment_alpha(step.opacity[i], lanes.segment_length(i)), color);
    }
    std::copy_n(step.t.data(), count, lanes.previous_t.data());
    std::copy_n(step.density.data(), count, lanes.previous_density.data());
    for (int& segment : lanes.segment) ++segment;
    if (refracts_)
      for (std::size_t i = 0; i < count; ++i) {
        if (lanes.segment[i] <= 0) continue;  // the probe before the entry bends nothing
        const float ior = std::clamp(output(samples, OutputId::ior, i), 0.1f, 10.0f);
        MarchingRay& ray = rays[lanes.record[i]];
        if (bends(ray, ior)) refract(lanes, i, ray, step.t[i], step.normal[i], ior);
      }
    retire_ended(lanes, rays);
  }

  // The rays that left the volume or became opaque give their record what
  // they gathered and leave the lanes, the last lane's ray taking the place
  // of each (a ray's samples do not depend on its lane).
  void retire_ended(RayLanes& lanes, std::vector<MarchingRay>& rays) const {
    const float opaque = 1.0f - std::max(options_.termination, extrapolation_);
    std::size_t count = lanes.size();
    for (std::size_t i = 0; i < count;) {
      const bool segments_left = lanes.has_segments_left(i);
      if (segments_left && !(lanes.alpha[i] >= opaque)) {
        ++i;
        continue;
      }
      MarchingRay& ray = rays[lanes.record[i]];
      ray.color = lanes.color_of(i);
      ray.alpha = lanes.alpha[i];
      ray.segments_left = segments_left;
      lanes.move(--count, i);
    }
    lanes.truncate(count);
  }

  // Each lane's sample: where along its ray (step.t) and where in space (step.at).
  static void place_samples(const RayLanes& lanes, StepSamples& step) {
    const std::size_t count = lanes.size();
    step.t.resize(count);
    for (int c = 0; c < 3; ++c) step.at[c].resize(count);
    float* __restrict t = step.t.data();
    for (std::size_t i = 0; i < count; ++i) t[i] = lanes.sample_t(i);
    for (int c = 0; c < 3; ++c) {
      const float* __restrict origin = lanes.origin[c].data();
      const float* __restrict along = lanes.along[c].data();
      float* __restrict at = step.at[c].data();
      for (std::size_t i = 0; i < count; ++i) at[i] = origin[i] + t[i] * along[i];
    }
  }

  const Kernel& kernel_;
  const OutputLayout& layout_;
  const Scene& scene_;
  glm::vec3 lo_, hi_;
  float step_, reference_step_, shadow_step_;
  bool jitter_, lit_, shadows_, refracts_, own_normals_;
  const OccupancyGrid* occupancy_;  // null: every sample is marched
  const LightGrids& grids_;
  const VolumeRenderOptions& options_;
  float extrapolation_;  // a ray ends once it lets through less, the rest of it extrapolated; 0: none
  float faint_normals_;  // a sample adding less takes its ray's slopes across; 0: every one probed
  glm::vec3 background_;
  glm::vec3 ambient_;
  bool objects_shadow_;  // the scene's objects may shadow a sample: light_point's shadow rays
  bool exact_specular_;  // the lobe's power is libm's, as the reference has it
  float specular_exponent_ = specular_exponent(SurfaceMaterial{}.roughness);
  SpecularLobeTable lobe_table_{specular_exponent_};  // `lobe` where it need not be powf's
};

// Empty space is bounded finely (the second level) only where the first
// level finds at least this much of the bricks empty: where it finds next
// to nothing (mesh_hypertexture, 0%), the cells beside the few empty
// bricks are not worth bounding one by one.
constexpr double least_empty_bricks = 0.05;

// Empty space is skipped where the second level finds at least this much
// of the bounds empty. Measured at 512x512 (docs/architecture.md):
// skipping made every volume whose bricks were 32% or more empty faster
// (sponge, 33%: 0.60 s against 1.40 s; furry_donut, 32%, as fast), and
// the STF volumes, 15% of their bricks and 38% of their cells empty, too.
constexpr double least_empty_cells = 0.3;

// Skipping pays where the kernel spends on a sample of empty space at
// least this share of what it spends on an occupied one. A graph that
// passes over its own empty space (the fireball's `if` beyond its reach)
// evaluates it for next to nothing, and there walking the cells costs more
// than the samples it saves (fireball at 512x512: its march took 1.23 s
// skipping, 1.07 s not).
constexpr double least_empty_sample_cost = 0.5;

// What a sample of a volume costs the kernel, in empty and occupied space
// (nanoseconds on one thread; 0 where too few points of one kind were
// found: then there is too little of that kind to matter, and nothing is
// decided by it).
struct SampleCosts {
  double empty = 0.0, occupied = 0.0;
};

// The kernel timed on points of the bounds in `grid`'s empty cells and in
// its occupied ones.
SampleCosts time_samples(const OccupancyGrid& grid, const Kernel& kernel, BoundKernel& bound, float step,
                         const glm::vec3& lo, const glm::vec3& hi) {
  constexpr std::size_t probes = 4096;
  std::vector<glm::vec3> empty, occupied;
  for (int k = 0; (empty.size() < probes || occupied.size() < probes) && k < 64 * static_cast<int>(probes); ++k) {
    const glm::vec3 at(unit_float(pixel_hash(k, 0, 0)), unit_float(pixel_hash(k, 1, 0)), unit_float(pixel_hash(k, 2, 0)));
    const glm::vec3 point = lo + at * (hi - lo);
    std::vector<glm::vec3>& probed = grid.occupied(point) ? occupied : empty;
    if (probed.size() < probes) probed.push_back(point);
  }
  if (empty.size() < probes / 8 || occupied.size() < probes / 8) return {};
  const auto batch_of = [&](const std::vector<glm::vec3>& points) {
    auto batch = std::make_unique<Batch>(points.size(), kernel, step);
    const Planes3 at(batch->inputs, GlobalId::P), views(batch->inputs, GlobalId::I);
    for (std::size_t i = 0; i < points.size(); ++i) {
      at.store(i, points[i]);
      views.store(i, glm::vec3(0.0f, 0.0f, -1.0f));
    }
    return batch;
  };
  const std::unique_ptr<Batch> empty_batch = batch_of(empty), occupied_batch = batch_of(occupied);
  const auto cost_per_sample = [&](Batch& batch, std::size_t count) {
    const auto start = std::chrono::steady_clock::now();
    bound.run(batch.inputs.inputs(), batch.outputs.planes(), count);
    return std::max(static_cast<double>(nanoseconds_since(start)) / static_cast<double>(count), 1e-3);
  };
  // Rounds of both, the median of their ratios: a tiered kernel may move
  // to its JIT between two calls, which then must not be compared. The
  // cheapest occupied sample is the JIT's where it has arrived.
  std::vector<double> ratios;
  double occupied_cost = std::numeric_limits<double>::infinity();
  for (int round = 0; round < 5; ++round) {
    const double empty_cost = cost_per_sample(*empty_batch, empty.size());
    const double round_cost = cost_per_sample(*occupied_batch, occupied.size());
    ratios.push_back(empty_cost / round_cost);
    occupied_cost = std::min(occupied_cost, round_cost);
  }
  std::nth_element(ratios.begin(), ratios.begin() + 2, ratios.end());
  return {ratios[2] * occupied_cost, occupied_cost};
}

// The average length of the chords of a box (Cauchy: 4 volume / area).
float mean_chord(const glm::vec3& size) {
  return 4.0f * size.x * size.y * size.z / (2.0f * (size.x * size.y + size.y * size.z + size.z * size.x));
}

// A marched sample costs the marcher about what it costs the kernel (at
// 512x512, stf_bumps: 2.1 s of march and 1.6 s of kernel, thread time).
constexpr double march_cost_per_kernel_cost = 1.0;

// What the interval bounds found of a volume's empty space.
struct EmptySpace {
  std::optional<OccupancyGrid> grid;  // none: no space is skipped
  EmptySpaceVerdict verdict = EmptySpaceVerdict::too_little;
  double samples_saved = 0.0;  // by the second level, as estimated from its survey
};

// What bounding a volume's empty space encloses: its opacity (or its
// density where it has none) first, and its index where it refracts. Only
// they are evaluated, not the colour.
std::vector<OutputId> bounded_outputs(const OutputLayout& layout) {
  std::vector<OutputId> bounded{layout.provides(OutputId::opacity) ? OutputId::opacity : OutputId::density};
  if (layout.provides(OutputId::ior)) bounded.push_back(OutputId::ior);
  return bounded;
}

// Where the volume may be visible: boxes of P (with any direction I) over
// which the graph's interval enclosure (interp/interval_program.h) of
// its opacity, or density where it has none, is not certainly 0, or, where
// the graph refracts, its index not certainly 1; full where that opacity
// is certainly above 0. The second level is bounded only where skipping
// pays: where the kernel spends on empty space much of what it spends
// elsewhere, and where the samples the second level would save this
// frame's `rays` (estimated from its survey and the kernel's cost, timed
// here) cost more than bounding the rest of it.
Result<EmptySpace> bound_empty_space(const Kernel& kernel, BoundKernel& bound, const std::vector<float>& params,
                                     const VolumeDesc& volume, float frame, float step, long rays,
                                     const VolumeRenderOptions& options) {
  const std::vector<OutputId> bounded = bounded_outputs(kernel.outputs());
  const OutputId seen = bounded.front();
  const IntervalProgram program(kernel.ir(), bounded);
  const UniformInputs uniforms = volume_uniforms(frame, step);
  // Per thread: a binding, and the enclosures of its last box.
  struct Bounding {
    std::optional<BoundIntervalProgram> bound;
    std::vector<lanes::Interval> outputs;
  };
  tbb::enumerable_thread_specific<Bounding> threads;
  const OutputLayout& layout = program.outputs();
  const int plane = layout.plane(seen);
  // A refracting graph's box may bend a ray wherever its index may differ
  // from 1, the index rays start in.
  const int ior_plane = layout.provides(OutputId::ior) ? layout.plane(OutputId::ior) : -1;
  const BoxOccupancy occupied = [&](const glm::vec3& lo, const glm::vec3& hi) {
    Bounding& local = threads.local();
    if (!local.bound) {
      local.bound.emplace(program.bind(params.data(), uniforms));
      local.outputs.resize(static_cast<std::size_t>(layout.plane_count));
    }
    SampleBox box;
    for (int c = 0; c < 3; ++c) {
      box.set(GlobalId::P, {lo[c], hi[c]}, c);
      box.set(GlobalId::I, {-1.0f, 1.0f}, c);
    }
    box.set(GlobalId::filter_width, {step, step});
    local.bound->evaluate(box, local.outputs.data());
    const lanes::Interval seen_bound = local.outputs[static_cast<std::size_t>(plane)];
    if (seen_bound.lo > 0.0f) return BoxContents::full;
    if (ior_plane >= 0) {
      const lanes::Interval ior = local.outputs[static_cast<std::size_t>(ior_plane)];
      if (!(ior.lo == 1.0f && ior.hi == 1.0f)) return BoxContents::some;
    }
    return seen_bound.hi <= 0.0f ? BoxContents::empty : BoxContents::some;
  };
  const glm::vec3 lo(volume.bounds_min[0], volume.bounds_min[1], volume.bounds_min[2]);
  const glm::vec3 hi(volume.bounds_max[0], volume.bounds_max[1], volume.bounds_max[2]);
  Result<std::optional<OccupancyGrid>> grid =
      OccupancyGrid::build(lo, hi, occupied, least_empty_bricks, options.threads, options.cancel);
  if (!grid) return grid.error();
  EmptySpace found;
  if (!*grid) return found;
  const SampleCosts costs = time_samples(**grid, kernel, bound, step, lo, hi);
  if (costs.empty < least_empty_sample_cost * costs.occupied) {
    found.verdict = EmptySpaceVerdict::cheap;
    return found;
  }
  const auto survey_start = std::chrono::steady_clock::now();
  if (Status refined = (*grid)->refine(occupied, true, options.threads, options.cancel); !refined)
    return refined.error();
  const double survey_seconds = static_cast<double>(nanoseconds_since(survey_start)) * 1e-9;
  const double empty = (*grid)->surveyed_empty_fraction();
  if (empty < least_empty_cells) return found;
  const long surveyed = (*grid)->occupied_bricks(true), rest = (*grid)->occupied_bricks(false);
  const double rest_seconds =
      surveyed > 0 ? survey_seconds * static_cast<double>(rest) / static_cast<double>(surveyed) : 0.0;
  found.samples_saved = static_cast<double>(rays) * mean_chord(hi - lo) / step * empty;
  const double saved_seconds = found.samples_saved * costs.occupied * 1e-9 * (1.0 + march_cost_per_kernel_cost) /
                               static_cast<double>(worker_count(options.threads));
  if (!options.bound_finely_always && costs.occupied > 0.0 && saved_seconds < rest_seconds) {
    found.verdict = EmptySpaceVerdict::not_worth_bounding;
    return found;
  }
  if (Status refined = (*grid)->refine(occupied, false, options.threads, options.cancel); !refined)
    return refined.error();
  found.grid = std::move(*grid);
  found.verdict = EmptySpaceVerdict::skipped;
  return found;
}

// The lights' transmittance grids hold at most this many values in all
// (128 MB): a grid whose rays would be finer grows its spacing to fit.
constexpr std::size_t max_grid_values = std::size_t{1} << 25;

// The world distance between neighbouring pixels' rays at `at`: the
// detail the image can show there.
float pixel_footprint(const Camera& camera, const VolumeView& view, const glm::vec3& at) {
  const float x = 0.5f * static_cast<float>(view.width), y = 0.5f * static_cast<float>(view.height);
  const Ray middle = camera.ray(x, y), next = camera.ray(x + 1.0f, y);
  const float distance = glm::length(at - middle.origin);
  return glm::length((next.origin + distance * next.direction) - (middle.origin + distance * middle.direction));
}

// Each light's transmittance grid, its rays as far apart as the shadow
// march's steps or the image's pixels at the bounds' centre, whichever is
// wider (finer shadow detail could not be seen), each filled with the
// kernel on the frame's bindings.
Result<LightGrids> fill_light_grids(const Kernel& kernel, ThreadBindings& bindings, const Scene& scene,
                                    const VolumeDesc& volume, const Camera& camera, const VolumeView& view,
                                    float step, float shadow_step, const OccupancyGrid* occupancy,
                                    const VolumeRenderOptions& options, std::atomic<long long>& kernel_ns,
                                    std::atomic<long>& lane_slots) {
  const glm::vec3 lo(volume.bounds_min[0], volume.bounds_min[1], volume.bounds_min[2]);
  const glm::vec3 hi(volume.bounds_max[0], volume.bounds_max[1], volume.bounds_max[2]);
  TransmittanceGridSpec spec;
  spec.spacing = std::max(shadow_step, pixel_footprint(camera, view, 0.5f * (lo + hi)));
  spec.shadow_step = shadow_step;
  spec.reference_step = reference_step(volume);
  spec.termination = options.termination;
  spec.max_values = max_grid_values / scene.lights().size();
  spec.threads = options.threads;
  spec.cancel = options.cancel;
  spec.occupancy = occupancy;
  tbb::enumerable_thread_specific<std::unique_ptr<Batch>> batches;
  const OpacitySampler opacity_at = [&](const std::vector<glm::vec3>& points,
                                        const std::vector<glm::vec3>& toward_light, std::vector<float>& opacities) {
    std::unique_ptr<Batch>& batch = batches.local();
    if (!batch || batch->inputs.count() < points.size()) batch = std::make_unique<Batch>(points.size(), kernel, step);
    const Planes3 at(batch->inputs, GlobalId::P), views(batch->inputs, GlobalId::I);
    for (std::size_t i = 0; i < points.size(); ++i) {
      at.store(i, points[i]);
      views.store(i, toward_light[i]);
    }
    {
      StageClock clock(kernel_ns);
      bindings.local().run(batch->inputs.inputs(), batch->outputs.planes(), points.size());
    }
    const float* opacity = opacity_plane(kernel.outputs(), *batch);
    for (std::size_t i = 0; i < points.size(); ++i) opacities[i] = unit_opacity(opacity[i]);
    lane_slots += static_cast<long>(lane_slots_of(points.size(), options.lane_width));
  };
  LightGrids grids;
  for (const Light& light : scene.lights()) {
    Result<std::optional<TransmittanceGrid>> grid = TransmittanceGrid::build(light, lo, hi, spec, opacity_at);
    if (!grid) return grid.error();
    grids.push_back(std::move(*grid));
  }
  return grids;
}

// Why empty space was not skipped, for the render line.
std::string why_not_skipped(EmptySpaceVerdict verdict, double samples_saved) {
  switch (verdict) {
    case EmptySpaceVerdict::cheap:
      return "the graph evaluates it for next to nothing";
    case EmptySpaceVerdict::not_worth_bounding:
      return samples_saved > 0 ? "bounding it finely would cost more than the " +
                                     std::to_string(std::lround(samples_saved / 1e6)) + " M samples it would save"
                               : "bounding it finely would cost more than the samples it would save";
    default:
      return "too little of the bounds found empty";
  }
}

class VolumeFrames : public FrameRenderer {
 public:
  VolumeFrames(Scene scene, std::shared_ptr<const EnvironmentBackground> environment, const VolumeDesc& volume,
               const VolumeView& view, const VolumeRenderOptions& options)
      : scene_(std::move(scene)), environment_(std::move(environment)),
        camera_(scene_.desc().camera, view.width, view.height), volume_(volume), view_(view), options_(options) {}

  Result<Image> render_frame(const Kernel& kernel, const std::vector<float>& params, float frame,
                             const ProgressCallback& progress, TileClaims* claims,
                             FrameReport& report) const override {
    VolumeView view = view_;
    view.frame = frame;
    VolumeRenderOptions options = options_;
    options.progress = progress;
    options.claims = claims;
    const EmptySpaceVerdict declined = declined_.load();
    const bool known = declined != EmptySpaceVerdict::skipped;
    if (known) options.skip_empty_space = false;
    Result<std::optional<Image>> background = environment_seen_by(
        environment_.get(), camera_, view.width, view.height, frame, {options.threads, {}, options.cancel});
    if (!background) return background.error();
    if (*background) options.background = &**background;
    VolumeRenderStats stats;
    Result<Image> image = render_volume(kernel, params, scene_, volume_, camera_, view, options, &stats);
    if (stats.empty_space != EmptySpaceVerdict::skipped && stats.empty_space != EmptySpaceVerdict::not_asked)
      declined_ = stats.empty_space;
    report.kernel_samples = stats.density_samples + stats.grid_samples;
    report.kernel_seconds = stats.kernel_seconds;
    report.figures = {{"rays", static_cast<double>(stats.rays)},
                      {"rays_ended_early", static_cast<double>(stats.rays_ended_early)},
                      {"density_samples", static_cast<double>(stats.density_samples)},
                      {"shadow_samples", static_cast<double>(stats.shadow_samples)},
                      {"grid_samples", static_cast<double>(stats.grid_samples)},
                      {"shadow_lookups", static_cast<double>(stats.shadow_lookups)},
                      {"grid_mb", static_cast<double>(stats.grid_bytes) / 1e6},
                      {"grid_s", stats.grid_seconds},
                      {"skipped_samples", static_cast<double>(stats.skipped_samples)},
                      {"empty_fraction", stats.empty_fraction},
                      {"bounds_s", stats.occupancy_seconds},
                      {"lane_utilisation", stats.lane_utilisation()},
                      {"kernel_s", stats.kernel_seconds},
                      {"gradient_s", stats.gradient_seconds},
                      {"march_s", stats.march_seconds}};
    for (std::size_t stage = 0; stage < march_stage_count; ++stage)
      report.figures.emplace_back(std::string("march_") + march_stage_names[stage] + "_s",
                                  stats.march_stage_seconds[stage]);
    // The line is formatted a part at a time, each far shorter than `part`.
    std::string what;
    char part[256];
    const auto add = [&](int written) {
      if (written > 0) what.append(part, std::min(static_cast<std::size_t>(written), sizeof part - 1));
    };
    add(std::snprintf(part, sizeof part, "%dx%d, %ld rays", view.width, view.height, stats.rays));
    if (options.extrapolation > 0.0f) add(std::snprintf(part, sizeof part, " (%ld ended early)", stats.rays_ended_early));
    add(std::snprintf(part, sizeof part, ", %ld density samples (%ld for gradients %s in %.3f s, %ld for shadow rays)",
                      stats.density_samples, stats.gradient_samples, options.normal_kernel ? "exactly" : "by probes",
                      stats.gradient_seconds, stats.shadow_samples));
    if (stats.empty_fraction > 0.0)
      add(std::snprintf(part, sizeof part,
                        stats.empty_space_read
                            ? ", %ld skipped in the %.0f%% of the bounds found empty before (read in %.3f s)"
                            : ", %ld skipped in the %.0f%% of the bounds found empty in %.3f s",
                        stats.skipped_samples, 100.0 * stats.empty_fraction, stats.occupancy_seconds));
    else if (known)
      add(std::snprintf(part, sizeof part, ", no empty space skipped (%s, as an earlier frame found)",
                        why_not_skipped(declined, 0).c_str()));
    else if (options.skip_empty_space)
      add(std::snprintf(part, sizeof part, ", no empty space skipped (%s; bounded in %.3f s)",
                        why_not_skipped(stats.empty_space, stats.samples_saved).c_str(), stats.occupancy_seconds));
    if (stats.grid_bytes > 0)
      add(std::snprintf(part, sizeof part, ", shadow grids of %.1f MB: %ld samples in %.3f s, %ld lookups",
                        stats.grid_bytes / 1e6, stats.grid_samples, stats.grid_seconds, stats.shadow_lookups));
    report.what = what;
    char text[512];
    std::snprintf(text, sizeof text,
                  "thread time: kernel %.3f s = %.2f M samples/s, %.1f%% of %d-wide lanes in use, march %.3f s",
                  stats.kernel_seconds,
                  stats.kernel_seconds > 0 ? static_cast<double>(report.kernel_samples) / stats.kernel_seconds / 1e6
                                           : 0.0,
                  100.0 * stats.lane_utilisation(), options.lane_width, stats.march_seconds);
    report.details = text;
    std::string stages;
    for (std::size_t stage = 0; stage < march_stage_count; ++stage) {
      if (stats.march_stage_seconds[stage] <= 0.0) continue;  // a stage this volume does not have
      std::snprintf(text, sizeof text, "%s%s %.3f", stages.empty() ? " (" : ", ", march_stage_names[stage],
                    stats.march_stage_seconds[stage]);
      stages += text;
    }
    if (!stages.empty()) report.details += stages + ")";
    return image;
  }

 private:
  Scene scene_;
  std::shared_ptr<const EnvironmentBackground> environment_;  // null: the scene's background colour
  Camera camera_;
  VolumeDesc volume_;
  VolumeView view_;
  VolumeRenderOptions options_;
  // Why a frame did not skip empty space (bound_empty_space), if one did
  // not: the later frames of the sequence then do not bound it and time
  // the kernel again, 16-22 ms of a fireball frame at 128x128. Skipping
  // never changes a pixel, only where the time goes.
  mutable std::atomic<EmptySpaceVerdict> declined_{EmptySpaceVerdict::skipped};
};

}  // namespace

SceneDesc volume_scene(const std::optional<SceneDesc>& scene) {
  if (scene) return *scene;
  SceneDesc desc;
  desc.lights = default_lights();
  return desc;
}

UniformInputs volume_uniforms(float frame, float step) {
  UniformInputs uniforms;
  uniforms.set(GlobalId::time, frame / frames_per_second);
  uniforms.set(GlobalId::frame, frame);
  uniforms.set(GlobalId::step_size, step);
  return uniforms;
}

Result<Image> render_volume(const Kernel& kernel, const std::vector<float>& params, const Scene& scene,
                            const VolumeDesc& volume, const Camera& camera, const VolumeView& view,
                            const VolumeRenderOptions& options, VolumeRenderStats* stats) {
  const OutputLayout& layout = kernel.outputs();
  if (layout.kind != GraphKind::volume || !layout.provides(OutputId::density))
    return invalid_input("the ray marcher needs a volume graph with an output \"density\"");
  const float step = options.step != 0.0f ? options.step : march_step(volume);
  if (std::string problem = step_problem(volume, step, "step"); !problem.empty()) return invalid_input(problem);
  if (options.shadow_step != 0.0f)
    if (std::string problem = step_problem(volume, options.shadow_step, "shadow step"); !problem.empty())
      return invalid_input(problem);
  const float shadow_step = options.shadow_step != 0.0f ? options.shadow_step : reference_step(volume);
  const bool jitter = options.jitter.value_or(volume.jitter);
  const bool shadows = options.shadows != ShadowMode::off && scene.desc().shadows;

  Image image;
  image.width = view.width;
  image.height = view.height;
  image.channels = 3;
  image.pixels.assign(static_cast<std::size_t>(view.width) * view.height * 3, 0.0f);
  ThreadBindings bindings(kernel, params.data(), volume_uniforms(view.frame, step));
  std::optional<ThreadBindings> normal_bindings;
  if (options.normal_kernel) normal_bindings.emplace(*options.normal_kernel, params.data(), volume_uniforms(view.frame, step));
  std::atomic<long long> tile_ns{0}, kernel_ns{0}, grid_kernel_ns{0};
  std::atomic<long long> gradient_ns{0};
  std::array<std::atomic<long long>, march_stage_count> stage_ns{};
  std::atomic<long> rays{0}, rays_ended_early{0}, density_samples{0}, gradient_samples{0}, shadow_samples{0},
      shadow_lookups{0}, skipped_samples{0}, kernel_calls{0}, lane_slots{0};

  const auto since = [](std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  std::optional<OccupancyGrid> occupancy;
  EmptySpaceVerdict empty_space_verdict = EmptySpaceVerdict::not_asked;
  double samples_saved = 0.0, occupancy_seconds = 0.0;
  bool empty_space_read = false;
  if (options.skip_empty_space) {
    const auto occupancy_start = std::chrono::steady_clock::now();
    const EmptySpaceSource source =
        empty_space_source(kernel.ir(), bounded_outputs(layout), params, volume_uniforms(view.frame, step),
                           glm::vec3(volume.bounds_min[0], volume.bounds_min[1], volume.bounds_min[2]),
                           glm::vec3(volume.bounds_max[0], volume.bounds_max[1], volume.bounds_max[2]));
    occupancy = read_cached_empty_space(options.empty_space_cache, source);
    empty_space_read = occupancy.has_value();
    if (empty_space_read) {
      empty_space_verdict = EmptySpaceVerdict::skipped;
    } else {
      Result<EmptySpace> bounded = bound_empty_space(kernel, bindings.local(), params, volume, view.frame, step,
                                                     static_cast<long>(view.width) * view.height, options);
      if (!bounded) return bounded.error();
      occupancy = std::move(bounded->grid);
      empty_space_verdict = bounded->verdict;
      samples_saved = bounded->samples_saved;
      if (occupancy) store_empty_space(options.empty_space_cache, source, *occupancy);
    }
    occupancy_seconds = since(occupancy_start);
  }
  const OccupancyGrid* empty_space = occupancy ? &*occupancy : nullptr;

  const auto grids_start = std::chrono::steady_clock::now();
  LightGrids grids;
  if (shadows && options.shadows == ShadowMode::cached && scene.desc().lighting == Lighting::lit &&
      !scene.lights().empty()) {
    Result<LightGrids> filled = fill_light_grids(kernel, bindings, scene, volume, camera, view, step, shadow_step,
                                                 empty_space, options, grid_kernel_ns, lane_slots);
    if (!filled) return filled.error();
    grids = std::move(*filled);
  }
  const double grid_seconds = since(grids_start);
  const Marcher marcher(kernel, scene, volume, step, reference_step(volume), shadow_step, jitter, shadows,
                        empty_space, grids, options);

  Status done = for_each_tile(
      view.width, view.height, tile_size, options.threads,
      [&](const Tile& tile) -> long {
        StageClock clock(tile_ns);
        std::vector<glm::vec3> pixels;
        TileCounts counts;
        marcher.render_tile(tile, camera, bindings.local(), normal_bindings ? &normal_bindings->local() : nullptr,
                            pixels, counts);
        for (int y = 0; y < tile.height; ++y)
          for (int x = 0; x < tile.width; ++x) {
            float* pixel =
                image.pixels.data() + (static_cast<std::size_t>(tile.y0 + y) * view.width + (tile.x0 + x)) * 3;
            const glm::vec3& value = pixels[static_cast<std::size_t>(y) * tile.width + x];
            for (int c = 0; c < 3; ++c) pixel[c] = value[c];
          }
        if (options.tile_done) options.tile_done(image, tile);
        rays += counts.rays;
        rays_ended_early += counts.rays_ended_early;
        kernel_ns += counts.kernel_ns;
        for (std::size_t stage = 0; stage < march_stage_count; ++stage) stage_ns[stage] += counts.stage_ns[stage];
        density_samples += counts.density_samples;
        gradient_samples += counts.gradient_samples;
        gradient_ns += counts.gradient_ns;
        shadow_samples += counts.shadow_samples;
        shadow_lookups += counts.shadow_lookups;
        skipped_samples += counts.skipped_samples;
        kernel_calls += counts.kernel_calls;
        lane_slots += counts.lane_slots;
        return counts.rays;
      },
      options.progress, options.cancel, options.claims);
  if (!done) return done.error();

  if (stats) {
    stats->kernel_seconds = seconds(kernel_ns) + seconds(grid_kernel_ns);
    stats->march_seconds = seconds(tile_ns) - seconds(kernel_ns);
    for (std::size_t stage = 0; stage < march_stage_count; ++stage)
      stats->march_stage_seconds[stage] = seconds(stage_ns[stage]);
    stats->rays = rays;
    stats->rays_ended_early = rays_ended_early;
    stats->density_samples = density_samples;
    stats->gradient_samples = gradient_samples;
    stats->gradient_seconds = seconds(gradient_ns);
    stats->shadow_samples = shadow_samples;
    stats->shadow_lookups = shadow_lookups;
    stats->skipped_samples = skipped_samples;
    for (const std::optional<TransmittanceGrid>& grid : grids)
      if (grid) {
        stats->grid_samples += grid->samples();
        stats->grid_bytes += grid->bytes();
        stats->skipped_samples += grid->skipped_samples();
      }
    stats->empty_fraction = occupancy ? occupancy->empty_fraction() : 0.0;
    stats->empty_space = empty_space_verdict;
    stats->empty_space_read = empty_space_read;
    stats->samples_saved = samples_saved;
    stats->occupancy_seconds = occupancy_seconds;
    stats->grid_seconds = grid_seconds;
    stats->kernel_calls = kernel_calls;
    stats->lane_slots = lane_slots;
  }
  return image;
}

Result<std::unique_ptr<FrameRenderer>> prepare_volume(const Graph& graph, const RenderRequest& request) {
  if (!graph.render.volume) return invalid_input("a volume graph needs render.volume to be rendered");
  const VolumeDesc& volume = *graph.render.volume;
  if (request.step)
    if (std::string problem = step_problem(volume, *request.step, "--step"); !problem.empty())
      return invalid_input(problem);
  const SceneDesc desc = volume_scene(graph.render.scene);
  Result<Scene> scene = Scene::build(desc, graph.file, request.search_paths);
  if (!scene) return scene.error();
  auto environment = EnvironmentBackground::of_scene(desc, graph.file, request.search_paths);
  if (!environment) return environment.error();
  VolumeView view;
  view.width = request.size ? request.size->first : graph.render.width;
  view.height = request.size ? request.size->second : graph.render.height;
  VolumeRenderOptions options;
  options.threads = request.threads;
  options.step = request.step.value_or(request.draft ? draft_step_factor * march_step(volume) : 0.0f);
  if (request.draft) options.shadow_step = draft_step_factor * reference_step(volume);
  if (request.jitter) options.jitter = true;
  options.shadows = request.shadows;
  // Exact shadows are the reference marcher: every sample marched, every
  // ray to its end, every lit sample probed.
  const bool reference = request.shadows == ShadowMode::exact;
  options.skip_empty_space = !reference;
  options.extrapolation = reference ? 0.0f : extrapolated_termination;
  options.faint_normals = reference ? 0.0f : faint_normal_weight;
  options.exact_specular = reference;
  options.empty_space_cache = user_cache_folder("");
  options.lane_width = request.lane_width;
  options.cancel = request.cancel;
  options.tile_done = request.tile_done;
  if (request.exact_normals && !request.normal_kernel)
    return invalid_input("exact normals need the kernel of the graph with its normal (graph/derived_normals.h)");
  options.normal_kernel = request.exact_normals ? request.normal_kernel : nullptr;
  return std::unique_ptr<FrameRenderer>(std::make_unique<VolumeFrames>(std::move(*scene), std::move(*environment), volume, view, options));
}

void volume_thumbnail(const Graph& graph, json& document) {
  if (!graph.render.volume) return;
  const VolumeDesc& volume = *graph.render.volume;
  for (json& node : document["nodes"]) {
    const std::string op = node.value("op", std::string());
    if (op == "step_size") node = {{"id", node["id"]}, {"op", "add"}, {"in", {{"a", march_step(volume)}, {"b", 0}}}};
    if (op == "density") node = {{"id", node["id"]}, {"op", "add"}, {"in", {{"a", 0}, {"b", 0}}}};
    if (op == "I") node = {{"id", node["id"]}, {"op", "vec3"}, {"in", {{"x", 0}, {"y", 0}, {"z", -1}}}};
  }
  json& render = document["render"];
  render.erase("scene");
  render.erase("volume");
  render["domain"] = {{"min", {volume.bounds_min[0], volume.bounds_min[1]}},
                      {"max", {volume.bounds_max[0], volume.bounds_max[1]}}};
  render["z"] = 0.5f * (volume.bounds_min[2] + volume.bounds_max[2]);
  document["kind"] = "texture";
}

}  // namespace shadetree

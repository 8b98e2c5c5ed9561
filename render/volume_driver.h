// The hypertexture ray marcher (Perlin & Hoffert 1989 section 3.1): each
// pixel's ray is clipped to the volume's bounding box and marched at a
// fixed step; the volume graph gives density, colour and opacity at each
// sample; where the density is soft (0 < density < 1) its gradient,
// estimated by finite differences, is the normal that the scene's lights
// shade; samples are composited front to back until the ray is opaque.
//
// Rays are marched in packets: every live ray of a tile takes its next
// sample together, in one kernel call over densely packed input planes,
// then the rays that ended are dropped from the packet, so the lanes stay
// full as rays terminate. Each ray's arithmetic depends only on the ray,
// so the image is the same for any packet size and thread count.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <filesystem>
#include <iterator>
#include <optional>
#include <vector>

#include "graph/scene.h"
#include "ir/kernel.h"
#include "render/graph_kinds.h"
#include "nodes/image.h"
#include "scene/camera.h"
#include "schedule/image_tiles.h"
#include "schedule/progress.h"
#include "scene/scene.h"

namespace shadetree {

struct VolumeView {
  int width = 512;
  int height = 512;
  float frame = 0.0f;
};

// A ray stops once its opacity passes 1 - this: what it could still add to
// the pixel is below half an 8-bit step.
inline constexpr float default_termination = 1.0f / 512.0f;

// A render that need not be the reference ends a ray once it lets
// through less than this, and takes what the ray would still have met to
// be as bright as what it met: its colour over its alpha. That changes a
// pixel by at most this times how far the colour behind differs from the
// colour in front, and saves the samples of its last two optical depths
// (from 1/64 to 1/512 of the light left): an eighth to a sixth of the
// furry volumes' samples (docs/architecture.md, "Rays ended early").
inline constexpr float extrapolated_termination = 1.0f / 64.0f;

// A render that need not be the reference probes the density's gradient
// only at samples that add at least this much of a colour to their pixel
// (their opacity times what their ray still lets through): a fainter one
// takes the density's slope along its ray from the sample before, as
// every sample does, and its slopes across the ray from the ray's last
// probed sample. In fur, where each sample adds little, that leaves out a
// third of the probes (docs/architecture.md, "Faint samples' normals").
inline constexpr float faint_normal_weight = 1.0f / 256.0f;

struct VolumeRenderOptions {
  int threads = 0;             // 0: all cores
  float step = 0.0f;           // 0: the volume's (graph/parse_volume.h: march_step); others are checked
  std::optional<bool> jitter;  // unset: the volume's
  float termination = default_termination;
  // Where a ray ends early, its rest extrapolated (above; at most a half
  // is taken); 0: rays end only at `termination`, over the background or
  // the object behind, as the reference marcher (`--shadows exact`) ends
  // them.
  float extrapolation = extrapolated_termination;
  // A sample fainter than this (its opacity times what its ray still lets
  // through) is lit by a normal that takes its slopes across the ray from
  // the ray's last probed sample, without probes of its own (above); 0:
  // every sample lit by its normal is probed, as the reference marcher
  // probes them.
  float faint_normals = faint_normal_weight;
  // Every specular lobe by libm's powf, as the reference marcher takes
  // them; false: +0 where the lobe adds less than 2^-16 of a light, and
  // elsewhere from a table within 2^-17 of powf
  // (scene/specular_lobe_table.h).
  bool exact_specular = false;
  ShadowMode shadows = ShadowMode::cached;  // and the scene's "shadows" (render/transmittance_grid.h)
  bool skip_empty_space = true;  // where the graph's interval bounds say so (render/occupancy_grid.h)
  // Bound empty space finely even where that is estimated to cost more
  // than the samples it saves (a small image): the same pixels either way.
  bool bound_finely_always = false;
  // The folder where empty space found is kept and found again
  // (render/occupancy_grid_cache.h); empty: it is found anew each render.
  std::filesystem::path empty_space_cache;
  float shadow_step = 0.0f;  // of the shadow march; 0: the volume's reference step (parse_volume.h)
  int packet_rays = 0;  // rays marched together; 0: a whole tile (32 x 32); 1: one ray at a time
  int lane_width = 0;   // the kernel's vector width, for the lane utilisation figure only
  const Image* background = nullptr;  // RGB per pixel (an environment the camera sees); else the scene's colour
  // A kernel of the same graph that also gives the density's normal
  // (graph/derived_normals.h: its exact gradient), run once per soft
  // sample instead of two probes; null: the probes. A graph that gives its
  // own normal is lit by it.
  const Kernel* normal_kernel = nullptr;
  ProgressCallback progress;  // may be empty
  const std::atomic<bool>* cancel = nullptr;  // see for_each_tile
  TileClaims* claims = nullptr;  // this process's tiles of the frame (for_each_tile); null: all
  TileSink tile_done;  // may be empty
};

// Whether empty space was skipped, and if not, why not.
enum class EmptySpaceVerdict {
  not_asked,           // skip_empty_space was off
  skipped,
  too_little,          // the bounds found too little of it empty
  cheap,               // found, but the graph evaluates it for next to nothing
  not_worth_bounding,  // bounding it finely would cost more than the samples it saves
};

// The stages of the march, whose thread time (without the kernel calls
// made in them) the render line breaks the march's into; named in order.
enum class MarchStage {
  rays,      // a tile's camera rays set up, clipped to the bounds and to the objects
  stepping,  // samples placed along the rays (empty space skipped) and their opacities read
  normals,   // the density's gradient at the samples lit by it
  shadows,   // what reaches each lit sample of each light: grid lookups and shadow rays
  shading,   // lighting and front-to-back compositing
};
inline constexpr const char* march_stage_names[] = {"rays", "stepping", "normals", "shadows", "shading"};
inline constexpr std::size_t march_stage_count = std::size(march_stage_names);

// Where the time went (seconds of one core, summed over threads) and how
// full the kernel calls were.
struct VolumeRenderStats {
  double march_seconds = 0;   // rays, packing, gradients, shading, compositing
  std::array<double, march_stage_count> march_stage_seconds{};  // of those, by MarchStage
  double kernel_seconds = 0;  // the graph
  long rays = 0;              // that met the volume
  long rays_ended_early = 0;  // of those, their rest extrapolated (VolumeRenderOptions::extrapolation)
  long density_samples = 0;   // graph evaluations: march samples and gradient probes
  long gradient_samples = 0;  // of those, the gradient probes (or the normal kernel's samples)
  double gradient_seconds = 0;  // in their kernel calls
  long shadow_samples = 0;    // and the samples of shadow rays
  long grid_samples = 0;      // and the samples that filled the lights' transmittance grids
  long shadow_lookups = 0;    // of those grids, instead of shadow rays
  std::size_t grid_bytes = 0;
  double grid_seconds = 0;    // wall time of filling the grids, before the march
  long skipped_samples = 0;   // of primary, shadow and grid rays, in empty space
  double empty_fraction = 0;  // of the bounds, by the interval bounds
  EmptySpaceVerdict empty_space = EmptySpaceVerdict::not_asked;
  bool empty_space_read = false;  // skipped where an earlier render found it (the cache's)
  double samples_saved = 0;   // by bounding empty space finely, as estimated before (not_worth_bounding)
  double occupancy_seconds = 0;  // wall time of bounding the graph over the bounds' bricks
  long kernel_calls = 0;
  long lane_slots = 0;  // samples the calls' vector lanes could have held (with lane_width)

  double lane_utilisation() const {
    return lane_slots > 0 ? static_cast<double>(density_samples + grid_samples) / static_cast<double>(lane_slots)
                          : 0.0;
  }
};

// The scene a volume graph is marched in: its render section's, or the
// default camera under the default key and fill lights.
SceneDesc volume_scene(const std::optional<SceneDesc>& scene);

// The uniform globals of a frame: time, frame and the march step.
UniformInputs volume_uniforms(float frame, float step);

// A volume graph's density (and colour and opacity, where it has them)
// over `volume`, lit by the scene's lights unless it says "lighting":
// "none", over the scene's background. RGB.
Result<Image> render_volume(const Kernel& kernel, const std::vector<float>& params, const Scene& scene,
                            const VolumeDesc& volume, const Camera& camera, const VolumeView& view,
                            const VolumeRenderOptions& options, VolumeRenderStats* stats = nullptr);

// A volume node's thumbnail (the kinds table's thumbnail_document): the
// probe graph becomes a texture over the slice through the middle of the
// bounds, so that it needs no ray march, with what only a march provides
// as it is there: step_size the march step, I into the slice, no incoming
// density.
void volume_thumbnail(const Graph& graph, json& document);

// A draft's steps (RenderRequest::draft), in units of the volume's march
// step and, for its shadow rays, of its reference step. Its density stays
// as it is: opacity is defined per reference step.
inline constexpr float draft_step_factor = 4.0f;

// The volume row of the kinds table (render/graph_kinds.h): the graph's
// scene (or the default one) built once, its camera at the requested size,
// the requested step checked against the volume.
Result<std::unique_ptr<FrameRenderer>> prepare_volume(const Graph& graph, const RenderRequest& request);

}  // namespace shadetree

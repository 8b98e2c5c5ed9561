// The ray marcher: compositing against the closed-form transmittance of a
// constant density, step independence, early termination, packets,
// backends and threads, on volume graphs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "graph/derived_normals.h"
#include "graph/parse_volume.h"
#include "interp/interpreter.h"
#include "io/graph_files.h"
#include "jit/jit_kernel.h"
#include "pipeline/compile_graph.h"
#include "render/graph_kinds.h"
#include "render/volume_driver.h"
#include "scene/lighting.h"
#include "support/gallery.h"
#include "support/graph_text.h"
#include "support/temp_folder.h"

namespace shadetree {
namespace {

LoadedGraph compile_volume(const std::string& nodes, const std::string& outputs) {
  Result<LoadedGraph> loaded = compile_graph_text(testing::graph_text(nodes, outputs, "", "volume"), "volume.json");
  EXPECT_TRUE(loaded.ok()) << loaded.error().to_string();
  return std::move(*loaded);
}

// An orthographic camera looking down -z at the box [-1, 1]^3, 3 units
// high, so the middle of the image sees the box's full thickness of 2.
SceneDesc looking_down_z(Lighting lighting) {
  SceneDesc desc;
  desc.camera.position = {0.0f, 0.0f, 5.0f};
  desc.camera.orthographic = true;
  desc.camera.orthographic_height = 3.0f;
  desc.background = {0.0f, 0.0f, 0.0f};
  desc.ambient = {0.0f, 0.0f, 0.0f};
  desc.lighting = lighting;
  LightDesc sun;
  sun.direction = {0.0f, 0.0f, -1.0f};
  desc.lights = {sun};
  return desc;
}

VolumeDesc unit_box(float step) {
  VolumeDesc volume;
  volume.bounds_min = {-1.0f, -1.0f, -1.0f};
  volume.bounds_max = {1.0f, 1.0f, 1.0f};
  volume.step = step;
  return volume;
}

Image render(const Kernel& kernel, const LoadedGraph& loaded, const SceneDesc& desc, const VolumeDesc& volume,
             int size, VolumeRenderOptions options = {}, VolumeRenderStats* stats = nullptr) {
  Result<Scene> scene = Scene::build(desc, "volume.json", {});
  EXPECT_TRUE(scene.ok()) << scene.error().to_string();
  VolumeView view;
  view.width = view.height = size;
  Result<Image> image =
      render_volume(kernel, loaded.params, *scene, volume, Camera(desc.camera, size, size), view, options, stats);
  EXPECT_TRUE(image.ok()) << image.error().to_string();
  return std::move(*image);
}

float centre_red(const Image& image) {
  return image.pixels[(static_cast<std::size_t>(image.height / 2) * image.width + image.width / 2) * 3];
}

float largest_difference(const Image& a, const Image& b) {
  float largest = 0.0f;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) largest = std::max(largest, std::fabs(a.pixels[i] - b.pixels[i]));
  return largest;
}

// 1989: alpha_k = 1 - (1 - density)^(step / reference step) per sample, so
// that through a thickness L of constant density d the opacity is
// 1 - (1 - d)^(L / reference step), whatever the step and the jitter.
TEST(VolumeDriver, ConstantDensityGivesTheClosedFormTransmittance) {
  const LoadedGraph loaded = compile_volume("", R"("density": 0.3, "color": [1, 1, 1])");
  auto kernel = make_interpreted_kernel(loaded.ir);
  VolumeRenderOptions exact;
  exact.termination = 0.0f;
  for (float step : {0.1f, 0.03f, 0.007f})
    for (bool jitter : {false, true}) {
      VolumeDesc volume = unit_box(step);
      volume.reference_step = 0.25f;
      volume.jitter = jitter;
      const float expected = 1.0f - std::pow(0.7f, 2.0f / 0.25f);
      EXPECT_NEAR(centre_red(render(*kernel, loaded, looking_down_z(Lighting::none), volume, 9, exact)), expected, 1e-4f)
          << "step " << step << (jitter ? " jittered" : "");
    }
}

// Outside the box the ray sees the background only.
TEST(VolumeDriver, RaysThatMissTheBoundsShowTheBackground) {
  const LoadedGraph loaded = compile_volume("", R"("density": 1, "color": [1, 1, 1])");
  SceneDesc desc = looking_down_z(Lighting::none);
  desc.background = {0.25f, 0.5f, 0.75f};
  VolumeRenderStats stats;
  const Image image = render(*make_interpreted_kernel(loaded.ir), loaded, desc, unit_box(0.05f), 30, {}, &stats);
  EXPECT_EQ(image.pixels[0], 0.25f);
  EXPECT_EQ(image.pixels[2], 0.75f);
  EXPECT_FLOAT_EQ(centre_red(image), 1.0f);
  EXPECT_EQ(stats.rays, 20 * 20);  // the box spans 2 of the image's 3 units
}

const char* const soft_sphere = R"({"id": "p", "op": "P"},
    {"id": "s", "op": "sphere", "in": {"p": "p", "radius": 0.6, "softness": 0.6}},
    {"id": "thin", "op": "mul", "in": {"a": "s", "b": 0.2}},
    {"id": "c", "op": "to_color", "in": {"v": "p"}}, {"id": "tint", "op": "abs", "in": {"x": "c"}})";

// Halving the step changes a soft sphere's picture by little: opacity is
// normalized by the step, and only the sampling of the density changes.
// Shadows add the samples that cross the cutoff for shadow rays.
TEST(VolumeDriver, HalvingTheStepChangesLittle) {
  const LoadedGraph loaded = compile_volume(soft_sphere, R"("density": "thin", "color": "tint")");
  auto kernel = make_interpreted_kernel(loaded.ir);
  VolumeRenderOptions unshadowed;
  unshadowed.shadows = ShadowMode::off;
  for (const auto& [lighting, options, tolerance] :
       {std::tuple{Lighting::none, VolumeRenderOptions{}, 0.01f}, std::tuple{Lighting::lit, unshadowed, 0.01f},
        std::tuple{Lighting::lit, VolumeRenderOptions{}, 0.02f}}) {
    const Image coarse = render(*kernel, loaded, looking_down_z(lighting), unit_box(0.02f), 40, options);
    const Image fine = render(*kernel, loaded, looking_down_z(lighting), unit_box(0.01f), 40, options);
    EXPECT_LT(largest_difference(coarse, fine), tolerance) << "tolerance " << tolerance;
    EXPECT_GT(*std::max_element(fine.pixels.begin(), fine.pixels.end()), 0.1f);
  }
}

// A ray stops once its opacity passes 1 - termination: what it leaves out
// is at most termination times the brightest colour (here 1).
TEST(VolumeDriver, EarlyTerminationChangesNoPixelByMoreThanItsEpsilon) {
  const LoadedGraph loaded = compile_volume(soft_sphere, R"("density": "s", "color": "tint")");
  auto kernel = make_interpreted_kernel(loaded.ir);
  VolumeRenderOptions early, full;
  early.extrapolation = full.extrapolation = 0.0f;
  full.termination = 0.0f;
  VolumeRenderStats early_stats, full_stats;
  const Image ended = render(*kernel, loaded, looking_down_z(Lighting::none), unit_box(0.01f), 40, early, &early_stats);
  const Image complete = render(*kernel, loaded, looking_down_z(Lighting::none), unit_box(0.01f), 40, full, &full_stats);
  EXPECT_LE(largest_difference(ended, complete), default_termination);
  EXPECT_LT(early_stats.density_samples, full_stats.density_samples);
}

// A ray that ends once it lets through less than the extrapolation takes
// the rest to be as bright as what it met: its pixel moves by at most the
// extrapolation times how far the colours behind differ from those in
// front (here within [0, 1], over black), and it takes fewer samples.
TEST(VolumeDriver, RaysEndedEarlyChangeNoPixelByMoreThanTheLightLeft) {
  const LoadedGraph loaded = compile_volume(soft_sphere, R"("density": "s", "color": "tint")");
  auto kernel = make_interpreted_kernel(loaded.ir);
  VolumeRenderOptions full;
  full.extrapolation = 0.0f;
  full.termination = 0.0f;
  VolumeRenderStats ended_stats, full_stats;
  const Image ended = render(*kernel, loaded, looking_down_z(Lighting::none), unit_box(0.01f), 40, {}, &ended_stats);
  const Image complete = render(*kernel, loaded, looking_down_z(Lighting::none), unit_box(0.01f), 40, full, &full_stats);
  EXPECT_LE(largest_difference(ended, complete), extrapolated_termination);
  EXPECT_LT(ended_stats.density_samples, full_stats.density_samples);
  // Asked to end rays that have met nothing yet, the marcher ends them
  // once they let half the light through: no pixel divides by 0.
  VolumeRenderOptions at_once;
  at_once.extrapolation = 1.0f;
  const Image halves = render(*kernel, loaded, looking_down_z(Lighting::none), unit_box(0.01f), 40, at_once);
  for (float value : halves.pixels) ASSERT_TRUE(std::isfinite(value));
  EXPECT_LE(largest_difference(halves, complete), 0.5f);
}

// Through a medium of one colour, what a ray met is that colour, and so is
// its pixel where it ended early, however dark the background behind.
TEST(VolumeDriver, ARayEndedEarlyInAMediumOfOneColourIsThatColour) {
  const LoadedGraph loaded = compile_volume(soft_sphere, R"("density": "s", "color": [0.2, 0.5, 0.8])");
  const Image image = render(*make_interpreted_kernel(loaded.ir), loaded, looking_down_z(Lighting::none),
                             unit_box(0.01f), 9);
  const float* centre = image.pixels.data() + (static_cast<std::size_t>(4) * 9 + 4) * 3;
  EXPECT_FLOAT_EQ(centre[0], 0.2f);
  EXPECT_FLOAT_EQ(centre[1], 0.5f);
  EXPECT_FLOAT_EQ(centre[2], 0.8f);
}

// A render that need not be the reference takes no specular lobe below
// 2^-16 of a light, and the rest from a table within 2^-17 of powf
// (VolumeRenderOptions::exact_specular): the pixels of a lit sphere move,
// but by no more than 2^-16 of the light's specular share at each
// sample, whose weights add up to 1.
TEST(VolumeDriver, LobesLeftOutMoveNoPixelByMoreThanTheirFloor) {
  const LoadedGraph loaded = compile_volume(soft_sphere, R"("density": "s", "color": "tint")");
  auto kernel = make_interpreted_kernel(loaded.ir);
  SceneDesc desc = looking_down_z(Lighting::lit);
  desc.lights[0].direction = {1.0f, 0.0f, -0.3f};
  VolumeRenderOptions exact_lobes;
  exact_lobes.exact_specular = true;
  const Image reference = render(*kernel, loaded, desc, unit_box(0.01f), 40, exact_lobes);
  const Image floored = render(*kernel, loaded, desc, unit_box(0.01f), 40);
  const float moved = largest_difference(reference, floored);
  EXPECT_GT(moved, 0.0f);
  EXPECT_LE(moved, SurfaceMaterial{}.specular * std::exp2(-16.0f));
}

// Each ray's arithmetic depends only on the ray (and each light ray of a
// transmittance grid only on itself): marching a tile's rays together,
// compacting as they end, gives the pixels of one ray at a time. The
// exact shadow rays of a packet keep its lanes full.
TEST(VolumeDriver, PacketsAndThreadCountsChangeNoPixel) {
  const LoadedGraph loaded = compile_volume(soft_sphere, R"("density": "s", "color": "tint")");
  auto kernel = make_interpreted_kernel(loaded.ir);
  SceneDesc desc = looking_down_z(Lighting::lit);
  desc.lights[0].direction = {1.0f, 0.0f, -0.3f};
  for (ShadowMode mode : {ShadowMode::exact, ShadowMode::cached}) {
    VolumeRenderOptions one_ray, one_thread, packets;
    one_ray.packet_rays = 1;
    one_thread.threads = 1;
    packets.threads = 2;
    packets.lane_width = 8;
    one_ray.shadows = one_thread.shadows = packets.shadows = mode;
    VolumeRenderStats stats;
    const Image alone = render(*kernel, loaded, desc, unit_box(0.02f), 40, one_ray);
    EXPECT_EQ(alone.pixels, render(*kernel, loaded, desc, unit_box(0.02f), 40, one_thread).pixels);
    EXPECT_EQ(alone.pixels, render(*kernel, loaded, desc, unit_box(0.02f), 40, packets, &stats).pixels);
    EXPECT_GT(stats.gradient_samples, 0);
    if (mode == ShadowMode::exact) {
      EXPECT_GT(stats.lane_utilisation(), 0.9);
    }
    EXPECT_LE(stats.lane_utilisation(), 1.0);
  }
}

// Shadow rays only take light away: every pixel is at most as bright as
// without them, and the lumpy sphere's far side from the light (lit at a
// grazing angle through its own bumps) is markedly darker.
TEST(VolumeDriver, ShadowsOnlyDarken) {
  const LoadedGraph loaded = compile_volume(R"({"id": "p", "op": "P"}, {"id": "p4", "op": "mul", "in": {"a": "p", "b": 4}},
      {"id": "n", "op": "noise", "in": {"p": "p4"}}, {"id": "bump", "op": "mul", "in": {"a": "n", "b": 0.3}},
      {"id": "r", "op": "add", "in": {"a": 0.6, "b": "bump"}},
      {"id": "s", "op": "sphere", "in": {"p": "p", "radius": "r", "softness": 0.1}})",
                                            R"("density": "s")");
  auto kernel = make_interpreted_kernel(loaded.ir);
  SceneDesc desc = looking_down_z(Lighting::lit);
  desc.lights[0].direction = {1.0f, 0.0f, -0.3f};  // from the left, grazing
  VolumeRenderOptions unshadowed;
  unshadowed.shadows = ShadowMode::off;
  const Image plain = render(*kernel, loaded, desc, unit_box(0.01f), 40, unshadowed);
  long exact_shadow_samples = 0;
  for (ShadowMode mode : {ShadowMode::exact, ShadowMode::cached}) {
    VolumeRenderOptions options;
    options.shadows = mode;
    options.skip_empty_space = mode != ShadowMode::exact;  // as `render --shadows exact` marches
    VolumeRenderStats stats;
    const Image shadowed = render(*kernel, loaded, desc, unit_box(0.01f), 40, options, &stats);
    float darkest = 0.0f;
    for (std::size_t i = 0; i < plain.pixels.size(); ++i) {
      EXPECT_LE(shadowed.pixels[i], plain.pixels[i] + 1e-6f) << i;
      darkest = std::max(darkest, plain.pixels[i] - shadowed.pixels[i]);
    }
    EXPECT_GT(darkest, 0.2f);
    const bool cached = mode == ShadowMode::cached;
    if (!cached) exact_shadow_samples = stats.shadow_samples;
    EXPECT_GT(stats.shadow_samples, 0) << "shadow rays: all of them, or where a shadow's edge leaves the grid";
    EXPECT_LT(stats.shadow_samples, cached ? exact_shadow_samples / 4 : std::numeric_limits<long>::max());
    EXPECT_EQ(stats.shadow_lookups > 0, cached) << "grid lookups";
    EXPECT_EQ(stats.grid_samples > 0, cached);
  }
  desc.shadows = false;
  EXPECT_EQ(render(*kernel, loaded, desc, unit_box(0.01f), 40).pixels, plain.pixels);
}

// The march's thread time is broken into its stages, without the kernel
// calls made in them: each stage the render has takes time, one it has
// not (an unlit volume's normals and shadows) takes none, and together
// they are within the march's time.
TEST(VolumeDriver, TheMarchsStagesAreWithinItsTime) {
  const LoadedGraph loaded = compile_volume(soft_sphere, R"("density": "thin", "color": "tint")");
  auto kernel = make_interpreted_kernel(loaded.ir);
  for (Lighting lighting : {Lighting::none, Lighting::lit}) {
    VolumeRenderStats stats;
    render(*kernel, loaded, looking_down_z(lighting), unit_box(0.02f), 24, {}, &stats);
    const auto stage = [&](MarchStage s) { return stats.march_stage_seconds[static_cast<std::size_t>(s)]; };
    double total = 0.0;
    for (double seconds : stats.march_stage_seconds) {
      EXPECT_GE(seconds, 0.0);
      total += seconds;
    }
    EXPECT_LE(total, stats.march_seconds + 1e-9);
    EXPECT_GT(stage(MarchStage::rays), 0.0);
    EXPECT_GT(stage(MarchStage::stepping), 0.0);
    EXPECT_GT(stage(MarchStage::shading), 0.0);
    const bool lit = lighting == Lighting::lit;
    EXPECT_EQ(stage(MarchStage::normals) > 0.0, lit);
    EXPECT_EQ(stage(MarchStage::shadows) > 0.0, lit);
  }
}

// Shadow rays composite with the same per-reference-step opacity as the
// march, so a coarser shadow step (a draft's) moves the shadows little
// while it takes proportionally fewer samples.
TEST(VolumeDriver, ACoarserShadowStepChangesTheShadowsLittle) {
  const LoadedGraph loaded = compile_volume(soft_sphere, R"("density": "thin", "color": "tint")");
  auto kernel = make_interpreted_kernel(loaded.ir);
  SceneDesc desc = looking_down_z(Lighting::lit);
  desc.lights[0].direction = {1.0f, 0.0f, -0.3f};
  VolumeDesc volume = unit_box(0.01f);
  VolumeRenderStats fine_stats, coarse_stats;
  VolumeRenderOptions fine_shadows, coarse_shadows;
  fine_shadows.shadows = coarse_shadows.shadows = ShadowMode::exact;
  const Image fine = render(*kernel, loaded, desc, volume, 40, fine_shadows, &fine_stats);
  coarse_shadows.shadow_step = 4.0f * reference_step(volume);
  const Image coarse = render(*kernel, loaded, desc, volume, 40, coarse_shadows, &coarse_stats);
  EXPECT_LT(largest_difference(coarse, fine), 0.03f);
  EXPECT_NE(coarse.pixels, fine.pixels) << "the shadow step reaches the shadow march";
  EXPECT_LT(coarse_stats.shadow_samples, fine_stats.shadow_samples / 3);
  EXPECT_EQ(coarse_stats.density_samples - coarse_stats.shadow_samples,
            fine_stats.density_samples - fine_stats.shadow_samples) << "the march itself is unchanged";
}

// A ray entering glass of index 1.5 at 30 degrees bends to asin(sin 30 /
// 1.5) = 19.47 degrees (Snell's law), which is where it meets a wall 1.9
// units further down: at x = 1.9 tan(19.47) = 0.672 instead of 1.097. The
// wall's colour is its x.
TEST(VolumeDriver, RefractionFollowsSnellsLaw) {
  const LoadedGraph loaded = compile_volume(R"({"id": "p", "op": "P"}, {"id": "xyz", "op": "split", "in": {"v": "p"}},
      {"id": "glass", "op": "box", "in": {"p": "p", "center": [0, 0, -1], "half_size": [5, 5, 1.5], "softness": 0.01}},
      {"id": "wall", "op": "box", "in": {"p": "p", "center": [0, 0, -1.45], "half_size": [5, 5, 0.05], "softness": 0}},
      {"id": "density", "op": "union", "in": {"a": "glass", "b": "wall"}},
      {"id": "rise", "op": "mul", "in": {"a": "glass", "b": 0.5}}, {"id": "ior", "op": "add", "in": {"a": 1, "b": "rise"}},
      {"id": "c", "op": "color", "in": {"r": "xyz.x", "g": 0, "b": 0}})",
                                            R"("density": "density", "opacity": "wall", "color": "c", "ior": "ior")");
  const float angle = 30.0f * 3.14159265f / 180.0f;
  SceneDesc desc = looking_down_z(Lighting::none);
  desc.camera.position = {-5.0f * std::sin(angle), 0.0f, 0.5f + 5.0f * std::cos(angle)};
  desc.camera.target = {0.0f, 0.0f, 0.5f};
  desc.camera.orthographic_height = 0.5f;
  VolumeDesc volume;
  volume.bounds_min = {-3.0f, -3.0f, -2.5f};
  volume.bounds_max = {3.0f, 3.0f, 1.0f};
  volume.step = 0.002f;
  const float bent = std::asin(std::sin(angle) / 1.5f);
  EXPECT_NEAR(centre_red(render(*make_interpreted_kernel(loaded.ir), loaded, desc, volume, 5)), 1.9f * std::tan(bent),
              0.01f);
}

// A refracting graph's empty space is where its opacity is 0 and its
// index 1: a ray travelling in index 1 steps over it, and nothing else
// is stepped over (a ray leaving a hard glass ball bends back at its first
// sample outside, empty as that may be, and where it meets the wall behind
// shows it; a medium of index 1.2 around the ball bends every ray where it
// enters the box), so skipping changes no pixel.
TEST(VolumeDriver, RefractingRaysSkipOnlyWhereTheIndexIsOne) {
  for (const char* around : {"1", "1.2"}) {
    const LoadedGraph loaded = compile_volume(
        std::string(R"({"id": "p", "op": "P"},
      {"id": "glass", "op": "sphere", "in": {"p": "p", "radius": 0.45, "softness": 0}},
      {"id": "rise", "op": "mul", "in": {"a": "glass", "b": 0.5}}, {"id": "ior", "op": "add", "in": {"a": )") +
            around + R"(, "b": "rise"}},
      {"id": "faint", "op": "mul", "in": {"a": "glass", "b": 0.01}},
      {"id": "wall", "op": "box", "in": {"p": "p", "center": [0, 0, -0.8], "half_size": [5, 5, 0.1], "softness": 0}},
      {"id": "density", "op": "union", "in": {"a": "glass", "b": "wall"}},
      {"id": "seen", "op": "max", "in": {"a": "faint", "b": "wall"}},
      {"id": "c", "op": "to_color", "in": {"v": "p"}}, {"id": "tint", "op": "abs", "in": {"x": "c"}})",
        R"("density": "density", "opacity": "seen", "color": "tint", "ior": "ior")");
    auto kernel = make_interpreted_kernel(loaded.ir);
    SceneDesc desc = looking_down_z(Lighting::none);
    desc.camera.orthographic = false;
    VolumeRenderOptions skipping, marching;
    skipping.bound_finely_always = true;
    marching.skip_empty_space = false;
    VolumeRenderStats skipped, marched;
    // A step longer than the occupancy cells (1/32 here), so that a ray's
    // first sample outside the ball may lie in an empty cell.
    EXPECT_EQ(render(*kernel, loaded, desc, unit_box(0.05f), 40, skipping, &skipped).pixels,
              render(*kernel, loaded, desc, unit_box(0.05f), 40, marching, &marched).pixels)
        << "index " << around;
    if (std::string(around) == "1")
      EXPECT_GT(skipped.skipped_samples, marched.density_samples / 2);
    else
      EXPECT_EQ(skipped.skipped_samples, 0);
  }
}

ObjectDesc plane_at_z(float z, std::array<float, 3> color) {
  ObjectDesc plane;
  plane.type = ObjectType::plane;
  plane.transform.rotate_degrees = {90.0f, 0.0f, 0.0f};  // y = 0, normal +y, turned to face +z
  plane.transform.translate = {0.0f, 0.0f, z};
  plane.color = color;
  return plane;
}

// An opaque object behind the box shows through what the box lets
// through, and one inside the box ends the march where it stands: through
// a thickness L of constant density 0.3 the pixel is
// a + (1 - a) colour with a = 1 - 0.7^(L / reference step).
TEST(VolumeDriver, OpaqueObjectsShowThroughTheVolumeAndEndTheMarch) {
  const LoadedGraph loaded = compile_volume("", R"("density": 0.3, "color": [1, 1, 1])");
  auto kernel = make_interpreted_kernel(loaded.ir);
  VolumeRenderOptions exact;
  exact.termination = 0.0f;
  VolumeDesc volume = unit_box(0.01f);
  volume.reference_step = 0.25f;
  for (const auto& [z, thickness] : {std::pair{-3.0f, 2.0f}, std::pair{0.0f, 1.0f}}) {
    SceneDesc desc = looking_down_z(Lighting::none);
    desc.background = {0.125f, 0.125f, 0.125f};  // hidden everywhere by the plane
    desc.objects = {plane_at_z(z, {0.5f, 0.25f, 0.0f})};
    const float a = 1.0f - std::pow(0.7f, thickness / 0.25f);
    const Image image = render(*kernel, loaded, desc, volume, 9, exact);
    EXPECT_NEAR(centre_red(image), a + (1.0f - a) * 0.5f, 1e-4f) << "plane at z = " << z;
    EXPECT_EQ(image.pixels[0], 0.5f) << "outside the box, the plane itself";
    EXPECT_EQ(image.pixels[1], 0.25f);
  }
}

// The volume's shadow falls on the objects: a floor point whose path to
// the light crosses a length s of the box receives 0.7^(s / reference
// step) of the light it receives without shadows. Here the box is x in
// [-1.5, -0.5], z in [-1, 1], the light travels along (1, 0, -1), and the
// floor point at x = 1.125, z = -3 (not behind the box as the camera sees
// it) reaches the light through x in [-1.5, -0.875]: s = 0.625 sqrt 2.
TEST(VolumeDriver, TheVolumeShadowsObjects) {
  const LoadedGraph loaded = compile_volume("", R"("density": 0.3, "color": [1, 1, 1])");
  auto kernel = make_interpreted_kernel(loaded.ir);
  SceneDesc desc = looking_down_z(Lighting::lit);
  desc.lights[0].direction = {1.0f, 0.0f, -1.0f};
  desc.objects = {plane_at_z(-3.0f, {1.0f, 1.0f, 1.0f})};
  VolumeDesc volume;
  volume.bounds_min = {-1.5f, -1.0f, -1.0f};
  volume.bounds_max = {-0.5f, 1.0f, 1.0f};
  volume.step = volume.reference_step = 0.25f;
  VolumeRenderOptions unshadowed;
  unshadowed.shadows = ShadowMode::off;
  unshadowed.termination = 0.0f;
  // Pixel column 10 of 12 is at x = 1.125 (the image spans x in [-1.5, 1.5]).
  const std::size_t pixel = (6 * 12 + 10) * 3;
  const Image plain = render(*kernel, loaded, desc, volume, 12, unshadowed);
  ASSERT_GT(plain.pixels[pixel], 0.1f);
  // Exact within what the shadow ray's start, 1e-4 (1 + |x|) off the
  // floor, adds to its path; the grid's light rays cross the box along the
  // light as the shadow ray does, and a lookup between four of them
  // interpolates path lengths that vary linearly across the box's face.
  for (const auto& [mode, tolerance] : {std::pair{ShadowMode::exact, 1e-3f}, std::pair{ShadowMode::cached, 1e-3f}}) {
    VolumeRenderOptions options;
    options.termination = 0.0f;
    options.shadows = mode;
    const Image shadowed = render(*kernel, loaded, desc, volume, 12, options);
    EXPECT_NEAR(shadowed.pixels[pixel] / plain.pixels[pixel], std::pow(0.7f, 0.625f * std::sqrt(2.0f) / 0.25f),
                tolerance)
        << (mode == ShadowMode::exact ? "exact" : "cached");
  }
}

// Objects cast shadows into the volume: a wall between the light and a
// soft sphere (out of the camera's view) leaves only the ambient light,
// here none.
TEST(VolumeDriver, ObjectsShadowTheVolume) {
  const LoadedGraph loaded = compile_volume(soft_sphere, R"("density": "s")");
  auto kernel = make_interpreted_kernel(loaded.ir);
  SceneDesc desc = looking_down_z(Lighting::lit);
  desc.lights[0].direction = {-1.0f, 0.0f, 0.0f};  // from +x
  const Image lit = render(*kernel, loaded, desc, unit_box(0.02f), 16);
  ObjectDesc wall;
  wall.type = ObjectType::box;
  wall.half_size = {0.5f, 10.0f, 10.0f};
  wall.transform.translate = {3.0f, 0.0f, 0.0f};
  desc.objects = {wall};
  const Image dark = render(*kernel, loaded, desc, unit_box(0.02f), 16);
  EXPECT_GT(*std::max_element(lit.pixels.begin(), lit.pixels.end()), 0.2f);
  EXPECT_LE(*std::max_element(dark.pixels.begin(), dark.pixels.end()), 1e-6f);
}

TEST(VolumeDriver, StepAndFrameReachTheGraph) {
  const LoadedGraph loaded =
      compile_volume(R"({"id": "st", "op": "step_size"}, {"id": "f", "op": "frame"}, {"id": "fw", "op": "filter_width"},
                        {"id": "c", "op": "color", "in": {"r": "st", "g": "f", "b": "fw"}})",
                     R"("density": 1, "color": "c")");
  Result<Scene> scene = Scene::build(looking_down_z(Lighting::none), "volume.json", {});
  ASSERT_TRUE(scene.ok());
  VolumeView view;
  view.width = view.height = 5;
  view.frame = 7.0f;
  Result<Image> image = render_volume(*make_interpreted_kernel(loaded.ir), loaded.params, *scene, unit_box(0.125f),
                                      Camera(scene->desc().camera, 5, 5), view, {});
  ASSERT_TRUE(image.ok());
  const std::size_t centre = (2 * 5 + 2) * 3;
  EXPECT_EQ(image->pixels[centre], 0.125f);
  EXPECT_EQ(image->pixels[centre + 1], 7.0f);
  EXPECT_EQ(image->pixels[centre + 2], 0.125f);
}

TEST(VolumeDriver, RefusesStepsThatAreNotPositiveOrTooSmall) {
  const LoadedGraph loaded = compile_volume("", R"("density": 0.5)");
  Result<Scene> scene = Scene::build(looking_down_z(Lighting::none), "volume.json", {});
  ASSERT_TRUE(scene.ok());
  for (float step : {-1.0f, 1e-6f})
    for (bool shadow : {false, true}) {
      VolumeRenderOptions options;
      (shadow ? options.shadow_step : options.step) = step;
      Result<Image> image = render_volume(*make_interpreted_kernel(loaded.ir), loaded.params, *scene, unit_box(0.1f),
                                          Camera(scene->desc().camera, 4, 4), VolumeView{4, 4, 0.0f}, options);
      ASSERT_FALSE(image.ok()) << step;
      EXPECT_EQ(image.error().status, ExitStatus::invalid_input);
      EXPECT_EQ(image.error().message.starts_with("shadow step"), shadow) << image.error().message;
    }
}

// Every volume graph of the gallery: the interpreter and the JIT give the
// same picture, which is not blank.
TEST(VolumeDriver, GalleryBackendsAgree) {
  const auto files = testing::gallery_graphs(GraphKind::volume);
  EXPECT_FALSE(files.empty());
  for (const std::string& file : files) {
    Result<LoadedGraph> loaded = testing::load_gallery_graph(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
    const RenderSettings& settings = loaded->graph->render;
    ASSERT_TRUE(settings.volume) << file;
    const SceneDesc desc = volume_scene(settings.scene);
    auto interpreted = make_interpreted_kernel(loaded->ir);
    Result<std::unique_ptr<Kernel>> compiled = make_jit_kernel(loaded->ir);
    ASSERT_TRUE(compiled.ok()) << compiled.error().to_string();
    VolumeDesc volume = *settings.volume;
    volume.step = std::max(march_step(volume), 0.02f);  // a coarse march keeps the test quick
    const Image a = render(*interpreted, *loaded, desc, volume, 64);
    const Image b = render(**compiled, *loaded, desc, volume, 64);
    EXPECT_LE(largest_difference(a, b), 1e-4f) << file;
    EXPECT_EQ(a.pixels, b.pixels) << file << ": the backends agree to the bit";
    const auto [low, high] = std::minmax_element(a.pixels.begin(), a.pixels.end());
    EXPECT_GT(*high - *low, 0.1f) << file << ": the image is (nearly) constant";
  }
}

// Samples skipped in empty space (render/occupancy_grid.h) are those whose
// opacity is certainly 0, which add nothing to a ray: skipping them
// changes no pixel, with shadows marched or cached, on a soft sphere and
// on gallery volumes whose bounds are mostly empty (fur, drips, glass).
// --normals exact: one sample of the graph's normal kernel (the density's
// exact gradient) per soft sample instead of two probes. The probes'
// difference over a step and the derivative agree closely on the gallery's
// noisy sphere and tribble (within 2/255 on average), with half the
// gradient samples.
TEST(VolumeDriver, ExactNormalsAgreeWithProbesAtHalfTheGradientSamples) {
  for (const char* name : {"noisy_sphere", "tribble"}) {
    SCOPED_TRACE(name);
    const std::string file = SHADETREE_SOURCE_DIR "/graphs/" + std::string(name) + ".json";
    Result<LoadedGraph> loaded = testing::load_gallery_graph(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
    Result<LoadedGraph> with_normal = compile_graph(with_normal_from_density(*loaded->graph), {}, graph_files());
    ASSERT_TRUE(with_normal.ok()) << with_normal.error().to_string();
    Result<std::unique_ptr<Kernel>> kernel = make_jit_kernel(loaded->ir);
    Result<std::unique_ptr<Kernel>> normal_kernel = make_jit_kernel(with_normal->ir);
    ASSERT_TRUE(kernel.ok() && normal_kernel.ok());
    const SceneDesc scene = volume_scene(loaded->graph->render.scene);
    const VolumeDesc& volume = *loaded->graph->render.volume;
    VolumeRenderOptions probes, exact;
    probes.faint_normals = 0.0f;  // every soft sample probed
    exact.normal_kernel = normal_kernel->get();
    VolumeRenderStats probed_stats, exact_stats;
    const Image a = render(**kernel, *loaded, scene, volume, 64, probes, &probed_stats);
    const Image b = render(**kernel, *loaded, scene, volume, 64, exact, &exact_stats);
    double total = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) total += std::fabs(a.pixels[i] - b.pixels[i]);
    EXPECT_LT(total / double(a.pixels.size()), 2.0 / 255);
    EXPECT_GT(largest_difference(a, b), 0.0f) << "the two gradients are computed differently";
    EXPECT_GT(exact_stats.gradient_samples, 0);
    EXPECT_LE(exact_stats.gradient_samples, probed_stats.gradient_samples / 2 + 64 * 64);
  }
}

// A faint sample takes the slopes across its ray from the ray's last
// probed sample. Across a linear density they are the same everywhere, so
// a march whose every sample but a ray's first is faint lights them as
// probing each would, from two probes a ray.
TEST(VolumeDriver, FaintSamplesOfALinearDensityAreLitAsIfProbed) {
  const LoadedGraph loaded = compile_volume(R"({"id": "p", "op": "P"},
      {"id": "slope", "op": "dot", "in": {"a": "p", "b": [0.05, 0.1, 0.02]}},
      {"id": "ramp", "op": "add", "in": {"a": "slope", "b": 0.2}})",
                                            R"("density": "ramp", "color": [1, 1, 1])");
  auto kernel = make_interpreted_kernel(loaded.ir);
  SceneDesc desc = looking_down_z(Lighting::lit);
  desc.lights[0].direction = {1.0f, 0.5f, -0.3f};
  VolumeRenderOptions probing, faint;
  probing.shadows = faint.shadows = ShadowMode::off;
  probing.faint_normals = 0.0f;
  faint.faint_normals = 1.0f;
  VolumeRenderStats probing_stats, faint_stats;
  const Image probed = render(*kernel, loaded, desc, unit_box(0.01f), 20, probing, &probing_stats);
  const Image taken = render(*kernel, loaded, desc, unit_box(0.01f), 20, faint, &faint_stats);
  EXPECT_LT(largest_difference(probed, taken), 1e-4f);
  EXPECT_GT(*std::max_element(taken.pixels.begin(), taken.pixels.end()), 0.1f);
  EXPECT_EQ(faint_stats.gradient_samples, 2 * faint_stats.rays);
  EXPECT_GT(probing_stats.gradient_samples, 10 * faint_stats.gradient_samples);
}

// A graph that gives its own normal is lit by it: no gradient samples.
// Here the normal faces the light everywhere, so every soft sample is lit
// as if head-on, brighter than by the sphere's own gradient at its rim.
TEST(VolumeDriver, AGraphsOwnNormalLightsItsSoftSamples) {
  const std::string nodes = R"({"id": "p", "op": "P"},
      {"id": "s", "op": "sphere", "in": {"p": "p", "radius": 0.5, "softness": 0.8}})";
  const LoadedGraph own = compile_volume(nodes, R"("density": "s", "normal": [0, 0, 1])");
  const LoadedGraph derived = compile_volume(nodes, R"("density": "s")");
  const SceneDesc desc = looking_down_z(Lighting::lit);
  VolumeRenderStats stats;
  const Image lit_head_on = render(*make_interpreted_kernel(own.ir), own, desc, unit_box(0.02f), 32, {}, &stats);
  EXPECT_EQ(stats.gradient_samples, 0);
  const Image by_gradient = render(*make_interpreted_kernel(derived.ir), derived, desc, unit_box(0.02f), 32);
  const std::size_t rim = (16 * 32 + 10) * 3;  // x = -0.52: in the sphere's soft rim
  EXPECT_GT(by_gradient.pixels[rim], 0.0f);
  EXPECT_GT(lit_head_on.pixels[rim], by_gradient.pixels[rim]);
}

// A hard surface (a step of a soft density) is lit only where it is
// reached: a ray stops at its first sample of opacity 1, so at most that
// one is probed for its normal, not the samples of the soft shell before
// it, whose opacity is 0.
TEST(VolumeDriver, OnlySamplesThatAddToARayAreProbedForTheirNormal) {
  const std::string nodes = R"({"id": "p", "op": "P"},
      {"id": "s", "op": "sphere", "in": {"p": "p", "radius": 0.5, "softness": 0.8}},
      {"id": "hard", "op": "step", "in": {"edge": 0.5, "x": "s"}})";
  const LoadedGraph surface = compile_volume(nodes, R"("density": "s", "opacity": "hard")");
  const SceneDesc desc = looking_down_z(Lighting::lit);
  constexpr int size = 32;
  VolumeRenderStats stats;
  const Image image = render(*make_interpreted_kernel(surface.ir), surface, desc, unit_box(0.02f), size, {}, &stats);
  // The rays that meet the sphere, each lit at one sample from two probes.
  long hits = 0;
  for (std::size_t i = 0; i < image.pixels.size(); i += 3) hits += image.pixels[i] > 0.0f;
  EXPECT_GT(hits, size * size / 10);
  EXPECT_EQ(stats.gradient_samples, 2 * hits);
}

TEST(VolumeDriver, SkippingEmptySpaceChangesNoPixel) {
  const LoadedGraph sphere = compile_volume(R"({"id": "p", "op": "P"},
      {"id": "s", "op": "sphere", "in": {"p": "p", "radius": 0.3, "softness": 0.2}},
      {"id": "c", "op": "to_color", "in": {"v": "p"}}, {"id": "tint", "op": "abs", "in": {"x": "c"}})",
                                            R"("density": "s", "color": "tint")");
  SceneDesc desc = looking_down_z(Lighting::lit);
  desc.lights[0].direction = {1.0f, 0.0f, -0.3f};
  for (ShadowMode mode : {ShadowMode::exact, ShadowMode::cached}) {
    VolumeRenderOptions skipping, marching;
    skipping.shadows = marching.shadows = mode;
    skipping.bound_finely_always = true;
    marching.skip_empty_space = false;
    VolumeRenderStats stats;
    auto kernel = make_interpreted_kernel(sphere.ir);
    EXPECT_EQ(render(*kernel, sphere, desc, unit_box(0.02f), 40, skipping, &stats).pixels,
              render(*kernel, sphere, desc, unit_box(0.02f), 40, marching).pixels);
    EXPECT_GT(stats.skipped_samples, 0);
    EXPECT_GT(stats.empty_fraction, 0.5);
  }
  for (const char* name : {"tribble", "dripping_sphere", "noisy_sphere_hifreq", "blue_glass"}) {
    Result<LoadedGraph> loaded = testing::load_gallery_graph(SHADETREE_SOURCE_DIR "/graphs/" + std::string(name) + ".json");
    ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
    Result<std::unique_ptr<Kernel>> compiled = make_jit_kernel(loaded->ir);
    ASSERT_TRUE(compiled.ok()) << compiled.error().to_string();
    const SceneDesc scene = volume_scene(loaded->graph->render.scene);
    VolumeDesc volume = *loaded->graph->render.volume;
    volume.step = std::max(march_step(volume), 0.02f);
    VolumeRenderOptions skipping, marching;
    skipping.bound_finely_always = true;
    marching.skip_empty_space = false;
    VolumeRenderStats stats;
    EXPECT_EQ(render(**compiled, *loaded, scene, volume, 48, skipping, &stats).pixels,
              render(**compiled, *loaded, scene, volume, 48, marching).pixels)
        << name;
    EXPECT_GT(stats.skipped_samples, 0) << name;
  }
}

// Empty space found by one render is read again by the next of the same
// graph, params, frame and bounds (render/occupancy_grid_cache.h), from
// another camera or light: the same cells, so the same pixels as bounding
// anew.
TEST(VolumeDriver, EmptySpaceFoundOnceIsReadAgain) {
  const LoadedGraph sphere = compile_volume(R"({"id": "p", "op": "P"},
      {"id": "s", "op": "sphere", "in": {"p": "p", "radius": 0.3, "softness": 0.2}})",
                                            R"("density": "s")");
  auto kernel = make_interpreted_kernel(sphere.ir);
  testing::TempFolder cache("shadetree-volume-empty-space");
  VolumeRenderOptions options;
  options.bound_finely_always = true;
  options.empty_space_cache = cache.path();
  SceneDesc desc = looking_down_z(Lighting::lit);
  VolumeRenderStats first, second, anew;
  const Image found = render(*kernel, sphere, desc, unit_box(0.02f), 40, options, &first);
  EXPECT_FALSE(first.empty_space_read);
  EXPECT_EQ(first.empty_space, EmptySpaceVerdict::skipped);
  desc.lights[0].direction = {1.0f, 0.0f, -0.3f};
  const Image read = render(*kernel, sphere, desc, unit_box(0.02f), 40, options, &second);
  EXPECT_TRUE(second.empty_space_read);
  EXPECT_EQ(second.empty_fraction, first.empty_fraction);
  EXPECT_GT(second.skipped_samples, 0);
  options.empty_space_cache.clear();
  EXPECT_EQ(read.pixels, render(*kernel, sphere, desc, unit_box(0.02f), 40, options, &anew).pixels);
  EXPECT_FALSE(anew.empty_space_read);
  EXPECT_NE(found.pixels, read.pixels) << "the light moved";
}

// A sequence's frames share one renderer, which remembers a frame's
// verdict that skipping would not pay (the fireball's own `if` passes
// over its empty space) and neither bounds nor times the later frames
// again: their pixels are those of a renderer of their own.
TEST(VolumeDriver, ASequenceBoundsItsEmptySpaceOnceWhereSkippingWouldNotPay) {
  Result<LoadedGraph> loaded = testing::load_gallery_graph(SHADETREE_SOURCE_DIR "/graphs/fireball.json");
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  Result<std::unique_ptr<Kernel>> compiled = make_jit_kernel(loaded->ir);
  ASSERT_TRUE(compiled.ok()) << compiled.error().to_string();
  RenderRequest request;
  request.size = {40, 40};
  const auto renderer = [&] {
    Result<std::unique_ptr<FrameRenderer>> prepared = prepare_render(*loaded->graph, request);
    EXPECT_TRUE(prepared.ok()) << prepared.error().to_string();
    return std::move(*prepared);
  };
  const auto figure = [](const FrameReport& report, const std::string& name) {
    for (const auto& [key, value] : report.figures)
      if (key == name) return value;
    return -1.0;
  };
  const std::unique_ptr<FrameRenderer> sequence = renderer();
  FrameReport first, second;
  Result<Image> frame0 = sequence->render(**compiled, loaded->params, 0.0f, {}, &first);
  Result<Image> frame1 = sequence->render(**compiled, loaded->params, 1.0f, {}, &second);
  ASSERT_TRUE(frame0.ok() && frame1.ok());
  EXPECT_EQ(frame1->pixels, (*renderer()->render(**compiled, loaded->params, 1.0f, {}, nullptr)).pixels);
  EXPECT_EQ(figure(first, "skipped_samples"), 0.0);
  if (first.what.find("evaluates it for next to nothing") != std::string::npos) {
    EXPECT_NE(second.what.find("as an earlier frame found"), std::string::npos) << second.what;
    EXPECT_EQ(figure(second, "bounds_s"), 0.0);
  }
}

// Cached shadows against the exact shadow march, on volumes of the
// gallery that stand for the others (fur, hard noisy surfaces, glass, a
// cloud over opaque objects; docs/architecture.md has the figures of
// every one at 256x256): the grid's light rays march what the shadow rays
// march, and lose only detail finer than their spacing; the cached
// render's rays also end early. Mean and 99th percentile of the
// per-channel difference, in 8-bit steps.
TEST(VolumeDriver, CachedShadowsAgreeWithExactOnes) {
  for (const char* name : {"furry_donut", "noisy_sphere_hiamp", "fractal_sphere", "blue_glass", "cloud_over_floor"}) {
    const std::string file = SHADETREE_SOURCE_DIR "/graphs/" + std::string(name) + ".json";
    Result<LoadedGraph> loaded = testing::load_gallery_graph(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
    Result<std::unique_ptr<Kernel>> compiled = make_jit_kernel(loaded->ir);
    ASSERT_TRUE(compiled.ok()) << compiled.error().to_string();
    const SceneDesc desc = volume_scene(loaded->graph->render.scene);
    VolumeRenderOptions exact, cached;
    exact.shadows = ShadowMode::exact;
    exact.extrapolation = 0.0f;  // as `render --shadows exact` marches
    const VolumeDesc& volume = *loaded->graph->render.volume;
    const Image a = render(**compiled, *loaded, desc, volume, 128, exact);
    const Image b = render(**compiled, *loaded, desc, volume, 128, cached);
    std::vector<float> differences(a.pixels.size());
    for (std::size_t i = 0; i < a.pixels.size(); ++i) differences[i] = 255.0f * std::fabs(a.pixels[i] - b.pixels[i]);
    std::sort(differences.begin(), differences.end());
    double sum = 0.0;
    for (float difference : differences) sum += difference;
    EXPECT_LE(sum / static_cast<double>(differences.size()), 1.0) << file << ": mean";
    EXPECT_LE(differences[differences.size() * 99 / 100], 4.0f) << file << ": 99th percentile";
  }
}

}  // namespace
}  // namespace shadetree

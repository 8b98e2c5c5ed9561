// The surface driver: lighting against closed forms, normal perturbation,
// filtering of the receding checkerboard, backends, frames and threads.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>

#include "interp/interpreter.h"
#include "jit/jit_kernel.h"
#include "pipeline/compile_graph.h"
#include "render/surface_driver.h"
#include "support/gallery.h"
#include "support/graph_text.h"

namespace shadetree {
namespace {

LoadedGraph compile_surface(const std::string& nodes, const std::string& outputs, const std::string& render = "") {
  Result<LoadedGraph> loaded = compile_graph_text(
      testing::graph_text(nodes, outputs, render.empty() ? "" : R"("render": )" + render + ",", "surface"),
      "surface.json");
  EXPECT_TRUE(loaded.ok()) << loaded.error().to_string();
  return std::move(*loaded);
}

Scene build_scene(const SceneDesc& desc) {
  Result<Scene> scene = Scene::build(desc, "surface.json", {});
  EXPECT_TRUE(scene.ok()) << scene.error().to_string();
  return std::move(*scene);
}

Image render(const Kernel& kernel, const LoadedGraph& loaded, const Scene& scene, int size, int threads = 0,
             float frame = 0.0f, int samples_per_pixel = 1) {
  SurfaceView view;
  view.width = view.height = size;
  view.frame = frame;
  view.samples_per_pixel = samples_per_pixel;
  SurfaceRenderOptions options;
  options.threads = threads;
  Result<Image> image = render_surface(kernel, loaded.params, scene, Camera(scene.desc().camera, size, size), view,
                                       options);
  EXPECT_TRUE(image.ok()) << image.error().to_string();
  return std::move(*image);
}

// A unit sphere seen along -z by an orthographic camera 2.5 units high,
// lit by one directional light travelling along `light`, no ambient.
SceneDesc sphere_under_one_light(std::array<float, 3> light) {
  SceneDesc desc;
  desc.camera.position = {0.0f, 0.0f, 5.0f};
  desc.camera.orthographic = true;
  desc.camera.orthographic_height = 2.5f;
  desc.objects.push_back(ObjectDesc{});
  LightDesc sun;
  sun.direction = light;
  sun.intensity = 0.8f;
  desc.lights = {sun};
  desc.ambient = {0.0f, 0.0f, 0.0f};
  desc.background = {0.0f, 0.0f, 0.0f};
  return desc;
}

TEST(SurfaceDriver, ConstantColourUnderOneDirectionalLightIsExactlyLambert) {
  const LoadedGraph loaded = compile_surface("", R"("color": [0.5, 0.4, 0.3], "specular": 0)");
  const Scene scene = build_scene(sphere_under_one_light({0.0f, 0.0f, -1.0f}));
  auto kernel = make_interpreted_kernel(loaded.ir);
  const int size = 64;
  const Image image = render(*kernel, loaded, scene, size);
  int lit = 0;
  for (int row = 0; row < size; ++row) {
    for (int column = 0; column < size; ++column) {
      // The pixel centre's point on the sphere; the light comes from +z,
      // so N.L is the point's z.
      const float x = ((column + 0.5f) / size * 2.0f - 1.0f) * 1.25f;
      const float y = (1.0f - (row + 0.5f) / size * 2.0f) * 1.25f;
      const float z2 = 1.0f - x * x - y * y;
      const float* pixel = &image.pixels[(static_cast<std::size_t>(row) * size + column) * 3];
      if (z2 <= 1e-3f) continue;  // the silhouette: hit or miss is a matter of rounding
      ++lit;
      const float cosine = std::sqrt(z2);
      EXPECT_NEAR(pixel[0], 0.5f * 0.8f * cosine, 1e-5f) << column << "," << row;
      EXPECT_NEAR(pixel[1], 0.4f * 0.8f * cosine, 1e-5f);
      EXPECT_NEAR(pixel[2], 0.3f * 0.8f * cosine, 1e-5f);
    }
  }
  EXPECT_GT(lit, 2000);
}

TEST(SurfaceDriver, LightingNoneShowsTheGraphColourAndItsOwnShading) {
  // With "lighting": "none" the graph lights itself from N and L.
  const LoadedGraph loaded = compile_surface(
      R"({"id": "n", "op": "N"}, {"id": "l", "op": "L"}, {"id": "d", "op": "dot", "in": {"a": "n", "b": "l"}},
         {"id": "c", "op": "color", "in": {"r": "d", "g": "d", "b": "d"}})",
      R"("color": "c")");
  SceneDesc desc = sphere_under_one_light({0.0f, 0.0f, -1.0f});
  desc.lighting = Lighting::none;
  const Scene scene = build_scene(desc);
  auto kernel = make_interpreted_kernel(loaded.ir);
  const Image image = render(*kernel, loaded, scene, 32);
  const float* centre = &image.pixels[(16 * 32 + 16) * 3];
  const float x = (16.5f / 32 * 2 - 1) * 1.25f, y = (1 - 16.5f / 32 * 2) * 1.25f;
  EXPECT_NEAR(centre[0], std::sqrt(1 - x * x - y * y), 1e-5f);
}

TEST(SurfaceDriver, PerturbedNormalChangesShadingOnlyWhereThePerturbationIsNonZero) {
  // N + dnoise(4P), masked to the right half (x > 0) of the sphere.
  const std::string nodes = R"({"id": "p", "op": "P"}, {"id": "n", "op": "N"},
      {"id": "q", "op": "mul", "in": {"a": "p", "b": 4}}, {"id": "g", "op": "dnoise", "in": {"p": "q"}},
      {"id": "xyz", "op": "split", "in": {"v": "p"}}, {"id": "right", "op": "step", "in": {"edge": 0, "x": "xyz.x"}},
      {"id": "tilt", "op": "mul", "in": {"a": "g", "b": "right"}},
      {"id": "bumped", "op": "add", "in": {"a": "n", "b": "tilt"}})";
  const LoadedGraph plain = compile_surface(nodes, R"("color": [0.7, 0.7, 0.7], "normal": "n")");
  const LoadedGraph bumpy = compile_surface(nodes, R"("color": [0.7, 0.7, 0.7], "normal": "bumped")");
  const Scene scene = build_scene(sphere_under_one_light({0.3f, -0.4f, -1.0f}));
  const int size = 64;
  const Image a = render(*make_interpreted_kernel(plain.ir), plain, scene, size);
  const Image b = render(*make_interpreted_kernel(bumpy.ir), bumpy, scene, size);
  int left_changed = 0, right_changed = 0, right_hit = 0;
  for (int row = 0; row < size; ++row)
    for (int column = 0; column < size; ++column) {
      const std::size_t i = (static_cast<std::size_t>(row) * size + column) * 3;
      const bool changed = a.pixels[i] != b.pixels[i];
      if (column < size / 2 - 1) left_changed += changed;
      if (column > size / 2 && a.pixels[i] > 0.0f) {
        ++right_hit;
        right_changed += changed;
      }
    }
  EXPECT_EQ(left_changed, 0);
  EXPECT_GT(right_changed, right_hit * 9 / 10);
}

// The 1992 checkerboard on a plane receding to the horizon: a square wave
// in x and z, box-filtered over the pixel footprint or not.
LoadedGraph checkerboard(bool filtered) {
  const std::string width = filtered ? R"("fw")" : "0";
  return compile_surface(
      R"({"id": "p", "op": "P"}, {"id": "fw", "op": "filter_width"}, {"id": "xyz", "op": "split", "in": {"v": "p"}},
         {"id": "sx", "op": "swave", "in": {"x": "xyz.x", "filter_width": )" + width + R"(}},
         {"id": "sz", "op": "swave", "in": {"x": "xyz.z", "filter_width": )" + width + R"(}},
         {"id": "a", "op": "mul", "in": {"a": "sx", "b": "sz"}},
         {"id": "na", "op": "sub", "in": {"a": 1, "b": "sx"}}, {"id": "nb", "op": "sub", "in": {"a": 1, "b": "sz"}},
         {"id": "b", "op": "mul", "in": {"a": "na", "b": "nb"}}, {"id": "c", "op": "add", "in": {"a": "a", "b": "b"}})",
      R"("color": "c")");
}

// Energy of the differences between horizontal neighbours in the image's
// upper (far) half, where the squares are smaller than a pixel.
double far_high_frequency_energy(const Image& image) {
  double energy = 0.0;
  for (int row = image.height / 4; row < image.height / 2; ++row)
    for (int column = 1; column < image.width; ++column) {
      const std::size_t i = (static_cast<std::size_t>(row) * image.width + column) * 3;
      const double difference = image.pixels[i] - image.pixels[i - 3];
      energy += difference * difference;
    }
  return energy;
}

TEST(SurfaceDriver, FilteredFarCheckerboardLosesItsMoire) {
  SceneDesc desc;
  desc.camera.position = {0.0f, 1.0f, 0.0f};
  desc.camera.target = {0.0f, 0.8f, -10.0f};
  desc.camera.fov_degrees = 60.0f;
  ObjectDesc plane;
  plane.type = ObjectType::plane;
  desc.objects = {plane};
  desc.lighting = Lighting::none;
  const Scene scene = build_scene(desc);
  const LoadedGraph sharp = checkerboard(false), filtered = checkerboard(true);
  const double sharp_energy = far_high_frequency_energy(render(*make_interpreted_kernel(sharp.ir), sharp, scene, 128));
  const double filtered_energy =
      far_high_frequency_energy(render(*make_interpreted_kernel(filtered.ir), filtered, scene, 128));
  EXPECT_GT(sharp_energy, 100.0);
  EXPECT_LT(filtered_energy, 0.25 * sharp_energy) << sharp_energy << " vs " << filtered_energy;
}

TEST(SurfaceDriver, BackendsAgreeAndThreadCountsDoNotMatter) {
  for (const std::string& file : testing::gallery_graphs(GraphKind::surface)) {
    Result<LoadedGraph> loaded = testing::load_gallery_graph(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
    Result<Scene> scene = Scene::build(*loaded->graph->render.scene, file, {});
    ASSERT_TRUE(scene.ok()) << scene.error().to_string();
    auto interpreted = make_interpreted_kernel(loaded->ir);
    Result<std::unique_ptr<Kernel>> compiled = make_jit_kernel(loaded->ir);
    ASSERT_TRUE(compiled.ok()) << compiled.error().to_string();
    const Image a = render(*interpreted, *loaded, *scene, 48, 1, 0.0f, 2);
    const Image b = render(**compiled, *loaded, *scene, 48, 2, 0.0f, 2);
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    for (std::size_t i = 0; i < a.pixels.size(); ++i) ASSERT_NEAR(a.pixels[i], b.pixels[i], 1e-4f) << file << " " << i;
    EXPECT_EQ(a.pixels, b.pixels) << file << ": the backends agree to the bit";
    const auto [low, high] = std::minmax_element(a.pixels.begin(), a.pixels.end());
    EXPECT_GT(*high - *low, 0.1f) << file << ": the image is (nearly) constant";
  }
}

// The gallery's bumpy donut tilts its normal with the bump node (exact
// derivatives of a height); Perlin 1985 built it by hand, N + bumpiness
// Dnoise(scale P). Blinn's bump drops the part of the gradient along N,
// which Perlin's sum keeps, so the two differ slightly where the tilt is
// large: within 1/255 on average over the picture.
TEST(SurfaceDriver, TheBumpNodeGivesTheHandBuiltBumpyDonut) {
  const std::string file = SHADETREE_SOURCE_DIR "/graphs/donut_bumpy.json";
  Result<LoadedGraph> bumped = testing::load_gallery_graph(file);
  ASSERT_TRUE(bumped.ok()) << bumped.error().to_string();
  std::ifstream stream(file);
  std::string text((std::istreambuf_iterator<char>(stream)), std::istreambuf_iterator<char>());
  const std::size_t begin = text.find("\"nodes\""), end = text.find("\"outputs\"");
  text.replace(begin, end - begin, R"("nodes": [{"id": "p", "op": "P"}, {"id": "n", "op": "N"},
    {"id": "scaled", "op": "mul", "in": {"a": "p", "b": "$scale"}},
    {"id": "gradient", "op": "dnoise", "in": {"p": "scaled"}},
    {"id": "tilt", "op": "mul", "in": {"a": "gradient", "b": "$bumpiness"}},
    {"id": "bumped", "op": "add", "in": {"a": "n", "b": "tilt"}}], )");
  Result<LoadedGraph> by_hand = compile_graph_text(text, file);
  ASSERT_TRUE(by_hand.ok()) << by_hand.error().to_string();
  Result<Scene> scene = Scene::build(*bumped->graph->render.scene, file, {});
  ASSERT_TRUE(scene.ok()) << scene.error().to_string();
  const Image a = render(**make_jit_kernel(bumped->ir), *bumped, *scene, 256);
  const Image b = render(**make_jit_kernel(by_hand->ir), *by_hand, *scene, 256);
  double total = 0, largest = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    total += std::fabs(a.pixels[i] - b.pixels[i]);
    largest = std::max(largest, double(std::fabs(a.pixels[i] - b.pixels[i])));
  }
  EXPECT_LT(total / double(a.pixels.size()), 1.0 / 255);
  EXPECT_GT(largest, 0.0) << "the two normals are computed differently";
}

TEST(SurfaceDriver, FramesDifferOnlyWhereTheGraphReadsTheFrame) {
  const Scene scene = build_scene(sphere_under_one_light({0.0f, 0.0f, -1.0f}));
  const LoadedGraph still = compile_surface(R"({"id": "p", "op": "P"}, {"id": "n", "op": "noise", "in": {"p": "p"}})",
                                            R"("color": "n")");
  const LoadedGraph moving = compile_surface(
      R"({"id": "p", "op": "P"}, {"id": "t", "op": "frame"}, {"id": "q", "op": "add", "in": {"a": "p", "b": "t"}},
         {"id": "n", "op": "noise", "in": {"p": "q"}})",
      R"("color": "n")");
  auto still_kernel = make_interpreted_kernel(still.ir);
  auto moving_kernel = make_interpreted_kernel(moving.ir);
  EXPECT_EQ(render(*still_kernel, still, scene, 32, 0, 1.0f).pixels,
            render(*still_kernel, still, scene, 32, 0, 7.0f).pixels);
  EXPECT_NE(render(*moving_kernel, moving, scene, 32, 0, 1.0f).pixels,
            render(*moving_kernel, moving, scene, 32, 0, 7.0f).pixels);
}

TEST(SurfaceDriver, ShadowRaysDarkenWhatLiesBehindAnObject) {
  // A sphere above a floor, lit from straight above: the floor below the
  // sphere is in shadow (ambient only), the floor beside it is not.
  SceneDesc desc;
  desc.camera.position = {0.0f, 6.0f, 0.01f};
  desc.camera.target = {0.0f, 0.0f, 0.0f};
  desc.camera.fov_degrees = 60.0f;
  ObjectDesc ball;
  ball.transform.translate = {0.0f, 2.0f, 0.0f};
  ball.radius = 0.5f;
  ObjectDesc floor;
  floor.type = ObjectType::plane;
  desc.objects = {ball, floor};
  LightDesc sun;
  sun.direction = {0.0f, -1.0f, 0.0f};
  desc.lights = {sun};
  desc.ambient = {0.1f, 0.1f, 0.1f};
  const Scene scene = build_scene(desc);
  const LoadedGraph loaded = compile_surface("", R"("color": [1, 1, 1], "specular": 0)");
  auto kernel = make_interpreted_kernel(loaded.ir);
  const Image image = render(*kernel, loaded, scene, 64);
  // Seen from above, the ball covers the centre; its shadow (radius 0.5 on
  // the floor) is hidden by the ball itself, which is lit. The floor at a
  // corner is fully lit.
  EXPECT_NEAR(image.pixels[0], 1.1f, 1e-5f);
  SceneDesc low_sun = desc;
  low_sun.lights[0].direction = {1.0f, -1.0f, 0.0f};  // shadow moves 2 units to +x
  const Scene moved = build_scene(low_sun);
  const Image shadowed = render(*kernel, loaded, moved, 64);
  // World (2, 0, 0) lies in the shadow, about 13 pixels of the middle row.
  int darkest = 0;
  for (int column = 0; column < 64; ++column) {
    const float value = shadowed.pixels[(32 * 64 + column) * 3];
    if (value < 0.1001f) ++darkest;
  }
  EXPECT_GT(darkest, 2) << "no pixel of the middle row lies in the shadow";
}

}  // namespace
}  // namespace shadetree

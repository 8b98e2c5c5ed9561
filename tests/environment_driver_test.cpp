// The environment driver: the panorama's directions and uv, the graph's
// colour for each against closed forms on both backends, and environments
// as the backgrounds of surface and volume scenes.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "interp/interpreter.h"
#include "jit/jit_kernel.h"
#include "pipeline/compile_graph.h"
#include "render/environment_driver.h"
#include "render/graph_kinds.h"
#include "support/graph_text.h"
#include "support/temp_folder.h"

namespace shadetree {
namespace {

// An environment whose colour is the direction, mapped to [0, 1]: I / 2 + 1/2.
const std::string direction_colour = testing::graph_text(
    R"({"id": "i", "op": "I"}, {"id": "half", "op": "mul", "in": {"a": "i", "b": 0.5}},
       {"id": "up", "op": "add", "in": {"a": "half", "b": 0.5}}, {"id": "c", "op": "to_color", "in": {"v": "up"}})",
    R"("color": "c")", R"("render": {"size": [16, 8]},)", "environment");

glm::vec3 pixel(const Image& image, int column, int row) {
  const float* p = image.pixels.data() + (static_cast<std::size_t>(row) * image.width + column) * image.channels;
  return {p[0], p[1], p[2]};
}

Image render(const LoadedGraph& loaded, const Kernel& kernel, std::pair<int, int> size,
             const std::vector<std::string>& search_paths = {}) {
  RenderRequest request;
  request.size = size;
  request.search_paths = search_paths;
  Result<std::unique_ptr<FrameRenderer>> renderer = prepare_render(*loaded.graph, request);
  EXPECT_TRUE(renderer.ok()) << renderer.error().to_string();
  Result<Image> image = (*renderer)->render(kernel, loaded.params, 0.0f, {}, nullptr);
  EXPECT_TRUE(image.ok()) << image.error().to_string();
  return std::move(*image);
}

TEST(EnvironmentDriver, PanoramaDirectionsCoverTheSphere) {
  const auto near = [](glm::vec3 a, glm::vec3 b) { return glm::length(a - b) < 1e-6f; };
  EXPECT_TRUE(near(panorama_direction(8, 4, 16, 8), {0, 0, -1}));  // the centre looks down -z
  EXPECT_TRUE(near(panorama_direction(12, 4, 16, 8), {1, 0, 0}));  // a quarter turn right: +x
  EXPECT_TRUE(near(panorama_direction(4, 4, 16, 8), {-1, 0, 0}));
  EXPECT_TRUE(near(panorama_direction(0, 4, 16, 8), {0, 0, 1}));   // the seam looks behind
  EXPECT_NEAR(panorama_direction(5, 0, 16, 8).y, 1.0f, 1e-6f);     // the top row is the zenith
  EXPECT_NEAR(panorama_direction(5, 8, 16, 8).y, -1.0f, 1e-6f);
  for (float x : {0.3f, 5.5f, 15.9f})
    for (float y : {0.1f, 3.7f, 7.9f}) EXPECT_NEAR(glm::length(panorama_direction(x, y, 16, 8)), 1.0f, 1e-6f);
}

TEST(EnvironmentDriver, EachPixelIsTheGraphOfItsDirectionOnBothBackends) {
  Result<LoadedGraph> loaded = compile_graph_text(direction_colour, "sky.json");
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  const Image interpreted = render(*loaded, *make_interpreted_kernel(loaded->ir), {16, 8});
  const Image compiled = render(*loaded, **make_jit_kernel(loaded->ir), {16, 8});
  ASSERT_EQ(interpreted.width, 16);
  ASSERT_EQ(interpreted.height, 8);
  for (int row = 0; row < 8; ++row)
    for (int column = 0; column < 16; ++column) {
      const glm::vec3 expected = 0.5f * panorama_direction(column + 0.5f, row + 0.5f, 16, 8) + 0.5f;
      EXPECT_LT(glm::length(pixel(interpreted, column, row) - expected), 1e-6f) << column << ", " << row;
      EXPECT_EQ(pixel(interpreted, column, row), pixel(compiled, column, row)) << column << ", " << row;
    }
}

// uv is (longitude, latitude) over [0, 1]: the panorama's own image coordinates.
TEST(EnvironmentDriver, UvIsThePanoramasImageCoordinates) {
  Result<LoadedGraph> loaded = compile_graph_text(
      testing::graph_text(R"({"id": "t", "op": "uv"}, {"id": "s", "op": "split", "in": {"v": "t"}},
                             {"id": "c", "op": "color", "in": {"r": "s.x", "g": "s.y"}})",
                          R"("color": "c")", "", "environment"),
      "uv.json");
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  const Image image = render(*loaded, *make_interpreted_kernel(loaded->ir), {32, 16});
  for (int row = 0; row < 16; ++row)
    for (int column = 0; column < 32; ++column) {
      EXPECT_NEAR(pixel(image, column, row).x, (column + 0.5f) / 32.0f, 1e-5f);
      EXPECT_NEAR(pixel(image, column, row).y, 1.0f - (row + 0.5f) / 16.0f, 1e-5f);
    }
}

// Where a camera ray meets nothing, a surface scene shows its environment
// in the ray's direction; where it meets the sphere, the graph's colour.
TEST(EnvironmentDriver, SurfaceScenesSeeTheirEnvironmentBehindTheirObjects) {
  testing::TempFolder folder("shadetree-environment");
  folder.write("sky.json", direction_colour);
  const std::string camera = R"({"position": [0, 0, 4], "target": [0, 0, 0], "fov": 40})";
  Result<LoadedGraph> loaded = compile_graph_text(
      testing::graph_text("", R"("color": [1, 0, 1])",
                          R"("render": {"scene": {"camera": )" + camera +
                              R"(, "objects": [{"type": "sphere", "radius": 0.5}], "lighting": "none",
                               "environment": "sky.json"}},)",
                          "surface"),
      folder.write("ball.json", ""));
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  const Image image = render(*loaded, *make_interpreted_kernel(loaded->ir), {24, 24});
  CameraDesc desc;
  const Camera view(desc, 24, 24);
  for (auto [column, row] : {std::pair{0, 0}, {23, 0}, {0, 23}, {5, 17}}) {
    const glm::vec3 expected = 0.5f * glm::normalize(view.ray(column + 0.5f, row + 0.5f).direction) + 0.5f;
    EXPECT_LT(glm::length(pixel(image, column, row) - expected), 1e-5f) << column << ", " << row;
  }
  EXPECT_EQ(pixel(image, 12, 12), glm::vec3(1, 0, 1));
}

// A volume of no density shows only what lies behind it.
TEST(EnvironmentDriver, VolumeScenesSeeTheirEnvironmentThroughTheVolume) {
  testing::TempFolder folder("shadetree-environment");
  folder.write("sky.json", direction_colour);
  Result<LoadedGraph> loaded = compile_graph_text(
      testing::graph_text("", R"("density": 0)",
                          R"("render": {"scene": {"environment": "sky.json"},
                               "volume": {"bounds": {"min": [-1, -1, -1], "max": [1, 1, 1]}}},)",
                          "volume"),
      folder.write("empty.json", ""));
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  const Image image = render(*loaded, *make_interpreted_kernel(loaded->ir), {16, 16});
  const Camera view(CameraDesc{}, 16, 16);
  for (int row = 0; row < 16; row += 5)
    for (int column = 0; column < 16; column += 3) {
      const glm::vec3 expected = 0.5f * glm::normalize(view.ray(column + 0.5f, row + 0.5f).direction) + 0.5f;
      EXPECT_LT(glm::length(pixel(image, column, row) - expected), 1e-5f) << column << ", " << row;
    }
}

// What a scene names as its environment must be an environment graph the
// scene may read; each refusal is one line naming the file.
TEST(EnvironmentDriver, ScenesNameOnlyEnvironmentGraphsTheyMayRead) {
  testing::TempFolder folder("shadetree-environment");
  folder.write("flat.json", testing::graph_text("", R"("color": 0.5)"));
  folder.write("broken.json", "{");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"flat.json", "is a texture graph, not an environment graph"},
      {"missing.json", "missing.json"},
      {"broken.json", "broken.json"},
      {"../outside.json", "outside the graph's folder"}};
  for (const auto& [file, words] : cases) {
    const std::string graph = folder.write("ball.json", "");
    Result<LoadedGraph> loaded = compile_graph_text(
        testing::graph_text("", R"("color": 1)",
                            R"("render": {"scene": {"objects": [{"type": "sphere"}], "environment": ")" + file +
                                R"("}},)",
                            "surface"),
        graph);
    ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
    Result<std::unique_ptr<FrameRenderer>> renderer = prepare_render(*loaded->graph, {});
    ASSERT_FALSE(renderer.ok()) << file;
    const std::string text = renderer.error().to_string();
    EXPECT_NE(text.find(words), std::string::npos) << text;
    EXPECT_EQ(text.find('\n'), std::string::npos) << text;
  }
}

TEST(EnvironmentDriver, TakesNoSceneOrSurfaceOptions) {
  Result<LoadedGraph> scene = compile_graph_text(
      testing::graph_text("", R"("color": 1)", R"("render": {"scene": {"objects": [{"type": "sphere"}]}},)",
                          "environment"),
      "sky.json");
  ASSERT_FALSE(scene.ok());
  EXPECT_NE(scene.error().message.find("\"scene\" is for surface or volume graphs"), std::string::npos)
      << scene.error().message;
  Result<LoadedGraph> loaded = compile_graph_text(direction_colour, "sky.json");
  ASSERT_TRUE(loaded.ok());
  RenderRequest request;
  request.samples_per_pixel = 4;
  Result<std::unique_ptr<FrameRenderer>> renderer = prepare_render(*loaded->graph, request);
  ASSERT_FALSE(renderer.ok());
  EXPECT_EQ(renderer.error().message, "--spp is for surface graphs; this is an environment graph");
}

}  // namespace
}  // namespace shadetree

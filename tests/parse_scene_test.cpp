// Scenes in a graph's render section: what they hold, and a one-line
// error naming the file for everything malformed.
#include <gtest/gtest.h>

#include "graph/parse.h"
#include "support/graph_text.h"

namespace shadetree {
namespace {

Result<Graph> parse_with_scene(const std::string& scene, const std::string& kind = "surface") {
  return parse_graph(testing::graph_text("", R"("color": [1, 1, 1])", R"("render": {"scene": )" + scene + "},", kind),
                     "scene.json");
}

std::string error_of(const std::string& scene) {
  Result<Graph> graph = parse_with_scene(scene);
  EXPECT_FALSE(graph.ok()) << scene;
  if (graph.ok()) return {};
  const std::string text = graph.error().to_string();
  EXPECT_EQ(text.find('\n'), std::string::npos);
  EXPECT_NE(text.find("scene.json"), std::string::npos) << text;
  EXPECT_EQ(graph.error().status, ExitStatus::invalid_input);
  return text;
}

TEST(ParseScene, ReadsCameraObjectsLightsAndDefaults) {
  Result<Graph> graph = parse_with_scene(R"({
      "camera": {"position": [0, 2, 5], "target": [0, 0, 0], "fov": 30},
      "objects": [{"type": "torus", "id": 7, "minor_radius": 0.3, "transform": {"translate": [1, 0, 0], "scale": 2}},
                  {"type": "revolution", "profile": [[0.5, 0], [0.7, 1]]},
                  {"type": "mesh", "file": "meshes/knot.obj"}],
      "lights": [{"type": "point", "position": [0, 4, 0], "intensity": 2}],
      "background": 0.5, "shadows": false})");
  ASSERT_TRUE(graph.ok()) << graph.error().to_string();
  const SceneDesc& scene = *graph->render.scene;
  EXPECT_EQ(scene.camera.fov_degrees, 30.0f);
  ASSERT_EQ(scene.objects.size(), 3u);
  EXPECT_EQ(scene.objects[0].type, ObjectType::torus);
  EXPECT_EQ(scene.objects[0].id, 7);
  EXPECT_EQ(scene.objects[0].minor_radius, 0.3f);
  EXPECT_EQ(scene.objects[0].major_radius, 1.0f);
  EXPECT_EQ(scene.objects[0].transform.scale[2], 2.0f);
  EXPECT_EQ(scene.objects[1].id, 1) << "ids default to the object's index";
  EXPECT_EQ(scene.objects[1].profile.size(), 2u);
  EXPECT_EQ(scene.objects[2].mesh_file, "meshes/knot.obj");
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.lights[0].type, LightType::point);
  EXPECT_EQ(scene.lights[0].intensity, 2.0f);
  EXPECT_EQ(scene.background[1], 0.5f);
  EXPECT_FALSE(scene.shadows);
  EXPECT_EQ(scene.lighting, Lighting::lit);
}

TEST(ParseScene, WithoutLightsTheDefaultKeyAndFillLightIt) {
  Result<Graph> graph = parse_with_scene(R"({"objects": [{"type": "sphere"}]})");
  ASSERT_TRUE(graph.ok()) << graph.error().to_string();
  EXPECT_EQ(graph->render.scene->lights.size(), default_lights().size());
}

TEST(ParseScene, MalformedScenesGiveOneLineErrors) {
  EXPECT_NE(error_of(R"({"objects": [{"type": "teapot"}]})").find("unknown type \"teapot\""), std::string::npos);
  EXPECT_NE(error_of(R"({"objects": []})").find("non-empty"), std::string::npos);
  EXPECT_NE(error_of(R"({"objects": [{"type": "sphere", "radius": -1}]})").find("radius must be positive"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"objects": [{"type": "sphere", "size": 2}]})").find("unknown field \"size\""),
            std::string::npos);
  EXPECT_NE(error_of(R"({"camera": {"position": [1, 1, 1], "target": [1, 1, 1]}, "objects": [{"type": "sphere"}]})")
                .find("must differ"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"camera": {"up": [0, 0, 1]}, "objects": [{"type": "sphere"}]})").find("parallel"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"camera": {"fov": 180}, "objects": [{"type": "sphere"}]})").find("fov"), std::string::npos);
  EXPECT_NE(error_of(R"({"objects": [{"type": "sphere", "transform": {"scale": 0}}]})").find("scale"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"objects": [{"type": "revolution", "profile": [[1, 0]]}]})").find("profile"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"objects": [{"type": "revolution", "profile": [[-1, 0], [1, 1]]}]})").find("radius >= 0"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"objects": [{"type": "mesh"}]})").find("file"), std::string::npos);
  EXPECT_NE(error_of(R"({"objects": [{"type": "plane", "color": [1, 0, 0]}]})").find("\"color\" is for volume graphs, not surfaces"),
            std::string::npos)
      << "a surface graph's color output colours its objects";
  EXPECT_NE(error_of(R"({"objects": [{"type": "sphere", "radius": 1e39}]})").find("32-bit float"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"objects": [{"type": "sphere", "id": 1.5}]})").find("id must be an integer"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"objects": [{"type": "sphere"}], "lights": [{"type": "spot"}]})").find("unknown type"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"objects": [{"type": "sphere"}], "lighting": "phong"})").find("lighting"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"objects": [{"type": "sphere"}], "background": [1, 2]})").find("background"),
            std::string::npos);
}

TEST(ParseScene, TextureGraphsHaveNoScene) {
  Result<Graph> graph = parse_with_scene(R"({"objects": [{"type": "sphere"}]})", "texture");
  ASSERT_FALSE(graph.ok());
  EXPECT_NE(graph.error().message.find("not textures"), std::string::npos);
}

TEST(ParseScene, TooManyObjectsAreRefused) {
  std::string objects;
  for (std::size_t i = 0; i <= max_scene_objects; ++i) objects += std::string(i ? "," : "") + R"({"type": "plane"})";
  EXPECT_NE(error_of(R"({"objects": [)" + objects + "]}").find("more than"), std::string::npos);
}

}  // namespace
}  // namespace shadetree

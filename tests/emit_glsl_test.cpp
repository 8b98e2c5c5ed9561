// emit --glsl: every gallery graph gives GLSL that glslangValidator
// accepts as an ES 3.00 fragment shader and as a Shadertoy mainImage, or
// is refused in one line naming the node or the part of the scene; so
// does every op alone; the uniforms list the params; names a graph
// supplies are never live code.
// (tests/glsl_render_test.cpp draws the shaders and compares pixels.)
#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <sstream>

#include "render/glsl_shader.h"
#include "render/scene_glsl.h"
#include "glslgen/traced_ops.h"
#include "graph/generated_names.h"
#include "support/gallery.h"
#include "support/graph_text.h"
#include "support/hostile_graph.h"
#include "support/one_op_graph.h"
#include "support/temp_folder.h"
#include "support/test_files.h"

namespace shadetree {
namespace {

// The shell status of glslangValidator on `source` as a fragment shader.
int validate(const testing::TempFolder& folder, const std::string& name, const std::string& source) {
  const std::string file = folder.write(name + ".frag", source);
  const std::string command =
      std::string(SHADETREE_GLSLANG) + " " + file + " > " + (folder.path() / (name + ".log")).string() + " 2>&1";
  return std::system(command.c_str());
}

// What Shadertoy puts around the Image tab's code.
std::string shadertoy_page(const std::string& image_tab) {
  return "#version 300 es\nprecision highp float;\nprecision highp int;\nuniform vec3 iResolution;\n"
         "uniform float iTime;\nout vec4 color;\n" +
         image_tab + "\nvoid main() { mainImage(color, gl_FragCoord.xy); }\n";
}

// The gallery graphs a shader cannot hold, and why.
constexpr const char* data_refusal = "too many for a GLSL shader";
const std::map<std::string, std::string> refusals = {
    {"composite", data_refusal},
    {"stones_applied", data_refusal},
    {"mesh_hypertexture", data_refusal},
    {"marble_vase", "scene object #1 is a surface of revolution"},
    {"mesh_knot", "scene object #1 is a mesh"},
    {"ocean", "the scene's environment sunset_sky.json"},
};

TEST(EmitGlsl, GalleryGraphsValidateOrAreRefusedNamingTheNode) {
  testing::TempFolder folder("shadetree-emit-glsl");
  int emitted = 0;
  for (const std::string& path : testing::gallery_graphs()) {
    const std::string name = testing::gallery_graph_name(path);
    Result<LoadedGraph> loaded = testing::load_gallery_graph(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
    Result<GlslShader> shader = glsl_shader(*loaded->graph, loaded->ir, loaded->params, {name, false});
    const auto refusal = refusals.find(name);
    if (!shader) {
      ASSERT_NE(refusal, refusals.end()) << name << ": " << shader.error().to_string();
      EXPECT_NE(shader.error().message.find(refusal->second), std::string::npos) << shader.error().to_string();
      if (refusal->second == data_refusal) {
        EXPECT_FALSE(shader.error().node.empty()) << name;
      }
      EXPECT_EQ(shader.error().file, loaded->graph->file);
      EXPECT_EQ(shader.error().to_string().find('\n'), std::string::npos) << name;
      continue;
    }
    EXPECT_EQ(refusal, refusals.end()) << name << " was not refused";
    ++emitted;
    EXPECT_EQ(validate(folder, name, shader->source), 0) << name << ":\n" << shader->source.substr(0, 2000);
    EXPECT_NE(shader->source.find("void main()"), std::string::npos) << name;
    Result<GlslShader> shadertoy = glsl_shader(*loaded->graph, loaded->ir, loaded->params, {name, true});
    ASSERT_TRUE(shadertoy.ok()) << name;
    EXPECT_TRUE(shadertoy->uniforms.empty());
    EXPECT_EQ(shadertoy->source.find("uniform "), std::string::npos) << name;
    EXPECT_EQ(validate(folder, name + "_shadertoy", shadertoy_page(shadertoy->source)), 0) << name;
  }
  EXPECT_GE(emitted, 40);
}

// Every op of the library, over each type it takes, traces into GLSL that
// glslangValidator accepts: an op added to nodes/ needs nothing more.
TEST(EmitGlsl, EveryOpTracesIntoValidGlsl) {
  testing::TempFolder folder("shadetree-emit-glsl-ops");
  int shaders = 0;
  for (const OpDef& op : all_ops()) {
    if (!traced_op(op.id)) continue;  // the inputs and split, lowered to other instructions
    for (Type instance : testing::op_instances(op)) {
      const std::string name = op.name + "_" + std::string(type_name(instance));
      Result<LoadedGraph> loaded = testing::one_op_graph(op, instance);
      ASSERT_TRUE(loaded.ok()) << name << ": " << loaded.error().to_string();
      Result<GlslShader> shader = glsl_shader(*loaded->graph, loaded->ir, loaded->params, {name, false});
      ASSERT_TRUE(shader.ok()) << name << ": " << shader.error().to_string();
      EXPECT_EQ(validate(folder, name, shader->source), 0) << name << ":\n" << shader->source.substr(0, 3000);
      ++shaders;
    }
  }
  EXPECT_GT(shaders, 80);
}

TEST(EmitGlsl, UniformsAreTheParamsWithTheirTypesAndSlots) {
  Result<LoadedGraph> loaded = testing::load_gallery_graph(SHADETREE_SOURCE_DIR "/graphs/marble.json");
  ASSERT_TRUE(loaded.ok());
  Result<GlslShader> shader = glsl_shader(*loaded->graph, loaded->ir, loaded->params, {"marble", false});
  ASSERT_TRUE(shader.ok());
  ASSERT_EQ(shader->uniforms.size(), loaded->ir.params.size());
  for (std::size_t i = 0; i < shader->uniforms.size(); ++i) {
    const GlslUniform& uniform = shader->uniforms[i];
    const IrParam& param = loaded->ir.params[i];
    EXPECT_EQ(uniform.param, param.name);
    EXPECT_EQ(uniform.name, "u_" + param.name);
    EXPECT_EQ(uniform.slot, param.slot);
    EXPECT_EQ(uniform.type, param.type == Type::int_ ? "int" : "float") << param.name;
    EXPECT_NE(shader->source.find("uniform " + uniform.type + " " + uniform.name + ";"), std::string::npos);
  }
}

TEST(EmitGlsl, RefusesDataTooLargeNamingTheNode) {
  Result<LoadedGraph> loaded = testing::large_image_graph();
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  Result<GlslShader> shader = glsl_shader(*loaded->graph, loaded->ir, loaded->params, {"big", false});
  ASSERT_FALSE(shader.ok());
  EXPECT_EQ(shader.error().node, "photo");
  EXPECT_EQ(shader.error().file, "big.json");
}

TEST(EmitGlsl, HostileNamesAreNeverLiveCode) {
  testing::TempFolder folder("shadetree-emit-glsl-hostile");
  Result<LoadedGraph> loaded =
      compile_graph_text(testing::hostile_graph(), testing::hostile_file_name, {}, {}, {});
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  for (const std::string& name : testing::hostile_names()) {
    Result<GlslShader> shader = glsl_shader(*loaded->graph, loaded->ir, loaded->params, {name, false});
    ASSERT_TRUE(shader.ok()) << shader.error().to_string();
    std::istringstream lines(shader->source);
    int number = 0;
    for (std::string line; std::getline(lines, line);) {
      ++number;
      for (char c : line) ASSERT_TRUE(c >= 0x20 && c < 0x7f) << "line " << number << ": " << line;
      ASSERT_TRUE(line.empty() || line.back() != '\\') << "line " << number << ": " << line;
      for (const char* live : {"#error", "static_assert(", "#include <no_such"})
        if (line.find(live) != std::string::npos) {
          EXPECT_LT(line.find("//"), line.find(live)) << "line " << number << " is not a comment: " << line;
        }
    }
    EXPECT_EQ(validate(folder, "hostile", shader->source), 0) << quoted_text(name);
  }
}

}  // namespace
}  // namespace shadetree

namespace shadetree {
namespace {

// A surface graph of one colour on `objects`, as its scene's text.
std::string surface_on(const std::string& objects) {
  return R"({"format": "shadetree-graph", "version": 1, "kind": "surface",
             "nodes": [{"id": "red", "op": "vec3", "in": {"x": 1, "y": 0, "z": 0}}],
             "outputs": {"color": "red"}, "render": {"scene": {"objects": [)" +
         objects + "]}}}";
}

// What a shader's scene cannot hold is refused in one line naming the
// object: too many objects to test per ray, a transform whose inverse is
// not finite in single precision (a shader's constants must be).
TEST(EmitGlsl, ScenesAShaderCannotHoldAreRefusedNamingTheObject) {
  std::string many;
  for (std::size_t i = 0; i <= max_glsl_objects; ++i)
    many += std::string(i > 0 ? ", " : "") + R"({"type": "sphere", "transform": {"translate": [)" +
            std::to_string(i) + ", 0, 0]}}";
  const std::pair<std::string, std::string> scenes[] = {
      {many, "65 objects, more than a GLSL shader tests per ray (at most 64)"},
      {R"({"type": "plane"}, {"type": "sphere", "transform": {"scale": 1e-11, "translate": [1e30, 0, 0]}})",
       "scene object #2's transform has no finite inverse"},
  };
  for (const auto& [objects, reason] : scenes) {
    Result<LoadedGraph> loaded = compile_graph_text(surface_on(objects), "scene.json");
    ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
    Result<GlslShader> shader = glsl_shader(*loaded->graph, loaded->ir, loaded->params, {"scene", false});
    ASSERT_FALSE(shader.ok()) << reason;
    EXPECT_NE(shader.error().message.find(reason), std::string::npos) << shader.error().to_string();
    EXPECT_EQ(shader.error().file, "scene.json");
  }
}

}  // namespace
}  // namespace shadetree

// emit --glsl's fragment shaders drawn by a real WebGL 2 (headless
// Chromium, SwiftShader where there is no GPU, through the editor's
// GlslCanvas: editor/tests/render_glsl.mjs) against the interpreter's
// render of the same graph (volumes with `--shadows exact`, the GLSL
// marcher's): every graph of the gallery that can be emitted and a graph
// of hostile names, at 64x64, with the mean and largest difference
// printed per graph. SwiftShader computes in IEEE single precision and does not fuse
// multiplies and adds, so the texture shaders agree with the interpreter to
// the bit or within an ulp or so (a GPU's own rounding moves further:
// docs/glsl.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "render/glsl_shader.h"
#include "interp/interpreter.h"
#include "render/graph_kinds.h"
#include "support/gallery.h"
#include "support/hostile_graph.h"
#include "support/temp_folder.h"

namespace shadetree {
namespace {

constexpr int size = 64;

// What a graph's pixels may differ by. A texture's shader places its
// pixels with the driver's own arithmetic, so only an ulp or so. An
// environment's turns each pixel into a direction with GLSL's sin and cos
// where the driver calls the C library's: the directions differ in their
// last bits, which moves the value of a pixel on an edge (a noise cell, a
// cloud's border) by up to a quarter, and the mean little.
struct Tolerance {
  double largest, mean;
};
Tolerance tolerance(const ShadeIR& ir) {
  switch (ir.kind) {
    case GraphKind::texture: return {1e-4, 1e-6};
    case GraphKind::environment: return {0.25, 1e-3};
    default: break;
  }
  // A refracting volume bends its rays about the density's gradient: a
  // gradient that differs in its last bits sends a ray at an edge of the
  // glass through another path, to another square of the floor.
  for (const IrOutput& output : ir.outputs)
    if (output.id == OutputId::ior) return {0.5, 1e-3};
  // A volume's march and a surface's ray cast call GLSL's pow, exp,
  // normalize and trigonometry where the drivers call the C library's,
  // and a sphere's quadratic is solved in float where the driver uses
  // double: the differences stay near single precision's, summed over
  // a ray's segments.
  return {5e-4, 1e-5};
}

struct Compared {
  std::string graph;
  Image reference;
  std::string raw;  // the GPU's pixels
  Tolerance tolerance;
  GraphKind kind;
};

TEST(GlslRender, GalleryGraphsDrawnByWebGlAgreeWithTheInterpreter) {
  testing::TempFolder folder("shadetree-glsl-render");
  nlohmann::json jobs = nlohmann::json::array();
  std::vector<Compared> compared;
  // The gallery's texture graphs, and one whose many params differ (a
  // uniform mixed up with another changes its pixels) under hostile names.
  std::vector<std::pair<std::string, Result<LoadedGraph>>> graphs;
  for (GraphKind kind : {GraphKind::texture, GraphKind::environment, GraphKind::volume, GraphKind::surface})
    for (const std::string& path : testing::gallery_graphs(kind))
      graphs.emplace_back(testing::gallery_graph_name(path), testing::load_gallery_graph(path));
  graphs.emplace_back("hostile", compile_graph_text(testing::hostile_graph(), testing::hostile_file_name, {}, {}, {}));
  for (auto& [name, loaded] : graphs) {
    ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
    Result<GlslShader> shader = glsl_shader(*loaded->graph, loaded->ir, loaded->params, {name, false});
    if (!shader) {  // refused in one line (tests/emit_glsl_test.cpp says why each is)
      std::printf("%-20s refused: %s\n", name.c_str(), shader.error().message.c_str());
      continue;
    }
    RenderRequest request;
    request.size = {size, size};
    // The GLSL marcher's shadows are exact ones (render/glsl_drivers.h).
    if (loaded->graph->kind == GraphKind::volume) request.shadows = ShadowMode::exact;
    Result<std::unique_ptr<FrameRenderer>> renderer = prepare_render(*loaded->graph, request);
    ASSERT_TRUE(renderer.ok()) << renderer.error().to_string();
    const std::unique_ptr<Kernel> interpreted = make_interpreted_kernel(loaded->ir);
    const float frame = loaded->graph->render.frame;
    Result<Image> reference = (*renderer)->render(*interpreted, loaded->params, frame, {}, nullptr);
    ASSERT_TRUE(reference.ok()) << reference.error().to_string();
    nlohmann::json uniforms = nlohmann::json::array();
    for (const GlslUniform& uniform : shader->uniforms)
      uniforms.push_back({{"name", uniform.name},
                          {"type", uniform.type},
                          {"values", std::vector<float>(loaded->params.begin() + uniform.slot,
                                                        loaded->params.begin() + uniform.slot + uniform.components)}});
    const std::string raw = (folder.path() / (name + ".raw")).string();
    jobs.push_back({{"shader", folder.write(name + ".frag", shader->source)},
                    {"width", size},
                    {"height", size},
                    {"frame", frame},
                    {"uniforms", uniforms},
                    {"output", raw}});
    // A picture of one colour would agree with anything of that colour.
    const auto [darkest, brightest] = std::minmax_element(reference->pixels.begin(), reference->pixels.end());
    EXPECT_GT(*brightest - *darkest, 0.1f) << name << " renders a picture of one colour";
    compared.push_back({name, std::move(*reference), raw, tolerance(loaded->ir), loaded->graph->kind});
  }
  std::map<GraphKind, int> drawn;
  for (const Compared& graph : compared) ++drawn[graph.kind];
  EXPECT_GE(drawn[GraphKind::texture], 8);
  EXPECT_GE(drawn[GraphKind::volume], 6);
  EXPECT_GE(drawn[GraphKind::surface], 3);
  const std::string jobs_file = folder.write("jobs.json", jobs.dump());
  const std::string command = std::string(SHADETREE_NODE) + " " + SHADETREE_SOURCE_DIR +
                              "/editor/tests/render_glsl.mjs " + jobs_file + " > " +
                              (folder.path() / "log.txt").string() + " 2>&1";
  const int status = std::system(command.c_str());
  std::ifstream log(folder.path() / "log.txt");
  const std::string log_text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  ASSERT_EQ(status, 0) << log_text;

  for (const Compared& graph : compared) {
    std::ifstream raw(graph.raw, std::ios::binary);
    std::vector<float> gpu(static_cast<std::size_t>(size) * size * 4);
    raw.read(reinterpret_cast<char*>(gpu.data()), static_cast<std::streamsize>(gpu.size() * sizeof(float)));
    ASSERT_TRUE(raw) << graph.graph << ": " << log_text;
    const int channels = graph.reference.channels;
    double sum = 0.0, largest = 0.0;
    long identical = 0;
    for (int pixel = 0; pixel < size * size; ++pixel)
      for (int c = 0; c < channels; ++c) {
        const float cpu = graph.reference.pixels[static_cast<std::size_t>(pixel * channels + c)];
        const float gpu_value = gpu[static_cast<std::size_t>(pixel * 4 + c)];
        const double difference = std::fabs(static_cast<double>(cpu) - gpu_value);
        sum += difference;
        largest = std::max(largest, std::isnan(difference) ? INFINITY : difference);
        identical += cpu == gpu_value;
      }
    const double mean = sum / (size * size * channels);
    std::printf("%-20s mean %.3g, largest %.3g, %.1f%% of values identical\n", graph.graph.c_str(), mean, largest,
                100.0 * identical / (size * size * channels));
    EXPECT_LE(largest, graph.tolerance.largest) << graph.graph;
    EXPECT_LE(mean, graph.tolerance.mean) << graph.graph;
  }
}

}  // namespace
}  // namespace shadetree

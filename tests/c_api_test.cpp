// The C API: loading, errors as statuses with one-line messages, params,
// kernel runs over planes (against the interpreter through the pipeline),
// texture renders and image writes.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <vector>

#include "api/shadetree.h"
#include "interp/interpreter.h"
#include "pipeline/compile_graph.h"
#include "io/graph_files.h"
#include "io/image_output.h"
#include "render/graph_kinds.h"

namespace shadetree {
namespace {

const std::string marble = SHADETREE_SOURCE_DIR "/graphs/marble.json";

struct GraphHandle {
  shadetree_graph* graph = nullptr;
  ~GraphHandle() { shadetree_free(graph); }
};

bool one_line(const char* message) { return std::string(message).find('\n') == std::string::npos; }

TEST(CApi, LoadFailuresAreStatusesWithOneLineMessages) {
  GraphHandle handle;
  EXPECT_EQ(shadetree_load("/no/such/graph.json", SHADETREE_JIT, &handle.graph), SHADETREE_INVALID_INPUT);
  EXPECT_EQ(handle.graph, nullptr);
  EXPECT_NE(std::string(shadetree_last_error()).find("/no/such/graph.json"), std::string::npos);
  EXPECT_EQ(shadetree_load_text("{\"format\": ", "broken.json", SHADETREE_JIT, &handle.graph), SHADETREE_INVALID_INPUT);
  EXPECT_NE(std::string(shadetree_last_error()).find("broken.json"), std::string::npos);
  EXPECT_TRUE(one_line(shadetree_last_error()));
  EXPECT_EQ(shadetree_load(nullptr, SHADETREE_JIT, &handle.graph), SHADETREE_INVALID_INPUT);
  EXPECT_EQ(shadetree_load(marble.c_str(), 7, &handle.graph), SHADETREE_INVALID_INPUT);
  ASSERT_EQ(shadetree_load(marble.c_str(), SHADETREE_JIT, &handle.graph), SHADETREE_OK) << shadetree_last_error();
  EXPECT_STREQ(shadetree_last_error(), "");
  EXPECT_STREQ(shadetree_kind(handle.graph), "texture");
}

TEST(CApi, ParamsAreCheckedAgainstTheirTypeAndRange) {
  GraphHandle handle;
  ASSERT_EQ(shadetree_load(marble.c_str(), SHADETREE_INTERPRETER, &handle.graph), SHADETREE_OK);
  EXPECT_EQ(shadetree_set_param(handle.graph, "scale", "9"), SHADETREE_OK) << shadetree_last_error();
  EXPECT_EQ(shadetree_set_param(handle.graph, "scale", "-5"), SHADETREE_INVALID_INPUT);
  EXPECT_NE(std::string(shadetree_last_error()).find("scale"), std::string::npos);
  EXPECT_EQ(shadetree_set_param(handle.graph, "scael", "9"), SHADETREE_INVALID_INPUT);
  EXPECT_NE(std::string(shadetree_last_error()).find("unknown param"), std::string::npos);
  EXPECT_EQ(shadetree_set_param(handle.graph, "octaves", "2.5"), SHADETREE_INVALID_INPUT);
  EXPECT_EQ(shadetree_set_param(handle.graph, nullptr, "1"), SHADETREE_INVALID_INPUT);
}

// shadetree_run with scale=9 computes what the pipeline's interpreter
// computes with --set scale=9, for both backends.
TEST(CApi, RunsTheKernelOverPlanes) {
  const std::size_t count = 21;
  std::vector<std::vector<float>> inputs(static_cast<std::size_t>(shadetree_input_plane_count()));
  std::vector<const float*> input_pointers(inputs.size(), nullptr);
  for (int c = 0; c < 3; ++c) {
    const int plane = shadetree_input_plane("P", c);
    ASSERT_GE(plane, 0);
    for (std::size_t i = 0; i < count; ++i) inputs[plane].push_back(0.13f * static_cast<float>(i) - 0.4f * c);
    input_pointers[plane] = inputs[plane].data();
  }
  const int width = shadetree_input_plane("filter_width", 0);
  inputs[width].assign(count, 0.002f);
  input_pointers[width] = inputs[width].data();
  EXPECT_EQ(shadetree_input_plane("P", 3), -1);
  EXPECT_EQ(shadetree_input_plane("time", 0), -1) << "uniform globals have no plane";
  EXPECT_EQ(shadetree_input_plane("Q", 0), -1);

  Result<LoadedGraph> loaded = load_and_compile(marble, {"scale=9"});
  ASSERT_TRUE(loaded.ok());
  auto reference = make_interpreted_kernel(loaded->ir);
  SampleInputs planes;
  for (std::size_t i = 0; i < inputs.size(); ++i) planes.planes[i] = input_pointers[i];
  std::vector<std::vector<float>> expected(3, std::vector<float>(count));
  std::vector<float*> expected_pointers(9, nullptr);  // a plane for each of the contract's
  for (int c = 0; c < 3; ++c) expected_pointers[static_cast<std::size_t>(c)] = expected[static_cast<std::size_t>(c)].data();
  reference->bind(loaded->params.data(), {})->run(planes, expected_pointers.data(), count);

  for (shadetree_backend backend : {SHADETREE_JIT, SHADETREE_INTERPRETER}) {
    GraphHandle handle;
    ASSERT_EQ(shadetree_load(marble.c_str(), backend, &handle.graph), SHADETREE_OK);
    ASSERT_EQ(shadetree_set_param(handle.graph, "scale", "9"), SHADETREE_OK);
    ASSERT_EQ(shadetree_output_plane_count(handle.graph), 9);  // color, alpha, height, normal, roughness
    EXPECT_EQ(shadetree_output_plane(handle.graph, "alpha", 0), 3);
    EXPECT_EQ(shadetree_output_plane(handle.graph, "density", 0), -1) << "not a texture output";
    std::vector<std::vector<float>> outputs(3, std::vector<float>(count, -1.0f));
    std::vector<float*> output_pointers(9, nullptr);
    for (int c = 0; c < 3; ++c) output_pointers[shadetree_output_plane(handle.graph, "color", c)] = outputs[c].data();
    ASSERT_EQ(shadetree_run(handle.graph, 0.0f, input_pointers.data(), output_pointers.data(), count), SHADETREE_OK)
        << shadetree_last_error();
    EXPECT_EQ(outputs, expected) << "backend " << backend;
    // A plane the graph reads, missing.
    std::vector<const float*> missing = input_pointers;
    missing[shadetree_input_plane("P", 1)] = nullptr;
    EXPECT_EQ(shadetree_run(handle.graph, 0.0f, missing.data(), output_pointers.data(), count), SHADETREE_INVALID_INPUT);
    EXPECT_NE(std::string(shadetree_last_error()).find("NULL"), std::string::npos);
  }
}

// shadetree_bound encloses what shadetree_run computes over a box, the
// same to the bit on both backends, and finds the noisy sphere's density 0
// over a box beyond its bumps.
TEST(CApi, BoundsEncloseWhatTheKernelComputesOverABox) {
  const std::string sphere = SHADETREE_SOURCE_DIR "/graphs/noisy_sphere.json";
  const int inputs = shadetree_input_plane_count();
  std::vector<float> lo(static_cast<std::size_t>(inputs), 0.0f), hi(static_cast<std::size_t>(inputs), 0.0f);
  const float box_lo[3] = {0.85f, -0.05f, -0.05f}, box_hi[3] = {1.05f, 0.1f, 0.1f};
  for (int c = 0; c < 3; ++c) {
    lo[static_cast<std::size_t>(shadetree_input_plane("P", c))] = box_lo[c];
    hi[static_cast<std::size_t>(shadetree_input_plane("P", c))] = box_hi[c];
  }
  const std::size_t width = static_cast<std::size_t>(shadetree_input_plane("filter_width", 0));
  lo[width] = hi[width] = 0.01f;
  std::vector<float> bounds[2][2];  // per backend: lo, hi
  const shadetree_backend backends[2] = {SHADETREE_JIT, SHADETREE_INTERPRETER};
  for (int b = 0; b < 2; ++b) {
    GraphHandle handle;
    ASSERT_EQ(shadetree_load(sphere.c_str(), backends[b], &handle.graph), SHADETREE_OK) << shadetree_last_error();
    const int outputs = shadetree_output_plane_count(handle.graph);
    bounds[b][0].assign(static_cast<std::size_t>(outputs), -7.0f);
    bounds[b][1].assign(static_cast<std::size_t>(outputs), 7.0f);
    ASSERT_EQ(shadetree_bound(handle.graph, 0.0f, lo.data(), hi.data(), bounds[b][0].data(), bounds[b][1].data()),
              SHADETREE_OK)
        << shadetree_last_error();
    // Samples of the box, corners first, through the kernel.
    constexpr std::size_t count = 64;
    std::vector<std::vector<float>> planes(static_cast<std::size_t>(inputs), std::vector<float>(count, 0.0f));
    std::vector<const float*> input_pointers;
    for (int plane = 0; plane < inputs; ++plane)
      for (std::size_t i = 0; i < count; ++i) {
        const float t = i < 8 ? static_cast<float>((i >> (plane % 3)) & 1) : static_cast<float>((i * 37 + plane * 11) % 64) / 63.0f;
        planes[static_cast<std::size_t>(plane)][i] = lo[static_cast<std::size_t>(plane)] +
                                                      t * (hi[static_cast<std::size_t>(plane)] - lo[static_cast<std::size_t>(plane)]);
      }
    for (auto& plane : planes) input_pointers.push_back(plane.data());
    std::vector<std::vector<float>> results(static_cast<std::size_t>(outputs), std::vector<float>(count));
    std::vector<float*> output_pointers;
    for (auto& plane : results) output_pointers.push_back(plane.data());
    ASSERT_EQ(shadetree_run(handle.graph, 0.0f, input_pointers.data(), output_pointers.data(), count), SHADETREE_OK);
    const std::size_t density = static_cast<std::size_t>(shadetree_output_plane(handle.graph, "density", 0));
    for (std::size_t i = 0; i < count; ++i) {
      EXPECT_GE(results[density][i], bounds[b][0][density]) << "sample " << i;
      EXPECT_LE(results[density][i], bounds[b][1][density]) << "sample " << i;
    }
    EXPECT_LT(bounds[b][0][density], bounds[b][1][density]) << "the box holds the sphere's surface";
    // Beyond the bumps the density is 0 everywhere.
    std::vector<float> far_lo = lo, far_hi = hi, out_lo(static_cast<std::size_t>(outputs)), out_hi(out_lo.size());
    for (int c = 0; c < 3; ++c) {
      far_lo[static_cast<std::size_t>(shadetree_input_plane("P", c))] = 1.3f;
      far_hi[static_cast<std::size_t>(shadetree_input_plane("P", c))] = 1.4f;
    }
    ASSERT_EQ(shadetree_bound(handle.graph, 0.0f, far_lo.data(), far_hi.data(), out_lo.data(), out_hi.data()), SHADETREE_OK);
    EXPECT_LE(out_hi[density], 0.0f);
    // Boxes that are none.
    std::vector<float> inverted = hi;
    inverted[static_cast<std::size_t>(shadetree_input_plane("P", 1))] = -1.0f;
    EXPECT_EQ(shadetree_bound(handle.graph, 0.0f, lo.data(), inverted.data(), out_lo.data(), out_hi.data()),
              SHADETREE_INVALID_INPUT);
    EXPECT_NE(std::string(shadetree_last_error()).find("lo > hi"), std::string::npos);
    std::vector<float> nan = lo;
    nan[0] = std::nanf("");
    EXPECT_EQ(shadetree_bound(handle.graph, 0.0f, nan.data(), hi.data(), out_lo.data(), out_hi.data()),
              SHADETREE_INVALID_INPUT);
    EXPECT_EQ(shadetree_bound(handle.graph, 0.0f, nullptr, hi.data(), out_lo.data(), out_hi.data()),
              SHADETREE_INVALID_INPUT);
  }
  EXPECT_EQ(bounds[0][0], bounds[1][0]);
  EXPECT_EQ(bounds[0][1], bounds[1][1]);
}

TEST(CApi, RendersTexturesAndWritesImages) {
  GraphHandle handle;
  ASSERT_EQ(shadetree_load(marble.c_str(), SHADETREE_JIT, &handle.graph), SHADETREE_OK);
  std::vector<float> rgba(4 * 16 * 8, -1.0f);
  ASSERT_EQ(shadetree_render_texture(handle.graph, 16, 8, 0.0f, rgba.data()), SHADETREE_OK) << shadetree_last_error();
  for (std::size_t i = 3; i < rgba.size(); i += 4) EXPECT_EQ(rgba[i], 1.0f) << "alpha 1 where the graph has none";
  EXPECT_GT(rgba[0], 0.0f);
  EXPECT_EQ(shadetree_render_texture(handle.graph, 0, 8, 0.0f, rgba.data()), SHADETREE_INVALID_INPUT);
  EXPECT_EQ(shadetree_render_texture(handle.graph, 1 << 20, 8, 0.0f, rgba.data()), SHADETREE_INVALID_INPUT);

  const std::filesystem::path png = std::filesystem::temp_directory_path() / "shadetree-c-api-test.png";
  ASSERT_EQ(shadetree_write_image(png.c_str(), rgba.data(), 16, 8, 4), SHADETREE_OK) << shadetree_last_error();
  Result<Image> image = read_image(png.string());
  ASSERT_TRUE(image.ok());
  EXPECT_EQ(image->width, 16);
  std::filesystem::remove(png);
  EXPECT_EQ(shadetree_write_image("/no/such/folder/out.png", rgba.data(), 16, 8, 4), SHADETREE_FAILURE);
  EXPECT_EQ(shadetree_write_image("out.tiff", rgba.data(), 16, 8, 4), SHADETREE_INVALID_INPUT);
  EXPECT_EQ(shadetree_write_image(png.c_str(), rgba.data(), 16, 8, 5), SHADETREE_INVALID_INPUT);

  GraphHandle surface;
  ASSERT_EQ(shadetree_load(SHADETREE_SOURCE_DIR "/graphs/marble_vase.json", SHADETREE_JIT, &surface.graph), SHADETREE_OK)
      << shadetree_last_error();
  EXPECT_EQ(shadetree_render_texture(surface.graph, 16, 8, 0.0f, rgba.data()), SHADETREE_INVALID_INPUT);
  EXPECT_NE(std::string(shadetree_last_error()).find("surface graph"), std::string::npos);
}

// Every kind renders through its driver, as the command line renders it:
// the vase on its scene, the sphere through the ray marcher.
TEST(CApi, RendersEveryKindAsTheCommandLineDoes) {
  for (const char* name : {"marble_vase", "noisy_sphere"}) {
    const std::string file = std::string(SHADETREE_SOURCE_DIR "/graphs/") + name + ".json";
    GraphHandle handle;
    ASSERT_EQ(shadetree_load(file.c_str(), SHADETREE_INTERPRETER, &handle.graph), SHADETREE_OK)
        << shadetree_last_error();
    std::vector<float> rgba(4 * 12 * 12, -1.0f);
    ASSERT_EQ(shadetree_render(handle.graph, 12, 12, 0.0f, rgba.data()), SHADETREE_OK) << shadetree_last_error();
    Result<LoadedGraph> loaded = load_and_compile(file, {}, {}, graph_files());
    ASSERT_TRUE(loaded.ok());
    RenderRequest request;
    request.size = {12, 12};
    Result<std::unique_ptr<FrameRenderer>> renderer = prepare_render(*loaded->graph, request);
    ASSERT_TRUE(renderer.ok()) << renderer.error().to_string();
    Result<Image> image = (*renderer)->render(*make_interpreted_kernel(loaded->ir), loaded->params, 0.0f, {}, nullptr);
    ASSERT_TRUE(image.ok());
    for (std::size_t i = 0; i < 12 * 12; ++i) {
      for (int c = 0; c < 3; ++c) EXPECT_EQ(rgba[4 * i + c], image->pixels[3 * i + c]) << name << " pixel " << i;
      EXPECT_EQ(rgba[4 * i + 3], 1.0f);
    }
  }
}

}  // namespace
}  // namespace shadetree

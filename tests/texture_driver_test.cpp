// The texture driver over the gallery: every graph checks and renders a
// non-constant image, renders are bit-identical across runs and thread
// counts, and a pixel equals the graph evaluated at that pixel's sample.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "pipeline/compile_graph.h"
#include "support/gallery.h"
#include "interp/interpreter.h"
#include "render/texture_driver.h"

namespace shadetree {
namespace {


Image render(const LoadedGraph& loaded, int size, int threads, float frame = 0.0f) {
  TextureView view = TextureView::from_settings(loaded.graph->render);
  view.width = view.height = size;
  view.frame = frame;
  TextureRenderOptions options;
  options.threads = threads;
  auto kernel = make_interpreted_kernel(loaded.ir);
  return *render_texture(*kernel, loaded.params, view, options);
}

class GalleryGraph : public ::testing::TestWithParam<std::string> {};

TEST_P(GalleryGraph, ChecksAndRendersANonConstantImage) {
  Result<LoadedGraph> loaded = testing::load_gallery_graph(GetParam());
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  const Image image = render(*loaded, 96, 0);
  const auto [low, high] = std::minmax_element(image.pixels.begin(), image.pixels.end());
  EXPECT_GT(*high - *low, 0.1f) << "the image is (nearly) constant";
  for (float value : image.pixels) ASSERT_TRUE(std::isfinite(value));
}

TEST_P(GalleryGraph, IsBitIdenticalAcrossRunsAndThreadCounts) {
  Result<LoadedGraph> loaded = testing::load_gallery_graph(GetParam());
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  const Image single = render(*loaded, 80, 1);
  const Image many = render(*loaded, 80, 4);
  const Image again = render(*loaded, 80, 4);
  EXPECT_EQ(single.pixels, many.pixels);
  EXPECT_EQ(many.pixels, again.pixels);
}

INSTANTIATE_TEST_SUITE_P(Gallery, GalleryGraph, ::testing::ValuesIn(testing::gallery_graphs(GraphKind::texture)),
                         [](const auto& info) { return testing::gallery_graph_name(info.param); });

TEST(TextureDriver, MapsPixelCentresThroughTheDomain) {
  TextureView view;
  view.width = 4;
  view.height = 2;
  view.domain_min[0] = -1.0f;
  view.domain_max[0] = 1.0f;
  view.domain_min[1] = 0.0f;
  view.domain_max[1] = 2.0f;
  view.z = 3.0f;
  const TextureSample top_left = texture_sample_at_pixel(view, 0, 0);
  EXPECT_FLOAT_EQ(top_left.P[0], -0.75f);
  EXPECT_FLOAT_EQ(top_left.P[1], 1.5f);
  EXPECT_FLOAT_EQ(top_left.P[2], 3.0f);
  EXPECT_FLOAT_EQ(top_left.uv[0], 0.125f);
  EXPECT_FLOAT_EQ(top_left.uv[1], 0.75f);
  EXPECT_FLOAT_EQ(top_left.filter_width, 1.0f);  // max(2 / 4, 2 / 2)
  const TextureSample same = texture_sample_at_point(view, top_left.P);
  EXPECT_FLOAT_EQ(same.uv[0], top_left.uv[0]);
  EXPECT_FLOAT_EQ(same.uv[1], top_left.uv[1]);
}

TEST(TextureDriver, AnimatedGraphsChangeWithTheFrame) {
  Result<LoadedGraph> loaded = load_and_compile(SHADETREE_SOURCE_DIR "/graphs/corona.json", {});
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  EXPECT_NE(render(*loaded, 48, 0, 0.0f).pixels, render(*loaded, 48, 0, 12.0f).pixels);
}

}  // namespace
}  // namespace shadetree

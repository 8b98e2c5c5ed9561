// Baked texture sets (render/texture_bake.h): a set of a periodic graph
// over one period tiles exactly on both backends (and one of plain noise
// does not); the normal map derived from a height is the height map's own
// slope; the encodings of the two normal-map conventions.
#include <gtest/gtest.h>

#include <cmath>

#include "graph/parse.h"
#include "interp/interpreter.h"
#include "jit/jit_kernel.h"
#include "pipeline/compile_graph.h"
#include "graph/derived_normals.h"
#include "render/texture_bake.h"
#include "support/graph_text.h"

namespace shadetree {
namespace {

// A texture graph of `nodes` with `outputs`, its normal derived from its
// height where it gives no normal, compiled.
LoadedGraph compile_set(const std::string& nodes, const std::string& outputs) {
  Result<Graph> parsed = parse_graph(testing::graph_text(nodes, outputs), "set.json");
  EXPECT_TRUE(parsed.ok()) << parsed.error().to_string();
  Result<LoadedGraph> loaded = compile_graph(with_normal_from_height(std::move(*parsed), 1.0f), {});
  EXPECT_TRUE(loaded.ok()) << loaded.error().to_string();
  return std::move(*loaded);
}

std::vector<std::unique_ptr<Kernel>> both_backends(const LoadedGraph& graph) {
  std::vector<std::unique_ptr<Kernel>> kernels;
  kernels.push_back(make_interpreted_kernel(graph.ir));
  Result<std::unique_ptr<Kernel>> jit = make_jit_kernel(graph.ir);
  EXPECT_TRUE(jit.ok()) << jit.error().to_string();
  kernels.push_back(std::move(*jit));
  return kernels;
}

TextureView square_view(int pixels, float side) {
  TextureView view;
  view.width = view.height = pixels;
  view.domain_max[0] = view.domain_max[1] = side;
  view.z = 0.375f;
  return view;
}

BakedSet bake(const Kernel& kernel, const LoadedGraph& graph, const TextureView& view,
              const std::vector<OutputId>& outputs) {
  Result<BakedSet> set = bake_texture_set(kernel, graph.params, view, outputs, {});
  EXPECT_TRUE(set.ok()) << set.error().to_string();
  return std::move(*set);
}

// Every periodic lattice op, and turbulence and fbm over them, as the
// height and colour of a set over one period (4 cells): the column past
// the right edge and the row past the bottom are the first column and the
// top row, bit for bit, and a set two periods wide is the same tile twice.
TEST(TextureBake, SetsOfPeriodicGraphsOverOnePeriodTileExactlyOnBothBackends) {
  const char* ops[] = {R"("op": "pnoise", "in": {"p": "p"})", R"("op": "pnoise_improved", "in": {"p": "p"})",
                       R"("op": "pturbulence", "in": {"p": "p", "octaves": 4})",
                       R"("op": "pfbm", "in": {"p": "p", "octaves": 4})",
                       R"("op": "pnoise4", "in": {"p": "p", "w": 0.3})"};
  for (const char* op : ops) {
    SCOPED_TRACE(op);
    const LoadedGraph graph = compile_set(std::string(R"({"id": "p", "op": "P"}, {"id": "h", )") + op + "}",
                                          R"("color": "h", "height": "h")");
    for (const auto& kernel : both_backends(graph)) {
      const BakedSet one = bake(*kernel, graph, square_view(64, 4.0f), {OutputId::color, OutputId::height, OutputId::normal});
      EXPECT_TRUE(one.tileable);
      TextureView wide = square_view(64, 8.0f);
      wide.width = 128;
      wide.domain_max[1] = 4.0f;
      const BakedSet two = bake(*kernel, graph, wide, {OutputId::height});
      EXPECT_TRUE(two.tileable);
      const Image& tile = one.maps[1].image;
      for (int row = 0; row < 64; ++row)
        for (int column = 0; column < 64; ++column) {
          const float left = two.maps[0].image.pixels[static_cast<std::size_t>(row * 128 + column)];
          ASSERT_EQ(left, two.maps[0].image.pixels[static_cast<std::size_t>(row * 128 + column + 64)]);
          ASSERT_EQ(left, tile.pixels[static_cast<std::size_t>(row * 64 + column)]);
        }
    }
  }
  // pcellular's two distances, as the colour.
  const LoadedGraph cells = compile_set(R"({"id": "p", "op": "P"}, {"id": "c", "op": "pcellular", "in": {"p": "p"}},
    {"id": "s", "op": "split", "in": {"v": "c"}}, {"id": "out", "op": "color", "in": {"r": "s.x", "g": "s.y"}})",
                                        R"("color": "out")");
  for (const auto& kernel : both_backends(cells)) EXPECT_TRUE(bake(*kernel, cells, square_view(64, 4.0f), {OutputId::color}).tileable);
}

TEST(TextureBake, APlainNoiseSetDoesNotTile) {
  const LoadedGraph graph = compile_set(R"({"id": "p", "op": "P"}, {"id": "h", "op": "noise", "in": {"p": "p"}})",
                                        R"("color": "h")");
  for (const auto& kernel : both_backends(graph))
    EXPECT_FALSE(bake(*kernel, graph, square_view(64, 4.0f), {OutputId::color}).tileable);
}

// The derived normal is normalize(-dh/dx, -dh/dy, 1) from the exact
// gradient; read against central differences of the baked height map
// itself (a smooth height, so that pixels resolve it), it agrees to what
// differences over a pixel can tell.
TEST(TextureBake, TheNormalMapIsTheSlopeOfTheHeightMap) {
  const LoadedGraph graph = compile_set(R"({"id": "p", "op": "P"}, {"id": "n", "op": "pnoise", "in": {"p": "p"}},
    {"id": "h", "op": "mul", "in": {"a": "n", "b": 0.2}})",
                                        R"("color": "h", "height": "h")");
  constexpr int size = 256;
  const TextureView view = square_view(size, 4.0f);
  const BakedSet set = bake(*both_backends(graph)[1], graph, view, {OutputId::height, OutputId::normal});
  const Image& height = set.maps[0].image;
  const Image& normal = set.maps[1].image;
  const double pixel = 4.0 / size;
  auto h = [&](int row, int column) {
    return double(height.pixels[static_cast<std::size_t>(((row + size) % size) * size + (column + size) % size)]);
  };
  double worst = 0;
  for (int row = 0; row < size; ++row)
    for (int column = 0; column < size; ++column) {
      // Columns run along +x; rows down the image, so along -y.
      const double dx = (h(row, column + 1) - h(row, column - 1)) / (2 * pixel);
      const double dy = -(h(row + 1, column) - h(row - 1, column)) / (2 * pixel);
      const double length = std::sqrt(dx * dx + dy * dy + 1);
      const float* n = &normal.pixels[static_cast<std::size_t>(row * size + column) * 3];
      worst = std::max({worst, std::fabs(n[0] + dx / length), std::fabs(n[1] + dy / length),
                        std::fabs(n[2] - 1 / length)});
    }
  EXPECT_LT(worst, 2e-3);
}

// A graph's own normal is baked as given; without a height there is none.
TEST(TextureBake, OnlyAHeightWithoutANormalGetsADerivedNormal) {
  Result<Graph> own = parse_graph(testing::graph_text(R"({"id": "p", "op": "P"})",
                                                      R"("color": "p", "height": 0.5, "normal": [0, 0, 1])"),
                                  "own.json");
  ASSERT_TRUE(own.ok());
  EXPECT_EQ(with_normal_from_height(*own, 1.0f).nodes.size(), own->nodes.size());
  Result<Graph> flat = parse_graph(testing::graph_text(R"({"id": "p", "op": "P"})", R"("color": "p")"), "flat.json");
  ASSERT_TRUE(flat.ok());
  EXPECT_EQ(with_normal_from_height(*flat, 1.0f).outputs.size(), 1u);
}

TEST(TextureBake, NormalMapConventionsDifferInTheGreenChannelOnly) {
  Image normals{2, 1, 3, {0.6f, 0.0f, 0.8f, -0.25f, 0.75f, 0.5f}};
  const Image opengl = encoded_normal_map(normals, NormalConvention::opengl);
  const Image directx = encoded_normal_map(normals, NormalConvention::directx);
  EXPECT_EQ(opengl.pixels, (std::vector<float>{0.8f, 0.5f, 0.9f, 0.375f, 0.875f, 0.75f}));
  EXPECT_EQ(directx.pixels, (std::vector<float>{0.8f, 0.5f, 0.9f, 0.375f, 0.125f, 0.75f}));
}

}  // namespace
}  // namespace shadetree

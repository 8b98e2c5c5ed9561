// The periodic noise ops (pnoise, pnoise_improved, pturbulence, pfbm,
// pcellular; the 4D ones are in tests/noise4_test.cpp): each
// repeats exactly every period along each axis, a period of 256 (the
// tables' own) gives back the plain op bit for bit, and a texture over
// one period tiles: the tile beside it is the same image on both backends.
#include <gtest/gtest.h>

#include <random>

#include "interp/interpreter.h"
#include "jit/jit_kernel.h"
#include "nodes/semantics/cellular.h"
#include "nodes/semantics/noise.h"
#include "pipeline/compile_graph.h"
#include "render/texture_driver.h"
#include "support/graph_text.h"

namespace shadetree {
namespace {

namespace sem = semantics;

const NoiseTables& tables() { return noise_tables(default_noise_seed); }

// Every periodic op at p, with periods (px, py, pz): one float per op and output.
std::vector<float> periodic_values(float x, float y, float z, float px, float py, float pz) {
  const auto cells = sem::pcellular(tables(), x, y, z, px, py, pz, 1.0f);
  return {sem::pnoise(tables(), x, y, z, px, py, pz),
          sem::pnoise_improved(x, y, z, px, py, pz),
          sem::pturbulence(tables(), x, y, z, px, py, pz, 6.0f, 0.0f),
          sem::pfbm(tables(), x, y, z, px, py, pz, 5.0f, 2.0f, 0.5f, 0.0f),
          sem::pfbm(tables(), x, y, z, px, py, pz, 4.0f, 3.0f, 0.6f, 0.0f),
          cells.nearest,
          cells.second};
}

// On points with few bits (sixteenths), p + period is exact, so the values
// must be equal, not close.
TEST(PeriodicNoise, RepeatsExactlyEveryPeriodAlongEachAxis) {
  std::mt19937 random(2002);
  std::uniform_int_distribution<int> sixteenths(-400, 400);
  const float periods[][3] = {{4, 4, 4}, {1, 3, 7}, {5, 2, 256}, {16, 9, 1}};
  for (const auto& period : periods)
    for (int i = 0; i < 300; ++i) {
      const float p[3] = {sixteenths(random) / 16.0f, sixteenths(random) / 16.0f, sixteenths(random) / 16.0f};
      const std::vector<float> here = periodic_values(p[0], p[1], p[2], period[0], period[1], period[2]);
      for (int axis = 0; axis < 3; ++axis)
        for (float times : {1.0f, -2.0f}) {
          float q[3] = {p[0], p[1], p[2]};
          q[axis] += times * period[axis];
          EXPECT_EQ(periodic_values(q[0], q[1], q[2], period[0], period[1], period[2]), here)
              << "axis " << axis << " at " << p[0] << ", " << p[1] << ", " << p[2];
        }
    }
}

// The tables repeat every 256 cells: with that period each op is the plain one.
TEST(PeriodicNoise, APeriodOf256IsThePlainOp) {
  std::mt19937 random(1985);
  std::uniform_real_distribution<float> coordinate(-300.0f, 300.0f);
  for (int i = 0; i < 2000; ++i) {
    const float x = coordinate(random), y = coordinate(random), z = coordinate(random);
    EXPECT_EQ(sem::pnoise(tables(), x, y, z, 256.0f, 256.0f, 256.0f), sem::noise(tables(), x, y, z));
    EXPECT_EQ(sem::pnoise_improved(x, y, z, 256.0f, 256.0f, 256.0f), sem::noise_improved(x, y, z));
    EXPECT_EQ(sem::pturbulence(tables(), x, y, z, 256.0f, 256.0f, 256.0f, 6.0f, 0.0f),
              sem::turbulence(tables(), x, y, z, 6.0f, 0.0f));
    EXPECT_EQ(sem::pfbm(tables(), x, y, z, 256.0f, 256.0f, 256.0f, 6.0f, 2.0f, 0.5f, 0.0f),
              sem::fbm(tables(), x, y, z, 6.0f, 2.0f, 0.5f, 0.0f));
    EXPECT_EQ(sem::pcellular(tables(), x, y, z, 256.0f, 256.0f, 256.0f, 1.0f).nearest,
              sem::cellular(tables(), x, y, z, 1.0f).nearest);
  }
}

// Periods are whole numbers of cells from 1 to 256; anything else is rounded
// into that range (NaN included, which becomes a period of 1).
TEST(PeriodicNoise, PeriodsAreRoundedToWholeCells) {
  const float x = 1.3f, y = 2.7f, z = -0.45f;
  EXPECT_EQ(sem::pnoise(tables(), x, y, z, 3.6f, 4.4f, 4.0f), sem::pnoise(tables(), x, y, z, 4.0f, 4.0f, 4.0f));
  EXPECT_EQ(sem::pnoise(tables(), x, y, z, 0.0f, -5.0f, 1.0f), sem::pnoise(tables(), x, y, z, 1.0f, 1.0f, 1.0f));
  EXPECT_EQ(sem::pnoise(tables(), x, y, z, 1e9f, 300.0f, 256.0f),
            sem::pnoise(tables(), x, y, z, 256.0f, 256.0f, 256.0f));
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_TRUE(std::isfinite(sem::pturbulence(tables(), x, y, z, nan, nan, nan, 6.0f, 0.0f)));
}

// A texture graph of `nodes` and `outputs`, run on the interpreter and the JIT.
struct BothBackends {
  LoadedGraph graph;
  std::unique_ptr<Kernel> interpreted;
  std::unique_ptr<Kernel> compiled;

  static BothBackends compile(const std::string& nodes, const std::string& outputs) {
    Result<LoadedGraph> loaded = compile_graph_text(testing::graph_text(nodes, outputs), "tile.json");
    EXPECT_TRUE(loaded.ok()) << loaded.error().to_string();
    BothBackends both{std::move(*loaded), nullptr, nullptr};
    both.interpreted = make_interpreted_kernel(both.graph.ir);
    auto compiled = make_jit_kernel(both.graph.ir);
    EXPECT_TRUE(compiled.ok()) << compiled.error().to_string();
    both.compiled = std::move(*compiled);
    return both;
  }

  // The 64x64 texture over [x0, x0 + 4] x [y0, y0 + 4].
  std::vector<float> tile(const Kernel& kernel, float x0, float y0) const {
    TextureView view;
    view.width = view.height = 64;
    view.domain_min[0] = x0, view.domain_min[1] = y0;
    view.domain_max[0] = x0 + 4, view.domain_max[1] = y0 + 4;
    view.z = 0.5f;
    Result<Image> image = render_texture(kernel, graph.params, view, {});
    EXPECT_TRUE(image.ok());
    return image->pixels;
  }
};

// A texture over one period and the one beside it are the same image, so
// tiles meet without a seam; the interpreter and the JIT agree to the bit.
// (Exactly where the pixels' P are: a period of 4 over 64 pixels puts them
// on sixty-fourths; other sizes round P, and tiles agree to rounding.)
TEST(PeriodicNoise, TexturesOverOnePeriodTile) {
  const BothBackends both = BothBackends::compile(R"({"id": "p", "op": "P"},
          {"id": "t", "op": "pturbulence", "in": {"p": "p", "period": [4, 4, 4], "octaves": 5}},
          {"id": "c", "op": "pcellular", "in": {"p": "p", "period": [4, 4, 4]}},
          {"id": "f", "op": "pfbm", "in": {"p": "p", "period": [4, 4, 4]}},
          {"id": "i", "op": "pnoise_improved", "in": {"p": "p", "period": [4, 4, 4]}},
          {"id": "parts", "op": "split", "in": {"v": "c"}},
          {"id": "rgb", "op": "color", "in": {"r": "t", "g": "parts.x", "b": "f"}})",
                                                  R"("color": "rgb", "alpha": "i")");
  const std::vector<float> first = both.tile(*both.interpreted, 0, 0);
  EXPECT_EQ(both.tile(*both.interpreted, 4, 0), first) << "the tile to the right";
  EXPECT_EQ(both.tile(*both.interpreted, 0, -4), first) << "the tile below";
  EXPECT_EQ(both.tile(*both.compiled, 0, 0), first) << "the JIT";
  EXPECT_EQ(both.tile(*both.compiled, -8, 4), first) << "the JIT, two tiles left and one up";
}

// On both backends, improved noise with a period of 256 is noise_improved
// to the bit (red and green), and the backends agree.
TEST(PeriodicNoise, ImprovedNoiseWithAPeriodOf256IsNoiseImprovedOnBothBackends) {
  const BothBackends both = BothBackends::compile(R"({"id": "p", "op": "P"},
          {"id": "q", "op": "mul", "in": {"a": "p", "b": 37.3}},
          {"id": "plain", "op": "noise_improved", "in": {"p": "q"}},
          {"id": "periodic", "op": "pnoise_improved", "in": {"p": "q", "period": [256, 256, 256]}},
          {"id": "rgb", "op": "color", "in": {"r": "plain", "g": "periodic", "b": 0}})",
                                                  R"("color": "rgb")");
  for (const Kernel* kernel : {both.interpreted.get(), both.compiled.get()}) {
    const std::vector<float> pixels = both.tile(*kernel, -3, -2);
    const int channels = static_cast<int>(pixels.size() / (64 * 64));
    for (std::size_t i = 0; i < pixels.size(); i += channels) ASSERT_EQ(pixels[i], pixels[i + 1]) << "pixel " << i;
  }
  EXPECT_EQ(both.tile(*both.compiled, -3, -2), both.tile(*both.interpreted, -3, -2));
}

}  // namespace
}  // namespace shadetree

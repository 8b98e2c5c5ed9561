// Noise over four dimensions (nodes/semantics/noise4.h): noise4 is zero on
// its lattice, within its proven bound, continuous across cell faces and
// isotropic in its spread; turbulence4 sums its octaves; pnoise4 and
// pturbulence4 repeat exactly along p and w, so that a 48-frame loop's
// frame 48 is its frame 0; the interpreter and the JIT agree to the bit.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "interp/interpreter.h"
#include "jit/jit_kernel.h"
#include "nodes/semantics/noise4.h"
#include "nodes/semantics/noise_intervals.h"
#include "pipeline/compile_graph.h"
#include "render/texture_driver.h"
#include "support/graph_text.h"

namespace shadetree {
namespace {

namespace sem = semantics;

const NoiseTables& tables() { return noise_tables(default_noise_seed); }

TEST(Noise4, IsZeroOnTheIntegerLattice) {
  std::mt19937 random(1989);
  std::uniform_int_distribution<int> knot(-600, 600);
  for (int i = 0; i < 2000; ++i) {
    const float x = float(knot(random)), y = float(knot(random)), z = float(knot(random)), w = float(knot(random));
    ASSERT_EQ(sem::noise4(tables(), x, y, z, w), 0.0f) << x << ", " << y << ", " << z << ", " << w;
    ASSERT_EQ(sem::pnoise4(tables(), x, y, z, w, 4.0f, 7.0f, 1.0f, 48.0f), 0.0f);
  }
}

// The rows' paired lookups give what a lookup per knot gives, to the bit,
// also where a row's cells straddle the tables' wrap (x cells 255 and 256).
TEST(Noise4, RowsOfKnotsAgreeWithKnotsOneAtATime) {
  std::mt19937 random(1985);
  std::uniform_real_distribution<float> coordinate(-50.0f, 50.0f), near_wrap(254.0f, 257.0f);
  for (int i = 0; i < 5000; ++i) {
    const float x = i % 2 ? coordinate(random) : near_wrap(random), y = coordinate(random), z = coordinate(random),
                w = coordinate(random);
    const auto gradient = sem::noise4_gradient_tables(tables());
    float knot_by_knot = 0.0f;
    sem::for_each_noise4_knot(tables(), x, y, z, w, sem::lattice_axis(x), sem::lattice_axis(y), sem::lattice_axis(z),
                              sem::lattice_axis(w), [&](int slot, float u, float v, float s, float t) {
                                const std::array<float, 4> g{gradient[0][slot], gradient[1][slot], gradient[2][slot],
                                                             gradient[3][slot]};
                                knot_by_knot = knot_by_knot + sem::noise_weight(u) * sem::noise_weight(v) *
                                                                  sem::noise_weight(s) * sem::noise_weight(t) *
                                                                  sem::noise4_slope(g, u, v, s, t);
                              });
    ASSERT_EQ(sem::noise4(tables(), x, y, z, w), knot_by_knot) << x << ", " << y << ", " << z << ", " << w;
  }
}

// The proven bound (nodes/semantics/noise_intervals.h) holds over many
// points, and the values fill a good part of it: noise4 is not a flat field.
TEST(Noise4, StaysWithinItsProvenBound) {
  std::mt19937 random(2002);
  std::uniform_real_distribution<float> coordinate(-50.0f, 50.0f);
  float largest = 0.0f;
  for (int i = 0; i < 400000; ++i) {
    const float value =
        sem::noise4(tables(), coordinate(random), coordinate(random), coordinate(random), coordinate(random));
    largest = std::max(largest, std::fabs(value));
  }
  EXPECT_LE(largest, lanes::noise4_bound);
  EXPECT_GT(largest, 0.6f);
}

// E[g g^T] = I / 3 for the 4D gradients as for the 3D ones, and the weights
// spread the same way (noise4.h), so noise4's spread is noise's, and the
// gallery's graphs keep their look when they move to 4D: root mean squares
// over random points agree within 5%.
TEST(Noise4, SpreadsAsMuchAsNoise) {
  std::mt19937 random(1985);
  std::uniform_real_distribution<float> coordinate(-100.0f, 100.0f);
  double squares3 = 0.0, squares4 = 0.0;
  const int count = 200000;
  for (int i = 0; i < count; ++i) {
    const float x = coordinate(random), y = coordinate(random), z = coordinate(random), w = coordinate(random);
    squares3 += std::pow(sem::noise(tables(), x, y, z), 2);
    squares4 += std::pow(sem::noise4(tables(), x, y, z, w), 2);
  }
  EXPECT_NEAR(std::sqrt(squares4 / count) / std::sqrt(squares3 / count), 1.0, 0.05);
}

// Knots on the far side of a face weigh w(1) = 0 at it, so the two cells'
// sums meet: a step of 2^-12 across a face changes the value no more than
// the gradient bound allows (6 per unit, dnoise's bound, generously).
TEST(Noise4, IsContinuousAcrossCellFaces) {
  std::mt19937 random(1992);
  std::uniform_real_distribution<float> coordinate(-20.0f, 20.0f);
  std::uniform_int_distribution<int> face(-20, 20);
  const float step = 1.0f / 4096.0f;
  for (int i = 0; i < 2000; ++i) {
    float p[4] = {coordinate(random), coordinate(random), coordinate(random), coordinate(random)};
    const int axis = i % 4;
    p[axis] = float(face(random));
    float before[4] = {p[0], p[1], p[2], p[3]}, after[4] = {p[0], p[1], p[2], p[3]};
    before[axis] -= step;
    after[axis] += step;
    const float at = sem::noise4(tables(), p[0], p[1], p[2], p[3]);
    EXPECT_NEAR(sem::noise4(tables(), before[0], before[1], before[2], before[3]), at, 8.0f * step) << "axis " << axis;
    EXPECT_NEAR(sem::noise4(tables(), after[0], after[1], after[2], after[3]), at, 8.0f * step) << "axis " << axis;
  }
}

// Moving along w changes the pattern itself, not where it is: noise4 at
// w + 1/2 is not noise4 at w shifted in p.
TEST(Noise4, EvolvesAlongW) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> coordinate(-10.0f, 10.0f);
  int changed = 0;
  for (int i = 0; i < 1000; ++i) {
    const float x = coordinate(random), y = coordinate(random), z = coordinate(random), w = coordinate(random);
    changed += std::fabs(sem::noise4(tables(), x, y, z, w) - sem::noise4(tables(), x, y, z, w + 0.5f)) > 0.05f;
  }
  EXPECT_GT(changed, 500);
}

TEST(Turbulence4, IsTheSumOfItsOctaves) {
  const float x = 0.37f, y = -1.61f, z = 2.9f, w = 5.25f;
  auto octave = [&](float f) { return std::fabs(sem::noise4(tables(), x * f, y * f, z * f, w * f)) / f; };
  EXPECT_EQ(sem::turbulence4(tables(), x, y, z, w, 1.0f, 0.0f), octave(1));
  EXPECT_FLOAT_EQ(sem::turbulence4(tables(), x, y, z, w, 3.0f, 0.0f), octave(1) + octave(2) + octave(4));
  // Octaves whose scale is not above filter_width drop out (1985 appendix).
  EXPECT_EQ(sem::turbulence4(tables(), x, y, z, w, 6.0f, 0.3f), sem::turbulence4(tables(), x, y, z, w, 2.0f, 0.0f));
}

// The periodic ops at (p, w), with periods along x, y, z and w.
std::vector<float> periodic_values(const float (&p)[4], const float (&period)[4]) {
  return {sem::pnoise4(tables(), p[0], p[1], p[2], p[3], period[0], period[1], period[2], period[3]),
          sem::pturbulence4(tables(), p[0], p[1], p[2], p[3], period[0], period[1], period[2], period[3], 6.0f, 0.0f)};
}

// On sixteenths, p + period and w + w_period are exact, so the values must
// be equal, not close.
TEST(PeriodicNoise4, RepeatsExactlyEveryPeriodAlongEachAxisAndW) {
  std::mt19937 random(48);
  std::uniform_int_distribution<int> sixteenths(-400, 400);
  const float periods[][4] = {{4, 4, 4, 4}, {1, 3, 7, 2}, {5, 2, 256, 48}, {16, 9, 1, 256}};
  for (const auto& period : periods)
    for (int i = 0; i < 200; ++i) {
      const float p[4] = {sixteenths(random) / 16.0f, sixteenths(random) / 16.0f, sixteenths(random) / 16.0f,
                          sixteenths(random) / 16.0f};
      const std::vector<float> here = periodic_values(p, period);
      for (int axis = 0; axis < 4; ++axis)
        for (float times : {1.0f, -2.0f}) {
          float q[4] = {p[0], p[1], p[2], p[3]};
          q[axis] += times * period[axis];
          EXPECT_EQ(periodic_values(q, period), here) << "axis " << axis << " at " << p[0] << ", " << p[1] << ", "
                                                      << p[2] << ", " << p[3];
        }
    }
}

TEST(PeriodicNoise4, APeriodOf256IsThePlainOp) {
  std::mt19937 random(256);
  std::uniform_real_distribution<float> coordinate(-300.0f, 300.0f);
  for (int i = 0; i < 2000; ++i) {
    const float x = coordinate(random), y = coordinate(random), z = coordinate(random), w = coordinate(random);
    EXPECT_EQ(sem::pnoise4(tables(), x, y, z, w, 256.0f, 256.0f, 256.0f, 256.0f), sem::noise4(tables(), x, y, z, w));
    EXPECT_EQ(sem::pturbulence4(tables(), x, y, z, w, 256.0f, 256.0f, 256.0f, 256.0f, 6.0f, 0.0f),
              sem::turbulence4(tables(), x, y, z, w, 6.0f, 0.0f));
  }
}

// The interval form (noise_intervals.h) on a point box is the value to
// within its rounding margin, and over any finite box within the bound.
TEST(Noise4, IntervalFormIsTightOnAPointAndBoundedOnABox) {
  using lanes::Interval;
  const float x = 1.37f, y = -0.61f, z = 3.9f, w = 0.25f;
  const float value = sem::noise4(tables(), x, y, z, w);
  const Interval point = sem::noise4(tables(), Interval(x), Interval(y), Interval(z), Interval(w));
  EXPECT_LE(point.lo, value);
  EXPECT_GE(point.hi, value);
  EXPECT_LT(point.hi - point.lo, 1e-3f);
  const Interval wide = sem::noise4(tables(), Interval(-40, 40), Interval(y), Interval(z), Interval(w));
  EXPECT_GE(wide.lo, -lanes::noise4_bound - lanes::lattice_rounding_margin);
  EXPECT_LE(wide.hi, lanes::noise4_bound + lanes::lattice_rounding_margin);
}

// A texture graph on both backends, at a frame.
struct BothBackends {
  LoadedGraph graph;
  std::unique_ptr<Kernel> interpreted;
  std::unique_ptr<Kernel> compiled;

  explicit BothBackends(const std::string& nodes) {
    Result<LoadedGraph> loaded = compile_graph_text(testing::graph_text(nodes, R"("color": "rgb")"), "noise4.json");
    EXPECT_TRUE(loaded.ok()) << loaded.error().to_string();
    graph = std::move(*loaded);
    interpreted = make_interpreted_kernel(graph.ir);
    auto jit = make_jit_kernel(graph.ir);
    EXPECT_TRUE(jit.ok()) << jit.error().to_string();
    compiled = std::move(*jit);
  }

  std::vector<float> frame(const Kernel& kernel, float frame) const {
    TextureView view;
    view.width = view.height = 48;
    view.domain_min[0] = view.domain_min[1] = -2.0f;
    view.domain_max[0] = view.domain_max[1] = 2.0f;
    view.z = 0.75f;
    view.frame = frame;
    Result<Image> image = render_texture(kernel, graph.params, view, {});
    EXPECT_TRUE(image.ok());
    return image->pixels;
  }
};

// A loop of 48 frames (2 seconds at 24 frames a second): w = 2 time with a
// w_period of 4, so frame 48 is frame 0 to the bit, on both backends, and
// frame 24 is not; the interpreter and the JIT agree on every op.
TEST(PeriodicNoise4, AFortyEightFrameLoopEndsWhereItStarts) {
  const BothBackends both(R"({"id": "p", "op": "P"}, {"id": "time", "op": "time"},
      {"id": "w", "op": "mul", "in": {"a": "time", "b": 2}},
      {"id": "q", "op": "mul", "in": {"a": "p", "b": 3}},
      {"id": "looping", "op": "pturbulence4", "in": {"p": "q", "w": "w", "period": [12, 12, 12], "w_period": 4}},
      {"id": "single", "op": "pnoise4", "in": {"p": "q", "w": "w", "period": [12, 12, 12], "w_period": 4}},
      {"id": "rgb", "op": "color", "in": {"r": "looping", "g": "single", "b": 0}})");
  for (const Kernel* kernel : {both.interpreted.get(), both.compiled.get()}) {
    EXPECT_EQ(both.frame(*kernel, 48), both.frame(*kernel, 0));
    EXPECT_EQ(both.frame(*kernel, 96), both.frame(*kernel, 0));
    EXPECT_NE(both.frame(*kernel, 24), both.frame(*kernel, 0));
  }
  for (float frame : {0.0f, 7.0f, 31.0f})
    EXPECT_EQ(both.frame(*both.compiled, frame), both.frame(*both.interpreted, frame)) << "frame " << frame;
}

TEST(Noise4, InterpreterAndJitAgree) {
  const BothBackends both(R"({"id": "p", "op": "P"}, {"id": "time", "op": "time"},
      {"id": "q", "op": "mul", "in": {"a": "p", "b": 5.3}},
      {"id": "n", "op": "noise4", "in": {"p": "q", "w": "time"}},
      {"id": "t", "op": "turbulence4", "in": {"p": "q", "w": "time", "octaves": 7}},
      {"id": "i", "op": "pnoise_improved", "in": {"p": "q", "period": [6, 5, 4]}},
      {"id": "rgb", "op": "color", "in": {"r": "n", "g": "t", "b": "i"}})");
  for (float frame : {0.0f, 13.0f, 200.5f})
    EXPECT_EQ(both.frame(*both.compiled, frame), both.frame(*both.interpreted, frame)) << "frame " << frame;
}

}  // namespace
}  // namespace shadetree

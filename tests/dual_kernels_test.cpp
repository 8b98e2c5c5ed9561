// Dual forms of the ops (interp/dual_kernels.h, nodes/lane_dual.h): for
// every op and type, the derivative its semantics compute over duals
// agrees with central differences of its lane form, at random points
// along random directions, wherever the lane form is smooth there.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "interp/dual_kernels.h"
#include "interp/interpreter.h"
#include "ir/op_constants.h"
#include "nodes/registry.h"
#include "support/one_op_graph.h"

namespace shadetree {
namespace {

constexpr int lanes = interpreter_block_size;

// The op's instruction in its one-op graph, with its constants.
struct OneOp {
  IrInstr instr;
  OpConstants constants;
};

// Plain planes of the arguments at point + t direction, per lane.
struct Points {
  std::vector<float> point, direction;  // [(3a + c) * lanes + lane]
  Points() : point(max_op_args * 3 * lanes), direction(max_op_args * 3 * lanes) {}
  float at(std::size_t plane, int lane, float t) const {
    const std::size_t i = plane * lanes + static_cast<std::size_t>(lane);
    return point[i] + t * direction[i];
  }
};

// The lane form at point + t direction: results[c * lanes + lane].
std::vector<float> lane_form(const OneOp& op, const Points& points, float t) {
  std::vector<float> planes(max_op_args * 3 * lanes), results(3 * lanes);
  const float* in[max_op_args * 3] = {};
  for (std::size_t plane = 0; plane < max_op_args * 3; ++plane) {
    for (int lane = 0; lane < lanes; ++lane) planes[plane * lanes + static_cast<std::size_t>(lane)] = points.at(plane, lane, t);
    in[plane] = &planes[plane * lanes];
  }
  float* out[3] = {&results[0], &results[lanes], &results[2 * lanes]};
  interp::op_kernel(op.instr.op)(interp::InstructionPlanes{in, out, &op.constants}, interp::Lanes{nullptr, lanes, true});
  return results;
}

// The dual form at the point, the direction carried as d/dP.x and, scaled
// by -1/2, as d/dP.y (d/dP.z stays 0): results[(4c + k) * lanes + lane].
std::vector<float> dual_form(const OneOp& op, const Points& points) {
  std::vector<float> planes(max_op_args * 12 * lanes), results(12 * lanes);
  const float* in[max_op_args * 12] = {};
  for (std::size_t plane = 0; plane < max_op_args * 3; ++plane)
    for (int k = 0; k < 4; ++k) {
      float* to = &planes[(plane * 4 + static_cast<std::size_t>(k)) * lanes];
      for (int lane = 0; lane < lanes; ++lane) {
        const float d = points.direction[plane * lanes + static_cast<std::size_t>(lane)];
        to[lane] = k == 0 ? points.at(plane, lane, 0.0f) : k == 1 ? d : k == 2 ? -0.5f * d : 0.0f;
      }
      in[plane * 4 + static_cast<std::size_t>(k)] = to;
    }
  float* out[12];
  for (std::size_t i = 0; i < 12; ++i) out[i] = &results[i * lanes];
  interp::dual_op_kernel(op.instr.op)(interp::InstructionPlanes{in, out, &op.constants},
                                      interp::Lanes{nullptr, lanes, true});
  return results;
}

struct ErrorStats {
  std::vector<double> errors;
  int skipped = 0;
  std::string worst_sample;
  double worst() const { return errors.empty() ? 0.0 : *std::max_element(errors.begin(), errors.end()); }
  double median() {
    if (errors.empty()) return 0.0;
    std::nth_element(errors.begin(), errors.begin() + errors.size() / 2, errors.end());
    return errors[errors.size() / 2];
  }
};

// Relative error of the dual derivative against Richardson-extrapolated
// central differences at steps h and h/2, checked only where those can
// tell: the lane form finite over [-h, h] and smooth there (its second
// differences at nine points h/4 apart agree: no kink, jump or sawtooth,
// no rounding inside the op larger than the steps), and the differences
// accurate to 1e-3 (converged, and above what rounding the values to
// floats leaves in them). Points and directions are dyadic (see
// random_points), so that every point p + t d the differences take is
// exact.
void compare(const OneOp& op, const Points& points, ErrorStats& stats) {
  constexpr double h = 1.0 / 64;
  std::vector<float> f[9];  // at t = (k - 4) h / 4
  for (int k = 0; k < 9; ++k) f[k] = lane_form(op, points, float((k - 4) * h / 4));
  const auto dual = dual_form(op, points);
  auto part = [&](int c, int k, int lane) {
    return dual[static_cast<std::size_t>(4 * c + k) * lanes + static_cast<std::size_t>(lane)];
  };
  for (int c = 0; c < op.constants.components; ++c)
    for (int lane = 0; lane < lanes; ++lane) {
      const std::size_t i = static_cast<std::size_t>(c * lanes + lane);
      double v[9], largest = 0;
      bool finite = true;
      for (int k = 0; k < 9; ++k) {
        v[k] = f[k][i];
        finite = finite && std::isfinite(v[k]);
        largest = std::max(largest, std::fabs(v[k]));
      }
      const double coarse = (v[8] - v[0]) / (2 * h), fine = (v[6] - v[2]) / h;
      const double difference = (4 * fine - coarse) / 3;
      const double scale = std::max(std::fabs(difference), 1.0);
      const double ulp = 1.2e-7 * largest;
      double lowest = INFINITY, highest = -INFINITY;
      for (int k = 1; k < 8; ++k) {
        const double second = v[k + 1] - 2 * v[k] + v[k - 1];
        lowest = std::min(lowest, second);
        highest = std::max(highest, second);
      }
      const bool smooth = highest - lowest <= 0.1 * std::max(std::fabs(lowest), std::fabs(highest)) + 8 * ulp;
      const bool accurate = std::fabs(coarse - fine) < 1e-3 * scale && 4 * ulp / h < 1e-3 * scale;
      if (!finite || !smooth || !accurate || std::fabs(difference) > 1e30) {
        ++stats.skipped;
        continue;
      }
      const float at = f[4][i];
      // The value is the lane form's, and every partial follows the chain rule.
      const float dx = part(c, 1, lane), dy = part(c, 2, lane), dz = part(c, 3, lane);
      EXPECT_EQ(part(c, 0, lane), at) << "component " << c;
      EXPECT_NEAR(dy, -0.5f * dx, 1e-6 * (std::fabs(dx) + 1e-3)) << "component " << c;
      EXPECT_EQ(dz, 0.0f) << "component " << c;
      const double error = std::fabs(dx - difference) / scale;
      if (error > stats.worst()) {
        char text[200];
        std::snprintf(text, sizeof text, "lane %d component %d: value %.9g, dual %.9g, differences %.9g at", lane, c,
                      at, dx, difference);
        stats.worst_sample = text;
        for (int a = 0; a < op.instr.arg_count; ++a)
          for (int k = 0; k < component_count(argument_type(op.instr, a)); ++k)
            stats.worst_sample += " " + std::to_string(points.at(static_cast<std::size_t>(3 * a + k), lane, 0.0f)) +
                                  "+t" + std::to_string(points.direction[static_cast<std::size_t>((3 * a + k) * lanes + lane)]);
      }
      stats.errors.push_back(error);
    }
}

// Points and directions of each argument component: near 0, out to 60 and
// in [0, 1], on multiples of 2^-8 (directions of 2^-6), so that p + t d
// is exact for the steps t of compare() (20 bits at most, 23 once an op
// has added an offset below 512 to it); ints (1 to 3,
// octave counts among them) and bools keep their values: they have no
// derivative.
Points random_points(const OneOp& op, std::mt19937& random) {
  Points points;
  auto uniform = [&](float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(random); };
  for (int a = 0; a < op.instr.arg_count; ++a) {
    const Type type = argument_type(op.instr, a);
    for (int c = 0; c < 3; ++c) {
      const int declared = std::min(c, component_count(type) - 1);
      for (int lane = 0; lane < lanes; ++lane) {
        const std::size_t i = static_cast<std::size_t>((a * 3 + c) * lanes + lane);
        if (declared != c) {  // a scalar read splatted: the same plane
          points.point[i] = points.point[static_cast<std::size_t>((a * 3 + declared) * lanes + lane)];
          points.direction[i] = points.direction[static_cast<std::size_t>((a * 3 + declared) * lanes + lane)];
          continue;
        }
        if (type == Type::bool_ || type == Type::int_) {
          points.point[i] = type == Type::bool_ ? float(random() % 2) : float(1 + random() % 3);
          continue;
        }
        const int range = static_cast<int>(random() % 3);
        const float point = range == 0 ? uniform(-3, 3) : range == 1 ? uniform(-60, 60) : uniform(0, 1);
        points.point[i] = std::round(point * 256) / 256;
        points.direction[i] = std::round(uniform(-1, 1) * 64) / 64;
        // Along its divisor b, mod(a, b) = a - b floor(a / b) is a staircase
        // of slope -floor(a / b) with steps far closer than any difference
        // step where |a / b| is large: differences sampled on a grid alias
        // it into a smooth line of another slope.
        if (op.instr.op == OpId::mod && a == 1) points.direction[i] = 0.0f;
      }
    }
  }
  return points;
}

TEST(DualKernels, EveryOpWithALaneFormHasADualForm) {
  for (const OpDef& op : all_ops())
    EXPECT_EQ(interp::op_kernel(op.id) != nullptr, interp::dual_op_kernel(op.id) != nullptr) << op.name;
}

// The figures this prints are the per-op relative errors the closing note
// of the derivatives work quotes; the bound is what float central
// differences can resolve.
TEST(DualKernels, EveryOpsDerivativeAgreesWithCentralDifferences) {
  std::printf("%-18s %-6s %10s %10s %8s %8s\n", "op", "type", "median", "worst", "checked", "skipped");
  for (const OpDef& op : all_ops()) {
    if (!interp::op_kernel(op.id)) continue;
    const Type result = op.outputs[0].type;
    if (op.outputs[0].rule == TypeRule::fixed && (result == Type::bool_ || result == Type::int_)) continue;
    // Each op draws its own points, whatever ops come before it.
    std::mt19937 random(1978 + static_cast<unsigned>(op.id));
    for (Type instance : testing::op_instances(op)) {
      SCOPED_TRACE(op.name + " over " + std::string(type_name(instance)));
      Result<LoadedGraph> loaded = testing::one_op_graph(op, instance);
      ASSERT_TRUE(loaded) << loaded.error().message;
      const IrInstr* found = nullptr;
      for (const IrInstr& instr : loaded->ir.code)
        if (instr.kind == IrOpKind::op && instr.op == op.id) found = &instr;
      ASSERT_NE(found, nullptr);
      const OneOp one{*found, op_constants(loaded->ir, *found)};
      ErrorStats stats;
      for (int batch = 0; batch < 8; ++batch) compare(one, random_points(one, random), stats);
      std::printf("%-18s %-6s %10.2e %10.2e %8zu %8d\n", op.name.c_str(), std::string(type_name(instance)).c_str(),
                  stats.median(), stats.worst(), stats.errors.size(), stats.skipped);
      EXPECT_LT(stats.worst(), 2e-3) << stats.worst_sample;
      // Enough smooth samples that the comparison means something.
      EXPECT_GT(stats.errors.size(), std::size_t{200});
    }
  }
}

}  // namespace
}  // namespace shadetree

// Splines and tables over attribute data laid out by the checker
// (graph/check.cpp). Each op: its definition and its semantics over a frame
// (see nodes/op_frame.h); the formulas are in nodes/semantics/splines.h.
#pragma once

#include "nodes/op_definition.h"
#include "nodes/op_frame.h"
#include "nodes/semantics/splines.h"

namespace shadetree::ops {

using namespace define;
namespace sem = semantics;

// data: count knots of `components` values each; immediates: components, basis.
struct spline {
  static OpDef definition() {
    return {.name = "spline", .family = OpFamily::spline,
            .doc = "spline through knots over x in [0,1] (the 1985 marble_color); T is the knots' type",
            .generic = GenericSet::numeric, .inputs = {in("x", Type::float_)}, .outputs = {generic_out()},
            .attributes = {{"knots", AttributeKind::value_list, true, {},
                            "knot values: numbers, or [r,g,b] / [x,y] arrays"},
                           {"basis", AttributeKind::choice, false, {"catmull-rom", "linear", "step"},
                            "catmull-rom (needs 4 knots, passes through the inner ones), linear or step"}},
            .type_from_knots = true};
  }
  template <class X>
  static void evaluate(const X& x) {
    const int components = x.immediate(0);
    const auto basis = static_cast<sem::SplineBasis>(x.immediate(1));
    for (int c = 0; c < components; ++c)
      x.out(c) = sem::spline(x.data(), x.data_count() / components, components, c, basis, x.in(0));
  }
};

// data: count entries of `components` values, then their prefix sums;
// immediates: components, count.
struct color_table {
  static OpDef definition() {
    return {.name = "color_table", .family = OpFamily::spline,
            .doc = "table of entries over x in [0,1], averaged over filter_width (Rhoades et al. 1992 antialiased "
                   "lookup)",
            .generic = GenericSet::numeric,
            .inputs = {in("x", Type::float_),
                       in("filter_width", Type::float_, 0.0f, "width of the averaged interval in units of x")},
            .outputs = {generic_out()},
            .attributes = {{"entries", AttributeKind::value_list, true, {},
                            "table entries: numbers or [r,g,b] arrays"}},
            .type_from_knots = true};
  }
  template <class X>
  static void evaluate(const X& x) {
    const int components = x.immediate(0), count = x.immediate(1);
    const float* prefix = x.data() + count * components;
    for (int c = 0; c < components; ++c)
      x.out(c) = sem::color_table(x.data(), prefix, count, components, c, x.in(0), x.in(1));
  }
};

// data: domain lo, hi, then the values; immediate: value count.
struct table1d {
  static OpDef definition() {
    return {.name = "table1d", .family = OpFamily::spline,
            .doc = "1D shape transfer function: control points linearly interpolated over domain (Gilet & "
                   "Dischler 2010)",
            .inputs = {in("x", Type::float_)}, .outputs = {out(Type::float_)},
            .attributes = {{"values", AttributeKind::value_list, true, {}, "equally spaced control values"},
                           {"domain", AttributeKind::number_pair, false, {},
                            "[lo, hi] range of x covered (default [0,1])"}}};
  }
  template <class X>
  static void evaluate(const X& x) {
    x.out() = sem::table1d(x.data(), x.immediate(0), x.in(0));
  }
};

// data: rows x columns values, row 0 first; immediates: rows, columns.
struct table2d {
  static OpDef definition() {
    return {.name = "table2d", .family = OpFamily::spline,
            .doc = "2D shape transfer function: bilinear over a grid on [0,1]^2 (Gilet & Dischler 2010 section 4.2)",
            .inputs = {in("x", Type::float_, "column coordinate in [0,1]"),
                       in("y", Type::float_, "row coordinate in [0,1]")},
            .outputs = {out(Type::float_)},
            .attributes = {{"values", AttributeKind::number_grid, true, {}, "rows of control values, row 0 at y = 0"}}};
  }
  template <class X>
  static void evaluate(const X& x) {
    x.out() = sem::table2d(x.data(), x.immediate(0), x.immediate(1), x.in(0), x.in(1));
  }
};

}  // namespace shadetree::ops

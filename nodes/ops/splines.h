// Splines and tables over constant data from their attributes. Each op:
// its definition, the layout of its attributes (nodes/attributes.h) and its
// semantics over a frame (nodes/op_frame.h); the formulas are in
// nodes/semantics/splines.h.
#pragma once

#include "nodes/interval_frame.h"
#include "nodes/op_definition.h"
#include "nodes/op_frame.h"
#include "nodes/semantics/shape_intervals.h"
#include "nodes/semantics/splines.h"

namespace shadetree::ops {

using namespace define;
namespace sem = semantics;

// In the order of semantics::SplineBasis. A function, not a global: a
// global with a constructor would be compiled into every JIT kernel.
inline std::vector<std::string> spline_bases() { return {"catmull-rom", "linear", "step"}; }

// data: count knots of `components` values each; immediates: components, basis.
struct spline {
  static OpDef definition() {
    return {.name = "spline", .family = OpFamily::spline,
            .doc = "spline through knots over x in [0,1] (the 1985 marble_color); T is the knots' type",
            .generic = GenericSet::numeric, .inputs = {in("x", Type::float_)}, .outputs = {generic_out()},
            .attributes = {{"knots", AttributeKind::value_list, true, {},
                            "knot values: numbers, or [r,g,b] / [x,y] arrays"},
                           {"basis", AttributeKind::choice, false, spline_bases(),
                            "catmull-rom (needs 4 knots, passes through the inner ones), linear or step"}},
            .type_from_knots = true};
  }
  static void lay_out(const Attributes& attributes, AttributeLayout& layout) {
    const auto basis = static_cast<sem::SplineBasis>(attributes.choice("basis", spline_bases()));
    const int minimum = basis == sem::SplineBasis::catmull_rom ? 4 : basis == sem::SplineBasis::linear ? 2 : 1;
    const int components = attributes.value_list("knots", minimum, layout.data);
    layout.immediate[0] = components;
    layout.immediate[1] = static_cast<int>(basis);
    layout.generic = type_of_knots(components);
  }
  template <class X>
  static void evaluate(const X& x) {
    const int components = x.immediate(0);
    const auto basis = static_cast<sem::SplineBasis>(x.immediate(1));
    frame::for_components(components, [&](int c) {
      x.out(c) = sem::spline(x.data(), x.data_count() / components, components, c, basis, x.in(0));
    });
  }
  static void evaluate_interval(const IntervalFrame& x) {
    const int components = x.immediate(0);
    const auto basis = static_cast<sem::SplineBasis>(x.immediate(1));
    frame::for_components(components, [&](int c) {
      x.out(c) = lanes::spline_range(x.data(), x.data_count() / components, components, c, basis, x.in(0));
    });
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
  static void lay_out(const Attributes& attributes, AttributeLayout& layout) {
    const int components = attributes.value_list("entries", 1, layout.data);
    const int count = static_cast<int>(layout.data.size()) / components;
    // Prefix sums follow the entries: prefix[k] = sum of the first k.
    std::vector<float> prefix(static_cast<std::size_t>((count + 1) * components), 0.0f);
    for (int k = 0; k < count; ++k)
      for (int c = 0; c < components; ++c)
        prefix[(k + 1) * components + c] = prefix[k * components + c] + layout.data[k * components + c];
    layout.data.insert(layout.data.end(), prefix.begin(), prefix.end());
    layout.immediate[0] = components;
    layout.immediate[1] = count;
    layout.generic = type_of_knots(components);
  }
  template <class X>
  static void evaluate(const X& x) {
    const int components = x.immediate(0), count = x.immediate(1);
    const float* prefix = x.data() + count * components;
    frame::for_components(components, [&](int c) {
      x.out(c) = sem::color_table(x.data(), prefix, count, components, c, x.in(0), x.in(1));
    });
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
  static void lay_out(const Attributes& attributes, AttributeLayout& layout) {
    const auto [lo, hi] = attributes.number_pair("domain", {0.0f, 1.0f});
    std::vector<float> values;
    if (attributes.value_list("values", 1, values) != 1) attributes.fail("attribute \"values\" must be a list of numbers");
    layout.data = {lo, hi};
    layout.data.insert(layout.data.end(), values.begin(), values.end());
    layout.immediate[0] = static_cast<int>(values.size());
  }
  template <class X>
  static void evaluate(const X& x) {
    x.out() = sem::table1d(x.data(), x.immediate(0), x.in(0));
  }
  static void evaluate_interval(const IntervalFrame& x) {
    const float lo = x.data()[0], hi = x.data()[1];
    x.out() = lanes::spline_range(x.data() + 2, x.immediate(0), 1, 0, sem::SplineBasis::linear,
                                  (x.in(0) - lo) / (lanes::Interval(hi) - lo));
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
  static void lay_out(const Attributes& attributes, AttributeLayout& layout) {
    const auto [rows, columns] = attributes.number_grid("values", layout.data);
    layout.immediate[0] = rows;
    layout.immediate[1] = columns;
  }
  template <class X>
  static void evaluate(const X& x) {
    x.out() = sem::table2d(x.data(), x.immediate(0), x.immediate(1), x.in(0), x.in(1));
  }
  static void evaluate_interval(const IntervalFrame& x) {
    x.out() = lanes::table2d_range(x.data(), x.immediate(0), x.immediate(1), x.in(0), x.in(1));
  }
};

inline std::vector<std::string> image_wraps() { return {"repeat", "clamp"}; }

// data: the image's RGB pixels, bottom row first (grey images repeat their
// one channel; alpha is dropped); immediates: width, wrap mode.
struct image {
  static OpDef definition() {
    return {.name = "image", .family = OpFamily::spline,
            .doc = "an image file sampled at uv, bilinear; (0,0) is its lower-left corner (Perlin 1985: a stored "
                   "texture is a table lookup composed with a projection)",
            .inputs = {in("uv", Type::vec2, "image coordinates, [0,1]^2 over the image")},
            .outputs = {out(Type::color)},
            .attributes = {{"file", AttributeKind::image_file, true, {},
                            "the image file (any format OpenImageIO reads, at most 1024x1024 pixels), relative to "
                            "the graph file"},
                           {"wrap", AttributeKind::choice, false, image_wraps(),
                            "outside [0,1]: repeat the image or clamp to its edge pixels"}}};
  }
  static void lay_out(const Attributes& attributes, AttributeLayout& layout) {
    const Image& file = attributes.image_file("file");
    const auto width = static_cast<std::size_t>(file.width), channels = static_cast<std::size_t>(file.channels);
    layout.data.reserve(width * static_cast<std::size_t>(file.height) * 3);
    for (int row = file.height - 1; row >= 0; --row)
      for (std::size_t column = 0; column < width; ++column)
        for (std::size_t c = 0; c < 3; ++c)
          layout.data.push_back(file.pixels[(static_cast<std::size_t>(row) * width + column) * channels +
                                            (channels >= 3 ? c : 0)]);
    layout.immediate[0] = file.width;
    layout.immediate[1] = attributes.choice("wrap", image_wraps());
  }
  template <class X>
  static void evaluate(const X& x) {
    const int width = x.immediate(0);
    const int height = x.data_count() / (3 * width);
    frame::store_vec3(x, sem::image(x.data(), width, height, static_cast<sem::ImageWrap>(x.immediate(1)), x.in(0, 0),
                                    x.in(0, 1)));
  }
};

}  // namespace shadetree::ops

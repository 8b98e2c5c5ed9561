// Signatures and docs of every op. Semantics live in nodes/semantics/*.h;
// the papers each op implements are cited there.
#include <cassert>

#include "nodes/registry.h"

namespace shadetree {
namespace {

PortSpec in(std::string name, Type type, std::string doc = {}) {
  return {std::move(name), TypeRule::fixed, type, std::nullopt, std::move(doc)};
}
PortSpec in(std::string name, Type type, float default_value, std::string doc = {}) {
  return {std::move(name), TypeRule::fixed, type, default_value, std::move(doc)};
}
PortSpec generic_in(std::string name, std::string doc = {}) {
  return {std::move(name), TypeRule::generic, Type::float_, std::nullopt, std::move(doc)};
}
PortSpec generic_in(std::string name, float default_value, std::string doc = {}) {
  return {std::move(name), TypeRule::generic, Type::float_, default_value, std::move(doc)};
}
PortSpec out(Type type, std::string name = "out") {
  return {std::move(name), TypeRule::fixed, type, std::nullopt, {}};
}
PortSpec generic_out() { return {"out", TypeRule::generic, Type::float_, std::nullopt, {}}; }

AttributeSpec seed_attribute() {
  return {"seed", AttributeKind::integer, false, {},
          "permutation and gradient tables seed (default 1989)"};
}

OpDef input_op(OpId id, std::string name, Type type, std::string doc,
               std::vector<std::string> kinds = {}) {
  return {id, std::move(name), OpFamily::input, std::move(doc), GenericSet::none, {}, {out(type)}, {}, false,
          std::move(kinds)};
}

// T -> T, applied to each component.
OpDef unary(OpId id, std::string name, std::string doc) {
  return {id, std::move(name), OpFamily::arithmetic, std::move(doc), GenericSet::numeric,
          {generic_in("x")}, {generic_out()}};
}

// (T, T) -> T, applied to each component; floats promote.
OpDef binary(OpId id, std::string name, std::string doc, std::string a = "a", std::string b = "b") {
  return {id, std::move(name), OpFamily::arithmetic, std::move(doc), GenericSet::numeric,
          {generic_in(std::move(a)), generic_in(std::move(b))}, {generic_out()}};
}

OpDef comparison(OpId id, std::string name, std::string doc) {
  return {id, std::move(name), OpFamily::conditional, std::move(doc), GenericSet::none,
          {in("a", Type::float_), in("b", Type::float_)}, {out(Type::bool_)}};
}

OpDef boolean(OpId id, std::string name, std::string doc) {
  return {id, std::move(name), OpFamily::soft_object, std::move(doc), GenericSet::none,
          {in("a", Type::float_), in("b", Type::float_)}, {out(Type::float_)}};
}

std::vector<OpDef> make_ops() {
  using T = Type;
  std::vector<OpDef> ops = {
      input_op(OpId::P, "P", T::vec3, "sample position (object or texture space)"),
      input_op(OpId::N, "N", T::vec3, "surface normal at the sample"),
      input_op(OpId::uv, "uv", T::vec2, "texture coordinates in [0,1]^2"),
      input_op(OpId::time, "time", T::float_, "time in seconds (frame / 24)"),
      input_op(OpId::frame, "frame", T::float_, "animation frame number"),
      input_op(OpId::filter_width, "filter_width", T::float_,
               "sample footprint: pixel size in the units of P, for frequency clamping"),
      input_op(OpId::density, "density", T::float_, "incoming density of a volume sample", {"volume"}),

      {OpId::noise, "noise", OpFamily::generator,
       "Perlin & Hoffert 1989 gradient noise in [-1,1], zero on the integer lattice", GenericSet::none,
       {in("p", T::vec3)}, {out(T::float_)}, {seed_attribute()}},
      {OpId::dnoise, "dnoise", OpFamily::generator, "analytic gradient of noise (Perlin 1985 Dnoise)",
       GenericSet::none, {in("p", T::vec3)}, {out(T::vec3)}, {seed_attribute()}},
      {OpId::vnoise, "vnoise", OpFamily::generator,
       "vector noise: noise at p - sigma, p, p + sigma (1989 section 2.4)", GenericSet::none,
       {in("p", T::vec3)}, {out(T::vec3)}, {seed_attribute()}},
      {OpId::noise_improved, "noise_improved", OpFamily::generator,
       "Perlin 2002 improved noise with the reference permutation", GenericSet::none, {in("p", T::vec3)},
       {out(T::float_)}},
      {OpId::turbulence, "turbulence", OpFamily::generator,
       "sum of |noise(2^i p)| / 2^i; octaves stop where 2^-i <= filter_width (1985 appendix)",
       GenericSet::none,
       {in("p", T::vec3), in("octaves", T::int_, 6.0f, "number of octaves, at most 16"),
        in("filter_width", T::float_, 0.0f, "sample footprint; 0 disables clamping")},
       {out(T::float_)}, {seed_attribute()}},
      {OpId::fbm, "fbm", OpFamily::generator,
       "fractional Brownian motion: sum of gain^i noise(lacunarity^i p), clamped at filter_width",
       GenericSet::none,
       {in("p", T::vec3), in("octaves", T::int_, 6.0f, "number of octaves, at most 16"),
        in("lacunarity", T::float_, 2.0f, "frequency ratio between octaves"),
        in("gain", T::float_, 0.5f, "amplitude ratio between octaves"),
        in("filter_width", T::float_, 0.0f, "sample footprint; 0 disables clamping")},
       {out(T::float_)}, {seed_attribute()}},
      {OpId::sines, "sines", OpFamily::generator,
       "Gardner 1984 sum of sines in [0,1] (cloudy skies): product of phase-shifted sine series in x and y",
       GenericSet::none,
       {in("p", T::vec3), in("frequency", T::float_, 1.0f, "base angular frequency"),
        in("octaves", T::int_, 5.0f, "terms per series, at most 16")},
       {out(T::float_)}},
      {OpId::swave, "swave", OpFamily::generator,
       "square wave in [0,1] box-filtered analytically over filter_width (Rhoades et al. 1992)",
       GenericSet::none,
       {in("x", T::float_), in("filter_width", T::float_, 0.0f, "box filter width in units of x"),
        in("frequency", T::float_, 1.0f, "periods per unit of x"),
        in("duty", T::float_, 0.5f, "fraction of each period that is 1"),
        in("phase", T::float_, 0.0f, "offset in periods")},
       {out(T::float_)}},
      {OpId::julia, "julia", OpFamily::generator,
       "Julia set z -> z^2 + c: fraction of iterations before escape, 1 inside the set", GenericSet::none,
       {in("p", T::vec2, "starting point z0"), in("c", T::vec2, "the constant c"),
        in("iterations", T::int_, 64.0f, "iteration limit, at most 1024")},
       {out(T::float_)}},
      {OpId::checker, "checker", OpFamily::generator, "3D checkerboard: 1 where floor(x)+floor(y)+floor(z) is odd",
       GenericSet::none, {in("p", T::vec3)}, {out(T::float_)}},

      binary(OpId::add, "add", "a + b"),
      binary(OpId::sub, "sub", "a - b"),
      binary(OpId::mul, "mul", "a * b"),
      binary(OpId::div, "div", "a / b"),
      unary(OpId::neg, "neg", "-x"),
      binary(OpId::min, "min", "smaller of a and b"),
      binary(OpId::max, "max", "larger of a and b"),
      {OpId::clamp, "clamp", OpFamily::arithmetic, "x limited to [lo, hi]", GenericSet::numeric,
       {generic_in("x"), generic_in("lo", 0.0f), generic_in("hi", 1.0f)}, {generic_out()}},
      unary(OpId::abs, "abs", "|x|"),
      unary(OpId::floor, "floor", "largest integer not above x"),
      unary(OpId::fract, "fract", "x - floor(x)"),
      binary(OpId::mod, "mod", "a - b * floor(a / b), the sign of b"),
      binary(OpId::pow, "pow", "a raised to b, as exp(b log a) with libm's special cases"),
      unary(OpId::sqrt, "sqrt", "square root"),
      unary(OpId::exp, "exp", "e^x (within a few ulp of libm)"),
      unary(OpId::log, "log", "natural logarithm (within a few ulp of libm)"),
      unary(OpId::sin, "sin", "sine (radians; within a few ulp of libm for |x| < 8192)"),
      unary(OpId::cos, "cos", "cosine (radians; within a few ulp of libm for |x| < 8192)"),
      {OpId::mix, "mix", OpFamily::arithmetic, "a + (b - a) * t", GenericSet::numeric,
       {generic_in("a"), generic_in("b"), generic_in("t")}, {generic_out()}},
      {OpId::step, "step", OpFamily::arithmetic, "0 where x < edge, else 1", GenericSet::numeric,
       {generic_in("edge"), generic_in("x")}, {generic_out()}},
      {OpId::smoothstep, "smoothstep", OpFamily::arithmetic, "cubic Hermite 0..1 between edge0 and edge1",
       GenericSet::numeric, {generic_in("edge0"), generic_in("edge1"), generic_in("x")}, {generic_out()}},
      {OpId::bias, "bias", OpFamily::arithmetic, "t^(ln b / ln 0.5): bias_b(1/2) = b (1989 section 2.3)",
       GenericSet::numeric, {generic_in("t"), generic_in("b", 0.5f)}, {generic_out()}},
      {OpId::gain, "gain", OpFamily::arithmetic,
       "spline of two bias curves: gain_g(1/4) = (1-g)/2 (1989 section 2.3)", GenericSet::numeric,
       {generic_in("t"), generic_in("g", 0.5f)}, {generic_out()}},
      {OpId::remap, "remap", OpFamily::arithmetic, "x mapped linearly from [from_lo, from_hi] to [to_lo, to_hi]",
       GenericSet::numeric,
       {generic_in("x"), generic_in("from_lo", 0.0f), generic_in("from_hi", 1.0f), generic_in("to_lo", 0.0f),
        generic_in("to_hi", 1.0f)},
       {generic_out()}},

      {OpId::dot, "dot", OpFamily::vector, "inner product", GenericSet::vectors,
       {generic_in("a"), generic_in("b")}, {out(T::float_)}},
      {OpId::cross, "cross", OpFamily::vector, "cross product", GenericSet::none,
       {in("a", T::vec3), in("b", T::vec3)}, {out(T::vec3)}},
      {OpId::length, "length", OpFamily::vector, "Euclidean norm", GenericSet::vectors, {generic_in("v")},
       {out(T::float_)}},
      {OpId::normalize, "normalize", OpFamily::vector, "v / length(v) (0 stays 0)", GenericSet::vectors,
       {generic_in("v")}, {generic_out()}},
      {OpId::split, "split", OpFamily::vector, "components x, y, z of a vector (z is 0 for vec2)",
       GenericSet::vectors, {generic_in("v")},
       {out(T::float_, "x"), out(T::float_, "y"), out(T::float_, "z")}},
      {OpId::vec2, "vec2", OpFamily::vector, "vec2 from components", GenericSet::none,
       {in("x", T::float_, 0.0f), in("y", T::float_, 0.0f)}, {out(T::vec2)}},
      {OpId::vec3, "vec3", OpFamily::vector, "vec3 from components", GenericSet::none,
       {in("x", T::float_, 0.0f), in("y", T::float_, 0.0f), in("z", T::float_, 0.0f)}, {out(T::vec3)}},
      {OpId::color, "color", OpFamily::vector, "color from r, g, b", GenericSet::none,
       {in("r", T::float_, 0.0f), in("g", T::float_, 0.0f), in("b", T::float_, 0.0f)}, {out(T::color)}},
      {OpId::to_color, "to_color", OpFamily::vector, "a vec3 reinterpreted as a color", GenericSet::none,
       {in("v", T::vec3)}, {out(T::color)}},
      {OpId::to_vec3, "to_vec3", OpFamily::vector, "a color reinterpreted as a vec3", GenericSet::none,
       {in("c", T::color)}, {out(T::vec3)}},

      comparison(OpId::lt, "lt", "a < b"),
      comparison(OpId::le, "le", "a <= b"),
      comparison(OpId::gt, "gt", "a > b"),
      comparison(OpId::ge, "ge", "a >= b"),
      comparison(OpId::eq, "eq", "a == b"),
      comparison(OpId::ne, "ne", "a != b"),
      {OpId::and_, "and", OpFamily::conditional, "a and b", GenericSet::none,
       {in("a", T::bool_), in("b", T::bool_)}, {out(T::bool_)}},
      {OpId::or_, "or", OpFamily::conditional, "a or b", GenericSet::none, {in("a", T::bool_), in("b", T::bool_)},
       {out(T::bool_)}},
      {OpId::not_, "not", OpFamily::conditional, "not a", GenericSet::none, {in("a", T::bool_)}, {out(T::bool_)}},
      {OpId::select, "select", OpFamily::conditional, "then where cond holds, else otherwise (both evaluated)",
       GenericSet::numeric, {in("cond", T::bool_), generic_in("then"), generic_in("else")}, {generic_out()}},
      {OpId::if_, "if", OpFamily::conditional,
       "then where cond holds, else otherwise; each branch runs only for the samples that take it",
       GenericSet::numeric, {in("cond", T::bool_), generic_in("then"), generic_in("else")}, {generic_out()}},

      {OpId::spline,
       "spline",
       OpFamily::spline,
       "spline through knots over x in [0,1] (the 1985 marble_color); T is the knots' type",
       GenericSet::numeric,
       {in("x", T::float_)},
       {generic_out()},
       {{"knots", AttributeKind::value_list, true, {}, "knot values: numbers, or [r,g,b] / [x,y] arrays"},
        {"basis", AttributeKind::choice, false, {"catmull-rom", "linear", "step"},
         "catmull-rom (needs 4 knots, passes through the inner ones), linear or step"}},
       true},
      {OpId::color_table,
       "color_table",
       OpFamily::spline,
       "table of entries over x in [0,1], averaged over filter_width (Rhoades et al. 1992 antialiased lookup)",
       GenericSet::numeric,
       {in("x", T::float_), in("filter_width", T::float_, 0.0f, "width of the averaged interval in units of x")},
       {generic_out()},
       {{"entries", AttributeKind::value_list, true, {}, "table entries: numbers or [r,g,b] arrays"}},
       true},
      {OpId::table1d,
       "table1d",
       OpFamily::spline,
       "1D shape transfer function: control points linearly interpolated over domain (Gilet & Dischler 2010)",
       GenericSet::none,
       {in("x", T::float_)},
       {out(T::float_)},
       {{"values", AttributeKind::value_list, true, {}, "equally spaced control values"},
        {"domain", AttributeKind::number_pair, false, {}, "[lo, hi] range of x covered (default [0,1])"}}},
      {OpId::table2d,
       "table2d",
       OpFamily::spline,
       "2D shape transfer function: bilinear over a grid on [0,1]^2 (Gilet & Dischler 2010 section 4.2)",
       GenericSet::none,
       {in("x", T::float_, "column coordinate in [0,1]"), in("y", T::float_, "row coordinate in [0,1]")},
       {out(T::float_)},
       {{"values", AttributeKind::number_grid, true, {}, "rows of control values, row 0 at y = 0"}}},

      {OpId::sphere, "sphere", OpFamily::soft_object,
       "soft sphere density: 1 inside r - s/2, 0 outside r + s/2 (1989 section 2.1)", GenericSet::none,
       {in("p", T::vec3), in("center", T::vec3, 0.0f), in("radius", T::float_, 1.0f),
        in("softness", T::float_, 0.2f)},
       {out(T::float_)}},
      {OpId::box, "box", OpFamily::soft_object,
       "soft box density: ramps from 1 to 0 across softness around the surface", GenericSet::none,
       {in("p", T::vec3), in("center", T::vec3, 0.0f), in("half_size", T::vec3, 0.5f),
        in("softness", T::float_, 0.2f)},
       {out(T::float_)}},
      {OpId::torus, "torus", OpFamily::soft_object,
       "soft torus around the z axis: ramps from 1 to 0 across softness around the surface", GenericSet::none,
       {in("p", T::vec3), in("center", T::vec3, 0.0f), in("major_radius", T::float_, 1.0f),
        in("minor_radius", T::float_, 0.25f), in("softness", T::float_, 0.2f)},
       {out(T::float_)}},
      boolean(OpId::intersect, "intersect", "a * b (1989 section 2.2)"),
      boolean(OpId::union_, "union", "a + b - a * b (1989 section 2.2)"),
      boolean(OpId::difference, "difference", "a - a * b (1989 section 2.2)"),
      {OpId::complement, "complement", OpFamily::soft_object, "1 - a (1989 section 2.2)", GenericSet::none,
       {in("a", T::float_)}, {out(T::float_)}},
  };
  for (std::size_t i = 0; i < ops.size(); ++i) assert(static_cast<std::size_t>(ops[i].id) == i);
  return ops;
}

}  // namespace

std::span<const OpDef> all_ops() {
  static const std::vector<OpDef> ops = make_ops();
  return ops;
}

}  // namespace shadetree

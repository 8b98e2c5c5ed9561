// Arithmetic: componentwise over the op's type T (float, vec2, vec3 or
// color), with floats promoted. Each op: its definition and its semantics
// over a frame (see nodes/op_frame.h); the formulas are in
// nodes/semantics/arithmetic.h.
#pragma once

#include "nodes/op_definition.h"
#include "nodes/op_frame.h"
#include "nodes/semantics/arithmetic.h"

namespace shadetree::ops {

using namespace define;
namespace sem = semantics;

// An op whose every result component is sem::function of the same
// component of each of its `arity` arguments. `apply` is that function, so
// a backend may also loop over components and lanes itself (the
// interpreter does, to keep its inner loops tight).
#define SHADETREE_COMPONENTWISE_OP(name, arity_, function, definition_expression)                               \
  struct name {                                                                                                \
    static constexpr int arity = arity_;                                                                       \
    static OpDef definition() { return definition_expression; }                                                \
    template <class... A>                                                                                      \
    static auto apply(A... arguments) {                                                                        \
      return sem::function(arguments...);                                                                      \
    }                                                                                                          \
    template <class X>                                                                                         \
    static void evaluate(const X& x) {                                                                         \
      frame::componentwise<arity>(x, [](auto... arguments) { return apply(arguments...); });                   \
    }                                                                                                          \
  };

inline OpDef numeric(std::string name, std::string doc, std::vector<PortSpec> inputs) {
  return {.name = std::move(name), .family = OpFamily::arithmetic, .doc = std::move(doc),
          .generic = GenericSet::numeric, .inputs = std::move(inputs), .outputs = {generic_out()}};
}

SHADETREE_COMPONENTWISE_OP(add, 2, add, binary("add", "a + b"))
SHADETREE_COMPONENTWISE_OP(sub, 2, sub, binary("sub", "a - b"))
SHADETREE_COMPONENTWISE_OP(mul, 2, mul, binary("mul", "a * b"))
SHADETREE_COMPONENTWISE_OP(div, 2, div, binary("div", "a / b"))
SHADETREE_COMPONENTWISE_OP(neg, 1, neg, unary("neg", "-x"))
SHADETREE_COMPONENTWISE_OP(min, 2, minimum, binary("min", "smaller of a and b"))
SHADETREE_COMPONENTWISE_OP(max, 2, maximum, binary("max", "larger of a and b"))
SHADETREE_COMPONENTWISE_OP(clamp, 3, clamp,
                           numeric("clamp", "x limited to [lo, hi]",
                                   {generic_in("x"), generic_in("lo", 0.0f), generic_in("hi", 1.0f)}))
SHADETREE_COMPONENTWISE_OP(abs, 1, absolute, unary("abs", "|x|"))
SHADETREE_COMPONENTWISE_OP(floor, 1, floor_of, unary("floor", "largest integer not above x"))
SHADETREE_COMPONENTWISE_OP(fract, 1, fract, unary("fract", "x - floor(x)"))
SHADETREE_COMPONENTWISE_OP(mod, 2, mod, binary("mod", "a - b * floor(a / b), the sign of b"))
SHADETREE_COMPONENTWISE_OP(pow, 2, power, binary("pow", "a raised to b, as exp(b log a) with libm's special cases"))
SHADETREE_COMPONENTWISE_OP(sqrt, 1, square_root, unary("sqrt", "square root"))
SHADETREE_COMPONENTWISE_OP(exp, 1, exponential, unary("exp", "e^x (within a few ulp of libm)"))
SHADETREE_COMPONENTWISE_OP(log, 1, logarithm, unary("log", "natural logarithm (within a few ulp of libm)"))
SHADETREE_COMPONENTWISE_OP(sin, 1, sine, unary("sin", "sine (radians; within a few ulp of libm for |x| < 8192)"))
SHADETREE_COMPONENTWISE_OP(cos, 1, cosine,
                           unary("cos", "cosine (radians; within a few ulp of libm for |x| < 8192)"))
SHADETREE_COMPONENTWISE_OP(mix, 3, mix,
                           numeric("mix", "a + (b - a) * t", {generic_in("a"), generic_in("b"), generic_in("t")}))
SHADETREE_COMPONENTWISE_OP(step, 2, step,
                           numeric("step", "0 where x < edge, else 1", {generic_in("edge"), generic_in("x")}))
SHADETREE_COMPONENTWISE_OP(smoothstep, 3, smoothstep,
                           numeric("smoothstep", "cubic Hermite 0..1 between edge0 and edge1",
                                   {generic_in("edge0"), generic_in("edge1"), generic_in("x")}))
SHADETREE_COMPONENTWISE_OP(bias, 2, bias,
                           numeric("bias", "t^(ln b / ln 0.5): bias_b(1/2) = b (1989 section 2.3)",
                                   {generic_in("t"), generic_in("b", 0.5f)}))
SHADETREE_COMPONENTWISE_OP(gain, 2, gain,
                           numeric("gain", "spline of two bias curves: gain_g(1/4) = (1-g)/2 (1989 section 2.3)",
                                   {generic_in("t"), generic_in("g", 0.5f)}))
SHADETREE_COMPONENTWISE_OP(remap, 5, remap,
                           numeric("remap", "x mapped linearly from [from_lo, from_hi] to [to_lo, to_hi]",
                                   {generic_in("x"), generic_in("from_lo", 0.0f), generic_in("from_hi", 1.0f),
                                    generic_in("to_lo", 0.0f), generic_in("to_hi", 1.0f)}))

}  // namespace shadetree::ops

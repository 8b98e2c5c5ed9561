// Every op of the node library, as an enumerator. The order is the order of
// `shadetree nodes`; the definitions are in nodes/signatures.cpp.
#pragma once

#include <cstdint>

namespace shadetree {

#define SHADETREE_OPS(X)                                                      \
  /* inputs */                                                                \
  X(P) X(N) X(uv) X(time) X(frame) X(filter_width) X(density)                \
  /* generators */                                                            \
  X(noise) X(dnoise) X(vnoise) X(noise_improved) X(turbulence) X(fbm)        \
  X(sines) X(swave) X(julia) X(checker)                                       \
  /* arithmetic */                                                            \
  X(add) X(sub) X(mul) X(div) X(neg) X(min) X(max) X(clamp) X(abs) X(floor)  \
  X(fract) X(mod) X(pow) X(sqrt) X(exp) X(log) X(sin) X(cos) X(mix) X(step)  \
  X(smoothstep) X(bias) X(gain) X(remap)                                      \
  /* vectors */                                                               \
  X(dot) X(cross) X(length) X(normalize) X(split) X(vec2) X(vec3) X(color)   \
  X(to_color) X(to_vec3)                                                      \
  /* conditionals */                                                          \
  X(lt) X(le) X(gt) X(ge) X(eq) X(ne) X(and_) X(or_) X(not_) X(select)       \
  X(if_)                                                                      \
  /* splines and tables */                                                    \
  X(spline) X(color_table) X(table1d) X(table2d)                              \
  /* soft objects */                                                          \
  X(sphere) X(box) X(torus) X(intersect) X(union_) X(difference)             \
  X(complement)

enum class OpId : std::uint16_t {
#define SHADETREE_ENUMERATOR(name) name,
  SHADETREE_OPS(SHADETREE_ENUMERATOR)
#undef SHADETREE_ENUMERATOR
};

inline constexpr int op_count = 0
#define SHADETREE_COUNT(name) +1
    SHADETREE_OPS(SHADETREE_COUNT)
#undef SHADETREE_COUNT
    ;

}  // namespace shadetree

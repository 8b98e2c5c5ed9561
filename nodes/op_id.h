// Every op of the node library, as an enumerator, in the order of
// `shadetree nodes`: first one input op per global (nodes/globals.h), then
// the library ops of SHADETREE_LIBRARY_OPS, each defined by the struct of
// the same name in nodes/ops/ (its signature and its semantics). A new op
// is a struct there and its name here; the registry, the interpreter's
// dispatch and the JIT's op library are all generated from this list, so
// their order cannot drift.
#pragma once

#include <cstdint>

#include "nodes/globals.h"

namespace shadetree {

#define SHADETREE_LIBRARY_OPS(X)                                              \
  /* generators (nodes/ops/generators.h) */                                   \
  X(noise) X(dnoise) X(vnoise) X(noise_improved) X(turbulence) X(fbm)        \
  X(sines) X(swave) X(julia) X(checker) X(cellular)                          \
  X(pnoise) X(pturbulence) X(pfbm) X(pcellular) X(pnoise_improved)          \
  X(noise4) X(turbulence4) X(pnoise4) X(pturbulence4)                        \
  /* arithmetic (nodes/ops/arithmetic.h) */                                   \
  X(add) X(sub) X(mul) X(div) X(neg) X(min) X(max) X(clamp) X(abs) X(floor)  \
  X(fract) X(mod) X(pow) X(sqrt) X(exp) X(log) X(sin) X(cos) X(mix) X(step)  \
  X(smoothstep) X(bias) X(gain) X(remap)                                      \
  /* vectors (nodes/ops/vectors.h) */                                         \
  X(dot) X(cross) X(length) X(normalize) X(split) X(vec2) X(vec3) X(color)   \
  X(to_color) X(to_vec3)                                                      \
  /* conditionals (nodes/ops/conditionals.h) */                               \
  X(lt) X(le) X(gt) X(ge) X(eq) X(ne) X(and_) X(or_) X(not_) X(select)       \
  X(if_)                                                                      \
  /* splines and tables (nodes/ops/splines.h) */                              \
  X(spline) X(color_table) X(table1d) X(table2d) X(image)                     \
  /* soft objects (nodes/ops/soft_objects.h) */                               \
  X(sphere) X(box) X(torus) X(closest_on_sphere) X(closest_on_torus)        \
  X(mesh_distance) X(mesh_closest) X(intersect) X(union_) X(difference)      \
  X(complement)                                                               \
  /* derivatives (nodes/ops/derivatives.h) */                                 \
  X(gradient) X(bump)

enum class OpId : std::uint16_t {
#define SHADETREE_GLOBAL_OP(name, type, variability, kinds, doc) name,
  SHADETREE_GLOBALS(SHADETREE_GLOBAL_OP)
#undef SHADETREE_GLOBAL_OP
#define SHADETREE_ENUMERATOR(name) name,
  SHADETREE_LIBRARY_OPS(SHADETREE_ENUMERATOR)
#undef SHADETREE_ENUMERATOR
};

inline constexpr int op_count = global_count
#define SHADETREE_COUNT(name) +1
    SHADETREE_LIBRARY_OPS(SHADETREE_COUNT)
#undef SHADETREE_COUNT
    ;

// The enumerator's name: the op library symbol of the JIT (st_<symbol>_w<W>).
const char* op_symbol(OpId id);

}  // namespace shadetree

// The op library of the JIT: every op's semantics (nodes/semantics/)
// instantiated over clang vector lanes of width 4, 8 and 16. This file is
// compiled by clang to LLVM bitcode at build time (see CMakeLists.txt),
// embedded in the shadetree binary, linked into every kernel module and
// inlined there, so the JIT computes exactly what the interpreter computes.
//
// Calling convention (ABI-neutral, since vectors are never passed by value):
//   st_<op>_w<W>(F* out, <constant data>, const F* arguments...)
// where a vec3 argument or result is an array of 3 F.
#include "nodes/lane_vector.h"
#include "nodes/semantics/arithmetic.h"
#include "nodes/semantics/noise.h"
#include "nodes/semantics/patterns.h"
#include "nodes/semantics/soft_objects.h"
#include "nodes/semantics/splines.h"
#include "nodes/semantics/vector.h"

namespace shadetree {
namespace {

namespace sem = semantics;

template <int W>
struct Ops {
  using F = lanes::floatv<W>;
  using M = lanes::intv<W>;

  static F stored(M mask) { return lanes::select(mask, lanes::splat<F>(1.0f), lanes::splat<F>(0.0f)); }
  static M loaded(F value) { return value != 0.0f; }
  static sem::Vec3<F> vec3(const F* v) { return {v[0], v[1], v[2]}; }
  static void store3(F* out, const sem::Vec3<F>& v) {
    out[0] = v.x;
    out[1] = v.y;
    out[2] = v.z;
  }
};

}  // namespace
}  // namespace shadetree

using namespace shadetree;

#define ST_UNARY(name, function, W) \
  extern "C" void st_##name##_w##W(Ops<W>::F* out, const Ops<W>::F* a) { *out = sem::function(*a); }
#define ST_BINARY(name, function, W)                                                           \
  extern "C" void st_##name##_w##W(Ops<W>::F* out, const Ops<W>::F* a, const Ops<W>::F* b) { \
    *out = sem::function(*a, *b);                                                              \
  }
#define ST_TERNARY(name, function, W)                                                                             \
  extern "C" void st_##name##_w##W(Ops<W>::F* out, const Ops<W>::F* a, const Ops<W>::F* b, const Ops<W>::F* c) { \
    *out = sem::function(*a, *b, *c);                                                                             \
  }
#define ST_QUINARY(name, function, W)                                                                            \
  extern "C" void st_##name##_w##W(Ops<W>::F* out, const Ops<W>::F* a, const Ops<W>::F* b, const Ops<W>::F* c, \
                                   const Ops<W>::F* d, const Ops<W>::F* e) {                                     \
    *out = sem::function(*a, *b, *c, *d, *e);                                                                    \
  }
#define ST_COMPARISON(name, function, W)                                                       \
  extern "C" void st_##name##_w##W(Ops<W>::F* out, const Ops<W>::F* a, const Ops<W>::F* b) { \
    *out = Ops<W>::stored(sem::function(*a, *b));                                              \
  }

#define ST_OPS(W)                                                                                                    \
  ST_UNARY(neg, neg, W)                                                                                              \
  ST_UNARY(abs, absolute, W)                                                                                         \
  ST_UNARY(floor, floor_of, W)                                                                                       \
  ST_UNARY(fract, fract, W)                                                                                          \
  ST_UNARY(sqrt, square_root, W)                                                                                     \
  ST_UNARY(exp, exponential, W)                                                                                      \
  ST_UNARY(log, logarithm, W)                                                                                        \
  ST_UNARY(sin, sine, W)                                                                                             \
  ST_UNARY(cos, cosine, W)                                                                                           \
  ST_UNARY(complement, soft_complement, W)                                                                           \
  ST_BINARY(add, add, W)                                                                                             \
  ST_BINARY(sub, sub, W)                                                                                             \
  ST_BINARY(mul, mul, W)                                                                                             \
  ST_BINARY(div, div, W)                                                                                             \
  ST_BINARY(min, minimum, W)                                                                                         \
  ST_BINARY(max, maximum, W)                                                                                         \
  ST_BINARY(mod, mod, W)                                                                                             \
  ST_BINARY(pow, power, W)                                                                                           \
  ST_BINARY(step, step, W)                                                                                           \
  ST_BINARY(bias, bias, W)                                                                                           \
  ST_BINARY(gain, gain, W)                                                                                           \
  ST_BINARY(intersect, soft_intersect, W)                                                                            \
  ST_BINARY(union, soft_union, W)                                                                                    \
  ST_BINARY(difference, soft_difference, W)                                                                          \
  ST_TERNARY(clamp, clamp, W)                                                                                        \
  ST_TERNARY(mix, mix, W)                                                                                            \
  ST_TERNARY(smoothstep, smoothstep, W)                                                                              \
  ST_QUINARY(remap, remap, W)                                                                                        \
  ST_QUINARY(swave, swave, W)                                                                                        \
  ST_COMPARISON(lt, less, W)                                                                                         \
  ST_COMPARISON(le, less_equal, W)                                                                                   \
  ST_COMPARISON(gt, greater, W)                                                                                      \
  ST_COMPARISON(ge, greater_equal, W)                                                                                \
  ST_COMPARISON(eq, equal, W)                                                                                        \
  ST_COMPARISON(ne, not_equal, W)                                                                                    \
  using F##W = Ops<W>::F;                                                                                            \
  extern "C" void st_and_w##W(F##W* out, const F##W* a, const F##W* b) {                                           \
    *out = Ops<W>::stored(lanes::both(Ops<W>::loaded(*a), Ops<W>::loaded(*b)));                                      \
  }                                                                                                                  \
  extern "C" void st_or_w##W(F##W* out, const F##W* a, const F##W* b) {                                            \
    *out = Ops<W>::stored(lanes::either(Ops<W>::loaded(*a), Ops<W>::loaded(*b)));                                    \
  }                                                                                                                  \
  extern "C" void st_not_w##W(F##W* out, const F##W* a) { *out = Ops<W>::stored(lanes::negate(Ops<W>::loaded(*a))); } \
  extern "C" void st_select_w##W(F##W* out, const F##W* condition, const F##W* a, const F##W* b) {                  \
    *out = lanes::select(Ops<W>::loaded(*condition), *a, *b);                                                       \
  }                                                                                                                  \
  extern "C" void st_noise_w##W(F##W* out, const NoiseTables* tables, const F##W* p) {                              \
    *out = sem::noise(*tables, p[0], p[1], p[2]);                                                                    \
  }                                                                                                                  \
  extern "C" void st_dnoise_w##W(F##W* out, const NoiseTables* tables, const F##W* p) {                             \
    Ops<W>::store3(out, sem::dnoise(*tables, p[0], p[1], p[2]));                                                     \
  }                                                                                                                  \
  extern "C" void st_vnoise_w##W(F##W* out, const NoiseTables* tables, const F##W* p) {                             \
    Ops<W>::store3(out, sem::vnoise(*tables, p[0], p[1], p[2]));                                                     \
  }                                                                                                                  \
  extern "C" void st_noise_improved_w##W(F##W* out, const F##W* p) { *out = sem::noise_improved(p[0], p[1], p[2]); } \
  extern "C" void st_turbulence_w##W(F##W* out, const NoiseTables* tables, const F##W* p, const F##W* octaves,      \
                                     const F##W* filter_width) {                                                     \
    *out = sem::turbulence(*tables, p[0], p[1], p[2], *octaves, *filter_width);                                      \
  }                                                                                                                  \
  extern "C" void st_fbm_w##W(F##W* out, const NoiseTables* tables, const F##W* p, const F##W* octaves,             \
                              const F##W* lacunarity, const F##W* gain, const F##W* filter_width) {                  \
    *out = sem::fbm(*tables, p[0], p[1], p[2], *octaves, *lacunarity, *gain, *filter_width);                         \
  }                                                                                                                  \
  extern "C" void st_sines_w##W(F##W* out, const F##W* p, const F##W* frequency, const F##W* octaves) {             \
    *out = sem::sines(p[0], p[1], *frequency, *octaves);                                                             \
  }                                                                                                                  \
  extern "C" void st_julia_w##W(F##W* out, const F##W* z, const F##W* c, const F##W* iterations) {                  \
    *out = sem::julia(z[0], z[1], c[0], c[1], *iterations);                                                          \
  }                                                                                                                  \
  extern "C" void st_checker_w##W(F##W* out, const F##W* p) { *out = sem::checker(p[0], p[1], p[2]); }             \
  extern "C" void st_dot_w##W(F##W* out, const F##W* a, const F##W* b, int n) { *out = sem::dot_n(a, b, n); }      \
  extern "C" void st_length_w##W(F##W* out, const F##W* v, int n) { *out = sem::length_n(v, n); }                   \
  extern "C" void st_normalize_w##W(F##W* out, const F##W* v, int n) { sem::normalize_n(v, n, out); }               \
  extern "C" void st_cross_w##W(F##W* out, const F##W* a, const F##W* b) {                                          \
    Ops<W>::store3(out, sem::cross(Ops<W>::vec3(a), Ops<W>::vec3(b)));                                               \
  }                                                                                                                  \
  extern "C" void st_spline_w##W(F##W* out, const float* knots, int count, int components, int component,          \
                                 int basis, const F##W* x) {                                                         \
    *out = sem::spline(knots, count, components, component, static_cast<sem::SplineBasis>(basis), *x);               \
  }                                                                                                                  \
  extern "C" void st_color_table_w##W(F##W* out, const float* entries, int count, int components, int component,   \
                                      const F##W* x, const F##W* filter_width) {                                     \
    *out = sem::color_table(entries, entries + count * components, count, components, component, *x, *filter_width); \
  }                                                                                                                  \
  extern "C" void st_table1d_w##W(F##W* out, const float* data, int count, const F##W* x) {                        \
    *out = sem::table1d(data, count, *x);                                                                            \
  }                                                                                                                  \
  extern "C" void st_table2d_w##W(F##W* out, const float* values, int rows, int columns, const F##W* x,            \
                                  const F##W* y) {                                                                   \
    *out = sem::table2d(values, rows, columns, *x, *y);                                                              \
  }                                                                                                                  \
  extern "C" void st_sphere_w##W(F##W* out, const F##W* p, const F##W* center, const F##W* radius,                 \
                                 const F##W* softness) {                                                             \
    *out = sem::soft_sphere(Ops<W>::vec3(p), Ops<W>::vec3(center), *radius, *softness);                              \
  }                                                                                                                  \
  extern "C" void st_box_w##W(F##W* out, const F##W* p, const F##W* center, const F##W* half_size,                 \
                              const F##W* softness) {                                                                \
    *out = sem::soft_box(Ops<W>::vec3(p), Ops<W>::vec3(center), Ops<W>::vec3(half_size), *softness);                 \
  }                                                                                                                  \
  extern "C" void st_torus_w##W(F##W* out, const F##W* p, const F##W* center, const F##W* major_radius,            \
                                const F##W* minor_radius, const F##W* softness) {                                    \
    *out = sem::soft_torus(Ops<W>::vec3(p), Ops<W>::vec3(center), *major_radius, *minor_radius, *softness);          \
  }

ST_OPS(4)
ST_OPS(8)
ST_OPS(16)

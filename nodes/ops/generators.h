// Generators: noise (Perlin 1985, Perlin & Hoffert 1989, Perlin 2002; in
// 3D, and in 4D for animations that evolve) and
// the pattern generators of the Pixel-Planes 5 T-code set (Rhoades et al.
// 1992). Each op: its definition and its semantics over a frame (see
// nodes/op_frame.h); the formulas are in nodes/semantics/.
#pragma once

#include "nodes/interval_frame.h"
#include "nodes/op_definition.h"
#include "nodes/op_frame.h"
#include "nodes/semantics/cellular.h"
#include "nodes/semantics/noise.h"
#include "nodes/semantics/noise4.h"
#include "nodes/semantics/patterns.h"

namespace shadetree::ops {

using namespace define;
namespace sem = semantics;

struct noise {
  static OpDef definition() {
    return {.name = "noise", .family = OpFamily::generator,
            .doc = "Perlin & Hoffert 1989 gradient noise in [-1,1], zero on the integer lattice",
            .inputs = {in("p", Type::vec3)}, .outputs = {out(Type::float_)}, .attributes = {seed_attribute()},
            .tables = OpTables::noise};
  }
  template <class X>
  static void evaluate(const X& x) {
    x.out() = sem::noise(x.tables(), x.in(0, 0), x.in(0, 1), x.in(0, 2));
  }
};

struct dnoise {
  static OpDef definition() {
    return {.name = "dnoise", .family = OpFamily::generator, .doc = "analytic gradient of noise (Perlin 1985 Dnoise)",
            .inputs = {in("p", Type::vec3)}, .outputs = {out(Type::vec3)}, .attributes = {seed_attribute()},
            .tables = OpTables::noise};
  }
  template <class X>
  static void evaluate(const X& x) {
    frame::store_vec3(x, sem::dnoise(x.tables(), x.in(0, 0), x.in(0, 1), x.in(0, 2)));
  }
  static void evaluate_interval(const IntervalFrame& x) {
    // Its proven bound: the product rule over the knots is not worth
    // enclosing cell by cell for an op no volume graph uses.
    const lanes::Interval bound = lanes::lattice_range(x.in(0, 0), x.in(0, 1), x.in(0, 2), lanes::noise_derivative_bound);
    frame::store_vec3(x, {bound, bound, bound});
  }
};

// No lane form: lowering makes vnoise three noise instructions
// (ir/lower.cpp), so that the optimizer, the kernel split and the
// outliner see each noise as the noise it is.
struct vnoise {
  // 1989 section 2.4: sigma is far enough apart (and not a multiple of the
  // 256-cell period) that the three noises meet unrelated knots.
  static constexpr float offset[3] = {113.5f, 271.25f, 37.75f};
  static OpDef definition() {
    return {.name = "vnoise", .family = OpFamily::generator,
            .doc = "vector noise: noise at p - sigma, p, p + sigma (1989 section 2.4)",
            .inputs = {in("p", Type::vec3)}, .outputs = {out(Type::vec3)}, .attributes = {seed_attribute()},
            .tables = OpTables::noise};
  }
};

struct noise_improved {
  static OpDef definition() {
    return {.name = "noise_improved", .family = OpFamily::generator,
            .doc = "Perlin 2002 improved noise with the reference permutation", .inputs = {in("p", Type::vec3)},
            .outputs = {out(Type::float_)}};
  }
  template <class X>
  static void evaluate(const X& x) {
    x.out() = sem::noise_improved(x.in(0, 0), x.in(0, 1), x.in(0, 2));
  }
  static void evaluate_interval(const IntervalFrame& x) {
    // Its proven bound (its hash is bits all the way).
    x.out() = lanes::lattice_range(x.in(0, 0), x.in(0, 1), x.in(0, 2), lanes::improved_noise_bound);
  }
};

struct turbulence {
  static OpDef definition() {
    return {.name = "turbulence", .family = OpFamily::generator,
            .doc = "sum of |noise(2^i p)| / 2^i; octaves stop where 2^-i <= filter_width (1985 appendix)",
            .inputs = {in("p", Type::vec3), in("octaves", Type::int_, 6.0f, "number of octaves, at most 16"),
                       in("filter_width", Type::float_, 0.0f, "sample footprint; 0 disables clamping")},
            .outputs = {out(Type::float_)}, .attributes = {seed_attribute()}, .tables = OpTables::noise};
  }
  template <class X>
  static void evaluate(const X& x) {
    x.out() = sem::turbulence(x.tables(), x.in(0, 0), x.in(0, 1), x.in(0, 2), x.in(1), x.in(2));
  }
};

struct fbm {
  static OpDef definition() {
    return {.name = "fbm", .family = OpFamily::generator,
            .doc = "fractional Brownian motion: sum of gain^i noise(lacunarity^i p), clamped at filter_width",
            .inputs = {in("p", Type::vec3), in("octaves", Type::int_, 6.0f, "number of octaves, at most 16"),
                       in("lacunarity", Type::float_, 2.0f, "frequency ratio between octaves"),
                       in("gain", Type::float_, 0.5f, "amplitude ratio between octaves"),
                       in("filter_width", Type::float_, 0.0f, "sample footprint; 0 disables clamping")},
            .outputs = {out(Type::float_)}, .attributes = {seed_attribute()}, .tables = OpTables::noise};
  }
  template <class X>
  static void evaluate(const X& x) {
    x.out() = sem::fbm(x.tables(), x.in(0, 0), x.in(0, 1), x.in(0, 2), x.in(1), x.in(2), x.in(3), x.in(4));
  }
};

struct pnoise {
  static OpDef definition() {
    return {.name = "pnoise", .family = OpFamily::generator,
            .doc = "noise repeating every period along each axis, for tileable textures (OSL pnoise)",
            .inputs = {in("p", Type::vec3), period_input()}, .outputs = {out(Type::float_)},
            .attributes = {seed_attribute()}, .tables = OpTables::noise};
  }
  template <class X>
  static void evaluate(const X& x) {
    x.out() = sem::pnoise(x.tables(), x.in(0, 0), x.in(0, 1), x.in(0, 2), x.in(1, 0), x.in(1, 1), x.in(1, 2));
  }
};

struct pturbulence {
  static OpDef definition() {
    return {.name = "pturbulence", .family = OpFamily::generator,
            .doc = "turbulence repeating every period: octave i is pnoise(2^i p) with period 2^i period",
            .inputs = {in("p", Type::vec3), period_input(),
                       in("octaves", Type::int_, 6.0f, "number of octaves, at most 16"),
                       in("filter_width", Type::float_, 0.0f, "sample footprint; 0 disables clamping")},
            .outputs = {out(Type::float_)}, .attributes = {seed_attribute()}, .tables = OpTables::noise};
  }
  template <class X>
  static void evaluate(const X& x) {
    x.out() = sem::pturbulence(x.tables(), x.in(0, 0), x.in(0, 1), x.in(0, 2), x.in(1, 0), x.in(1, 1), x.in(1, 2),
                               x.in(2), x.in(3));
  }
};

struct pfbm {
  static OpDef definition() {
    return {.name = "pfbm", .family = OpFamily::generator,
            .doc = "fbm repeating every period; the lacunarity is rounded to a whole number, at least 2",
            .inputs = {in("p", Type::vec3), period_input(),
                       in("octaves", Type::int_, 6.0f, "number of octaves, at most 16"),
                       in("lacunarity", Type::float_, 2.0f, "frequency ratio between octaves (whole)"),
                       in("gain", Type::float_, 0.5f, "amplitude ratio between octaves"),
                       in("filter_width", Type::float_, 0.0f, "sample footprint; 0 disables clamping")},
            .outputs = {out(Type::float_)}, .attributes = {seed_attribute()}, .tables = OpTables::noise};
  }
  template <class X>
  static void evaluate(const X& x) {
    x.out() = sem::pfbm(x.tables(), x.in(0, 0), x.in(0, 1), x.in(0, 2), x.in(1, 0), x.in(1, 1), x.in(1, 2), x.in(2),
                        x.in(3), x.in(4), x.in(5));
  }
};

struct pnoise_improved {
  static OpDef definition() {
    return {.name = "pnoise_improved", .family = OpFamily::generator,
            .doc = "Perlin 2002 improved noise repeating every period along each axis; a period of 256 is "
                   "noise_improved",
            .inputs = {in("p", Type::vec3), period_input()}, .outputs = {out(Type::float_)}};
  }
  template <class X>
  static void evaluate(const X& x) {
    x.out() = sem::pnoise_improved(x.in(0, 0), x.in(0, 1), x.in(0, 2), x.in(1, 0), x.in(1, 1), x.in(1, 2));
  }
  static void evaluate_interval(const IntervalFrame& x) {
    // noise_improved's proven bound: the same gradients and weights.
    x.out() = lanes::lattice_range(x.in(0, 0), x.in(0, 1), x.in(0, 2), lanes::improved_noise_bound);
  }
};

struct noise4 {
  static OpDef definition() {
    return {.name = "noise4", .family = OpFamily::generator,
            .doc = "1989 gradient noise over 4D (p, w), |value| <= (sqrt(3)+1)/2, zero on the integer lattice: "
                   "with w = time a texture evolves instead of sliding",
            .inputs = {in("p", Type::vec3), w_input()}, .outputs = {out(Type::float_)},
            .attributes = {seed_attribute()}, .tables = OpTables::noise};
  }
  template <class X>
  static void evaluate(const X& x) {
    x.out() = sem::noise4(x.tables(), x.in(0, 0), x.in(0, 1), x.in(0, 2), x.in(1));
  }
};

struct turbulence4 {
  static OpDef definition() {
    return {.name = "turbulence4", .family = OpFamily::generator,
            .doc = "turbulence over 4D: sum of |noise4(2^i (p, w))| / 2^i; octaves stop where 2^-i <= "
                   "filter_width",
            .inputs = {in("p", Type::vec3), w_input(), in("octaves", Type::int_, 6.0f, "number of octaves, at most 16"),
                       in("filter_width", Type::float_, 0.0f, "sample footprint; 0 disables clamping")},
            .outputs = {out(Type::float_)}, .attributes = {seed_attribute()}, .tables = OpTables::noise};
  }
  template <class X>
  static void evaluate(const X& x) {
    x.out() = sem::turbulence4(x.tables(), x.in(0, 0), x.in(0, 1), x.in(0, 2), x.in(1), x.in(2), x.in(3));
  }
};

struct pnoise4 {
  static OpDef definition() {
    return {.name = "pnoise4", .family = OpFamily::generator,
            .doc = "noise4 repeating every period along x, y, z and every w_period along w: tileable textures "
                   "that loop in time",
            .inputs = {in("p", Type::vec3), w_input(), period_input(), w_period_input()},
            .outputs = {out(Type::float_)}, .attributes = {seed_attribute()}, .tables = OpTables::noise};
  }
  template <class X>
  static void evaluate(const X& x) {
    x.out() = sem::pnoise4(x.tables(), x.in(0, 0), x.in(0, 1), x.in(0, 2), x.in(1), x.in(2, 0), x.in(2, 1),
                           x.in(2, 2), x.in(3));
  }
};

struct pturbulence4 {
  static OpDef definition() {
    return {.name = "pturbulence4", .family = OpFamily::generator,
            .doc = "turbulence4 repeating every period and w_period: octave i is pnoise4(2^i (p, w)) with periods "
                   "2^i (period, w_period)",
            .inputs = {in("p", Type::vec3), w_input(), period_input(), w_period_input(),
                       in("octaves", Type::int_, 6.0f, "number of octaves, at most 16"),
                       in("filter_width", Type::float_, 0.0f, "sample footprint; 0 disables clamping")},
            .outputs = {out(Type::float_)}, .attributes = {seed_attribute()}, .tables = OpTables::noise};
  }
  template <class X>
  static void evaluate(const X& x) {
    x.out() = sem::pturbulence4(x.tables(), x.in(0, 0), x.in(0, 1), x.in(0, 2), x.in(1), x.in(2, 0), x.in(2, 1),
                                x.in(2, 2), x.in(3), x.in(4), x.in(5));
  }
};

struct sines {
  static OpDef definition() {
    return {.name = "sines", .family = OpFamily::generator,
            .doc = "Gardner 1984 sum of sines in [0,1] (cloudy skies): product of phase-shifted sine series in x "
                   "and y",
            .inputs = {in("p", Type::vec3), in("frequency", Type::float_, 1.0f, "base angular frequency"),
                       in("octaves", Type::int_, 5.0f, "terms per series, at most 16")},
            .outputs = {out(Type::float_)}};
  }
  template <class X>
  static void evaluate(const X& x) {
    x.out() = sem::sines(x.in(0, 0), x.in(0, 1), x.in(1), x.in(2));
  }
};

struct swave {
  static OpDef definition() {
    return {.name = "swave", .family = OpFamily::generator,
            .doc = "square wave in [0,1] box-filtered analytically over filter_width (Rhoades et al. 1992)",
            .inputs = {in("x", Type::float_),
                       in("filter_width", Type::float_, 0.0f, "box filter width in units of x"),
                       in("frequency", Type::float_, 1.0f, "periods per unit of x"),
                       in("duty", Type::float_, 0.5f, "fraction of each period that is 1"),
                       in("phase", Type::float_, 0.0f, "offset in periods")},
            .outputs = {out(Type::float_)}};
  }
  template <class X>
  static void evaluate(const X& x) {
    x.out() = sem::swave(x.in(0), x.in(1), x.in(2), x.in(3), x.in(4));
  }
};

struct julia {
  static OpDef definition() {
    return {.name = "julia", .family = OpFamily::generator,
            .doc = "Julia set z -> z^2 + c: fraction of iterations before escape, 1 inside the set",
            .inputs = {in("p", Type::vec2, "starting point z0"), in("c", Type::vec2, "the constant c"),
                       in("iterations", Type::int_, 64.0f, "iteration limit, at most 1024")},
            .outputs = {out(Type::float_)}};
  }
  template <class X>
  static void evaluate(const X& x) {
    x.out() = sem::julia(x.in(0, 0), x.in(0, 1), x.in(1, 0), x.in(1, 1), x.in(2));
  }
};

struct checker {
  static OpDef definition() {
    return {.name = "checker", .family = OpFamily::generator,
            .doc = "3D checkerboard: 1 where floor(x)+floor(y)+floor(z) is odd", .inputs = {in("p", Type::vec3)},
            .outputs = {out(Type::float_)}};
  }
  template <class X>
  static void evaluate(const X& x) {
    x.out() = sem::checker(x.in(0, 0), x.in(0, 1), x.in(0, 2));
  }
};

struct cellular {
  static OpDef definition() {
    return {.name = "cellular", .family = OpFamily::generator,
            .doc = "Worley 1996 cellular noise: distances (F1, F2) to the nearest and second-nearest feature "
                   "points, one per unit cell",
            .inputs = {in("p", Type::vec3),
                       in("jitter", Type::float_, 1.0f, "0: points at cell centres, 1: anywhere in their cell")},
            .outputs = {out(Type::vec2)}, .attributes = {seed_attribute()}, .tables = OpTables::noise};
  }
  template <class X>
  static void evaluate(const X& x) {
    const auto distances = sem::cellular(x.tables(), x.in(0, 0), x.in(0, 1), x.in(0, 2), x.in(1));
    x.out(0) = distances.nearest;
    x.out(1) = distances.second;
  }
};

struct pcellular {
  static OpDef definition() {
    return {.name = "pcellular", .family = OpFamily::generator,
            .doc = "cellular noise repeating every period: the feature points of cell c are those of c mod period",
            .inputs = {in("p", Type::vec3), period_input(),
                       in("jitter", Type::float_, 1.0f, "0: points at cell centres, 1: anywhere in their cell")},
            .outputs = {out(Type::vec2)}, .attributes = {seed_attribute()}, .tables = OpTables::noise};
  }
  template <class X>
  static void evaluate(const X& x) {
    const auto distances =
        sem::pcellular(x.tables(), x.in(0, 0), x.in(0, 1), x.in(0, 2), x.in(1, 0), x.in(1, 1), x.in(1, 2), x.in(2));
    x.out(0) = distances.nearest;
    x.out(1) = distances.second;
  }
};

}  // namespace shadetree::ops

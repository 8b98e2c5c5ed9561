// The colour splines of graphs/turbulence.json and graphs/marble.json as
// the SIMD yardsticks hold them: component by component, knot k in lane k,
// so that one register holds a component's 8 knots (padded to 16 floats
// for a 512-bit load).
#pragma once

namespace shadetree::yardstick {

struct SplineKnots {
  float component[3][16];
};

inline constexpr SplineKnots turbulence_knots = {{{0.02f, 0.02f, 0.08f, 0.1f, 0.35f, 0.8f, 1.0f, 1.0f},
                                                  {0.02f, 0.02f, 0.12f, 0.4f, 0.72f, 0.93f, 1.0f, 1.0f},
                                                  {0.08f, 0.08f, 0.35f, 0.65f, 0.82f, 0.95f, 1.0f, 1.0f}}};

inline constexpr SplineKnots marble_knots = {{{0.95f, 0.95f, 0.8f, 0.62f, 0.4f, 0.2f, 0.1f, 0.1f},
                                              {0.93f, 0.93f, 0.78f, 0.6f, 0.38f, 0.18f, 0.08f, 0.08f},
                                              {0.9f, 0.9f, 0.76f, 0.6f, 0.42f, 0.24f, 0.12f, 0.12f}}};

}  // namespace shadetree::yardstick

// Derivatives with respect to P. Neither op has a lane form: lowering
// differentiates the graph that computes its input (ir/differentiate.h),
// so the derivative of every op comes from that op's own semantics,
// evaluated over dual numbers.
#pragma once

#include "nodes/op_definition.h"

namespace shadetree::ops {

using namespace define;

struct gradient {
  static OpDef definition() {
    return {.name = "gradient", .family = OpFamily::derivative,
            .doc = "exact gradient of x with respect to P (forward-mode derivatives through every op)",
            .inputs = {in("x", Type::float_)}, .outputs = {out(Type::vec3)}};
  }
};

// Blinn 1978: a surface displaced along its normal by a height h has the
// normal N - grad_s h, where grad_s h = grad h - (grad h . N) N is the
// gradient's part along the surface. Perlin 1985's bumpy donut adds
// Dnoise to N the same way.
struct bump {
  static OpDef definition() {
    return {.name = "bump", .family = OpFamily::derivative,
            .doc = "normal perturbed by a height field (Blinn 1978): normalize(N - strength (grad h - (grad h . N) "
                   "N))",
            .inputs = {in("height", Type::float_, "height above the surface, in the units of P"),
                       in("normal", Type::vec3, "the unperturbed normal, usually N"),
                       in("strength", Type::float_, 1.0f, "scale of the height")},
            .outputs = {out(Type::vec3)}};
  }
};

}  // namespace shadetree::ops

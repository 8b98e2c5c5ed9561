// Comparisons, logic and the two conditionals. Bools are stored as 0 / 1.
// Each op: its definition and its semantics over a frame (see
// nodes/op_frame.h).
#pragma once

#include "nodes/op_definition.h"
#include "nodes/op_frame.h"
#include "nodes/semantics/arithmetic.h"

namespace shadetree::ops {

using namespace define;
namespace sem = semantics;

// A comparison: sem::function(a, b) stored as 0 / 1.
#define SHADETREE_COMPARISON_OP(name, function, doc)                                  \
  struct name {                                                                       \
    static OpDef definition() { return comparison(#name, doc); }                      \
    template <class X>                                                                \
    static void evaluate(const X& x) {                                                \
      x.out() = frame::stored<LaneOf<X>>(sem::function(x.in(0), x.in(1)));            \
    }                                                                                 \
  };

SHADETREE_COMPARISON_OP(lt, less, "a < b")
SHADETREE_COMPARISON_OP(le, less_equal, "a <= b")
SHADETREE_COMPARISON_OP(gt, greater, "a > b")
SHADETREE_COMPARISON_OP(ge, greater_equal, "a >= b")
SHADETREE_COMPARISON_OP(eq, equal, "a == b")
SHADETREE_COMPARISON_OP(ne, not_equal, "a != b")

inline OpDef logic(std::string name, std::string doc, int arity) {
  std::vector<PortSpec> inputs = {in("a", Type::bool_)};
  if (arity == 2) inputs.push_back(in("b", Type::bool_));
  return {.name = std::move(name), .family = OpFamily::conditional, .doc = std::move(doc), .inputs = inputs,
          .outputs = {out(Type::bool_)}};
}

struct and_ {
  static OpDef definition() { return logic("and", "a and b", 2); }
  template <class X>
  static void evaluate(const X& x) {
    x.out() = frame::stored<LaneOf<X>>(lanes::both(frame::loaded(x.in(0)), frame::loaded(x.in(1))));
  }
};

struct or_ {
  static OpDef definition() { return logic("or", "a or b", 2); }
  template <class X>
  static void evaluate(const X& x) {
    x.out() = frame::stored<LaneOf<X>>(lanes::either(frame::loaded(x.in(0)), frame::loaded(x.in(1))));
  }
};

struct not_ {
  static OpDef definition() { return logic("not", "not a", 1); }
  template <class X>
  static void evaluate(const X& x) {
    x.out() = frame::stored<LaneOf<X>>(lanes::negate(frame::loaded(x.in(0))));
  }
};

// then where cond holds, else otherwise, per component.
struct choose {
  template <class X>
  static void evaluate(const X& x) {
    const auto condition = frame::loaded(x.in(0));
    frame::for_components(x.components(), [&](int c) { x.out(c) = lanes::select(condition, x.in(1, c), x.in(2, c)); });
  }
};

inline OpDef conditional(std::string name, std::string doc) {
  return {.name = std::move(name), .family = OpFamily::conditional, .doc = std::move(doc),
          .generic = GenericSet::numeric, .inputs = {in("cond", Type::bool_), generic_in("then"), generic_in("else")},
          .outputs = {generic_out()}};
}

struct select : choose {
  static OpDef definition() {
    return conditional("select", "then where cond holds, else otherwise (both evaluated)");
  }
};

// The branches are placed in conditional regions (ir/passes/
// place_conditional_regions.cpp), so each runs only where it is taken.
struct if_ : choose {
  static OpDef definition() {
    return conditional("if", "then where cond holds, else otherwise; each branch runs only for the samples that take it");
  }
};

}  // namespace shadetree::ops

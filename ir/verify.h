// The ShadeIR verifier: the invariants every pass may assume and must keep.
//   - operands precede their users, and every index is in range;
//   - each op has its signature's argument count, arguments whose types
//     convert to the declared ones, and the declared result type;
//   - constants, params and globals read data, slots and globals that exist;
//   - uniform instructions read only uniform values;
//   - regions are well nested, each begin_region names its end_region, and
//     they hold only varying code;
//   - outputs name existing values, in contract order, with contract types.
// It runs after every pass in debug builds and in the tests (see
// ir/optimize.h: PassObserver).
#pragma once

#include <string>

#include "ir/shade_ir.h"

namespace shadetree {

// The first broken invariant, or "" for a well-formed program.
std::string verify_shade_ir(const ShadeIR& ir);

}  // namespace shadetree

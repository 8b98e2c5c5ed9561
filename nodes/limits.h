// Limits the type checker enforces and the semantics rely on (documented
// in docs/graph-format.md).
#pragma once

namespace shadetree {

inline constexpr int max_octaves = 16;
inline constexpr int max_julia_iterations = 1024;
inline constexpr int max_table_entries = 4096;
// Pixels of an image the `image` op samples: its pixels are compiled into
// the kernel as constant data (12 bytes a pixel), so 1024 x 1024 at most.
inline constexpr int max_image_pixels = 1024 * 1024;
// Arguments of one op (its inputs), the width of the op ABI (op_frame.h).
inline constexpr int max_op_args = 6;
// What an interval program keeps of each value (nodes/interval_frame.h):
// an interval per component, then a bound on its length where it is a
// vector. The length knows what the components' box forgets: d / |d| has
// length 1 wherever its box holds short vectors, and x - k d / |d| is
// within k of |x|.
inline constexpr int interval_planes_per_value = 4;

}  // namespace shadetree

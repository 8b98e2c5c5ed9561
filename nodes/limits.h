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

}  // namespace shadetree

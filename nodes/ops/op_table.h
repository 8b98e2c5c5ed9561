// A table of one entry per op, generated from the op list in its order
// (nodes/op_id.h): `input_entry` for the input ops, EntryOf<ops::name>::value
// for each library op. The interpreter's lane, interval and dual dispatches
// and the GLSL tracer's are such tables.
#pragma once

#include <array>

#include "nodes/op_id.h"
#include "nodes/ops/all.h"

namespace shadetree {

template <template <class> class EntryOf, class Entry>
constexpr std::array<Entry, op_count> op_table(Entry input_entry) {
  return {{
#define SHADETREE_INPUT_ENTRY(name, type, variability, kinds, doc) input_entry,
      SHADETREE_GLOBALS(SHADETREE_INPUT_ENTRY)
#undef SHADETREE_INPUT_ENTRY
#define SHADETREE_OP_ENTRY(name) EntryOf<ops::name>::value,
          SHADETREE_LIBRARY_OPS(SHADETREE_OP_ENTRY)
#undef SHADETREE_OP_ENTRY
  }};
}

}  // namespace shadetree

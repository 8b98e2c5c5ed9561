#include "platform/process_heap.h"

#include <malloc.h>

namespace shadetree {

namespace {

// Past this much free memory at its top, an arena gives some back.
constexpr int kept_free_bytes = 1 << 30;
// Blocks of this size or more are mapped apart (glibc's largest setting).
constexpr int mapped_block_bytes = 32 << 20;

}  // namespace

void keep_freed_memory_in_the_process() {
  mallopt(M_TRIM_THRESHOLD, kept_free_bytes);
  mallopt(M_MMAP_THRESHOLD, mapped_block_bytes);
}

}  // namespace shadetree

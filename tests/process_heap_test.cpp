// The executable's heap policy (platform/process_heap.h): a block under
// 32 MiB comes from the heap, and once freed it stays there for the next
// allocation instead of going back to the system.
#include "platform/process_heap.h"

#include <gtest/gtest.h>
#include <malloc.h>

#include <cstdlib>
#include <cstring>

namespace shadetree {
namespace {

TEST(ProcessHeap, AFreedBlockStaysInTheProcess) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer's allocator replaces glibc's, whose policy this is";
#endif
  keep_freed_memory_in_the_process();
  // Past glibc's default mmap threshold (128 KiB, 32 MiB at most as it
  // adapts) and its default trim threshold (128 KiB).
  constexpr std::size_t block = 8u << 20;
  const struct mallinfo2 before = mallinfo2();
  char* memory = static_cast<char*>(std::malloc(block));
  ASSERT_NE(memory, nullptr);
  std::memset(memory, 1, block);
  asm volatile("" : : "r"(memory) : "memory");  // the block is used, so it is really allocated
  const struct mallinfo2 held = mallinfo2();
  EXPECT_EQ(held.hblkhd, before.hblkhd) << "the block was mapped apart";
  std::free(memory);
  const struct mallinfo2 after = mallinfo2();
  EXPECT_GE(after.fordblks, block) << "the freed block went back to the system";
  EXPECT_GE(after.arena, held.arena) << "the heap shrank";
}

}  // namespace
}  // namespace shadetree

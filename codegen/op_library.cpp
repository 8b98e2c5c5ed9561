#include "codegen/op_library.h"

#include <llvm/Bitcode/BitcodeReader.h>
#include <llvm/IR/Module.h>
#include <llvm/Support/Error.h>
#include <llvm/Support/MemoryBuffer.h>
#include <llvm/Support/xxhash.h>

extern const unsigned char shadetree_ops_bitcode_w4[];
extern const unsigned long shadetree_ops_bitcode_w4_size;
extern const unsigned char shadetree_ops_bitcode_w8[];
extern const unsigned long shadetree_ops_bitcode_w8_size;
extern const unsigned char shadetree_ops_bitcode_w16[];
extern const unsigned long shadetree_ops_bitcode_w16_size;

namespace shadetree {

namespace {
llvm::StringRef as_text(const unsigned char* bytes, unsigned long size) {
  return llvm::StringRef(reinterpret_cast<const char*>(bytes), size);
}

// The library of `width`; empty for any other width.
llvm::StringRef bitcode(int width) {
  switch (width) {
    case 4: return as_text(shadetree_ops_bitcode_w4, shadetree_ops_bitcode_w4_size);
    case 8: return as_text(shadetree_ops_bitcode_w8, shadetree_ops_bitcode_w8_size);
    case 16: return as_text(shadetree_ops_bitcode_w16, shadetree_ops_bitcode_w16_size);
    default: return {};
  }
}
}  // namespace

std::uint64_t op_library_hash() {
  static const std::uint64_t hash = [] {
    std::uint64_t combined = 0;
    for (int width : {4, 8, 16}) combined = llvm::xxh3_64bits(bitcode(width)) ^ (combined * 0x9e3779b97f4a7c15ull);
    return combined;
  }();
  return hash;
}

std::unique_ptr<llvm::Module> load_op_library(llvm::LLVMContext& context, int width) {
  const llvm::StringRef library = bitcode(width);
  if (library.empty()) return nullptr;
  auto module = llvm::getLazyBitcodeModule(llvm::MemoryBufferRef(library, "shadetree_ops"), context);
  if (!module) {
    llvm::consumeError(module.takeError());
    return nullptr;
  }
  return std::move(*module);
}

}  // namespace shadetree

#include "codegen/op_library.h"

#include <llvm/Bitcode/BitcodeReader.h>
#include <llvm/IR/Module.h>
#include <llvm/Support/Error.h>
#include <llvm/Support/MemoryBuffer.h>
#include <llvm/Support/xxhash.h>

extern const unsigned char shadetree_ops_bitcode[];
extern const unsigned long shadetree_ops_bitcode_size;

namespace shadetree {

namespace {
llvm::StringRef bitcode() {
  return llvm::StringRef(reinterpret_cast<const char*>(shadetree_ops_bitcode), shadetree_ops_bitcode_size);
}
}  // namespace

std::uint64_t op_library_hash() {
  static const std::uint64_t hash = llvm::xxh3_64bits(bitcode());
  return hash;
}

std::unique_ptr<llvm::Module> load_op_library(llvm::LLVMContext& context) {
  llvm::MemoryBufferRef buffer(bitcode(), "shadetree_ops");
  auto module = llvm::getLazyBitcodeModule(buffer, context);
  if (!module) {
    llvm::consumeError(module.takeError());
    return nullptr;
  }
  return std::move(*module);
}

}  // namespace shadetree

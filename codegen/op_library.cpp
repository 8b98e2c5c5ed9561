#include "codegen/op_library.h"

#include <map>
#include <mutex>
#include <utility>

#include <llvm/Bitcode/BitcodeReader.h>
#include <llvm/IR/LLVMContext.h>
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

std::string op_library_symbol(OpId op, bool dual, int width) {
  return std::string("st_") + op_symbol(op) + (dual ? "_dual" : "") + "_w" + std::to_string(width);
}

unsigned op_library_instructions(const std::string& symbol, int width) {
  static std::mutex mutex;
  static std::map<std::pair<std::string, int>, unsigned> sizes;
  static llvm::LLVMContext* context = new llvm::LLVMContext;  // never destroyed, like the JIT
  static auto* libraries = new std::map<int, std::unique_ptr<llvm::Module>>;
  std::lock_guard lock(mutex);
  const auto key = std::make_pair(symbol, width);
  if (auto found = sizes.find(key); found != sizes.end()) return found->second;
  std::unique_ptr<llvm::Module>& library = (*libraries)[width];
  if (!library) library = load_op_library(*context, width);
  llvm::Function* function = library ? library->getFunction(symbol) : nullptr;
  unsigned size = 0;
  if (function && !function->isDeclaration()) {
    if (llvm::Error error = function->materialize())
      llvm::consumeError(std::move(error));
    else
      size = function->getInstructionCount();
  }
  return sizes[key] = size;
}

}  // namespace shadetree

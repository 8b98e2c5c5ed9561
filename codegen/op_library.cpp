#include "codegen/op_library.h"

#include <llvm/Bitcode/BitcodeReader.h>
#include <llvm/IR/Module.h>
#include <llvm/Support/Error.h>
#include <llvm/Support/MemoryBuffer.h>

extern const unsigned char shadetree_ops_bitcode[];
extern const unsigned long shadetree_ops_bitcode_size;

namespace shadetree {

std::unique_ptr<llvm::Module> load_op_library(llvm::LLVMContext& context) {
  llvm::MemoryBufferRef buffer(
      llvm::StringRef(reinterpret_cast<const char*>(shadetree_ops_bitcode), shadetree_ops_bitcode_size),
      "shadetree_ops");
  auto module = llvm::parseBitcodeFile(buffer, context);
  if (!module) {
    llvm::consumeError(module.takeError());
    return nullptr;
  }
  return std::move(*module);
}

}  // namespace shadetree

// The JIT's op library: the bitcode of codegen/ops_bitcode.cpp, embedded in
// the binary at build time.
#pragma once

#include <cstdint>
#include <memory>

namespace llvm {
class LLVMContext;
class Module;
}  // namespace llvm

namespace shadetree {

// A fresh copy of the library in `context`; null if the embedded bitcode is
// unreadable (a build fault).
std::unique_ptr<llvm::Module> load_op_library(llvm::LLVMContext& context);

// A hash of the library's bitcode: part of every kernel cache key, so that
// a rebuilt shadetree never loads kernels made from older semantics.
std::uint64_t op_library_hash();

}  // namespace shadetree

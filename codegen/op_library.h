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

// A fresh copy of the library of vector width `width` (4, 8 or 16) in
// `context`, loaded lazily: a function's body is read when it is
// materialized (a kernel calls a few of the library's hundreds of
// functions, and reading them all took 10 ms of every compile). Null for
// another width, or if the embedded bitcode is unreadable (a build fault).
std::unique_ptr<llvm::Module> load_op_library(llvm::LLVMContext& context, int width);

// A hash of the libraries' bitcode: part of every kernel cache key, so
// that a rebuilt shadetree never loads kernels made from older semantics.
std::uint64_t op_library_hash();

}  // namespace shadetree

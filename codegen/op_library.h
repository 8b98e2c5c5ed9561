// The JIT's op library: the bitcode of codegen/ops_bitcode.cpp, embedded in
// the binary at build time.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "nodes/op_id.h"

namespace llvm {
class Function;
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

// The library loaded in `module` made to be inlined into the code emitted
// there: its functions and constant tables internal (a weak definition
// shared by name would tie a kernel to the copy of the first kernel that
// defined it, which may be released before it) and always inlined.
void make_library_inlined(llvm::Module& module);

// Reads the bodies of the library functions the emitted code calls, and of
// those they call: a lazily loaded function has uses only from bodies
// read. False if the bitcode is unreadable.
bool materialize_called(llvm::Module& module);

// Drops the library functions that neither `entry_points` nor what they
// call use (other ops, dual forms) before the optimizer spends time on
// them, and reads the rest. False if the bitcode is unreadable.
bool drop_uncalled(llvm::Module& module, const std::vector<llvm::Function*>& entry_points);

// The library function of `op` at `width`, over duals if `dual`:
// st_<op>_w<W> or st_<op>_dual_w<W> (codegen/ops_bitcode.cpp).
std::string op_library_symbol(OpId op, bool dual, int width);

// The instructions of the library function `symbol` (0 if there is none)
// that depend on the inputs in the mask `unknown_inputs` (bit i: input i
// is not a constant), counted once per process and mask: what inlining
// the op costs a kernel, known before the kernel is emitted. The rest
// work on constants only and fold away (gain's exponent from its g).
unsigned op_library_instructions(const std::string& symbol, int width, unsigned unknown_inputs);

// A hash of the libraries' bitcode: part of every kernel cache key, so
// that a rebuilt shadetree never loads kernels made from older semantics.
std::uint64_t op_library_hash();

}  // namespace shadetree

// x86 lowerings of the op library's table lookups, apart from the generic
// emitter as Halide keeps CodeGen_X86 beside CodeGen_LLVM: AVX-512
// permutes over a 256-entry table held in registers, which beat hardware
// gathers on the x86 parts measured (docs/architecture.md). Each takes 16
// indices and returns the 16 looked-up values; the caller has checked
// that the target has AVX-512 (and VBMI for the byte permutes).
#pragma once

#include <utility>

namespace llvm {
class IRBuilderBase;
class Module;
class Value;
}  // namespace llvm

namespace shadetree {

// vpermt2ps/vpermt2d pick within each 32-entry pair of the table's sixteen
// registers by the index's low 5 bits, then three rounds of selects on
// bits 5, 6 and 7 pick the pair.
llvm::Value* x86_register_table_lookup(llvm::IRBuilderBase& builder, llvm::Module& module, bool is_float,
                                       llvm::Value* table, llvm::Value* index);

// An int table whose values fit in a byte (the noise permutation), as 256
// bytes in four registers (AVX-512 VBMI): two vpermi2b on the index's low
// 7 bits, a select on bit 7.
llvm::Value* x86_byte_table_lookup(llvm::IRBuilderBase& builder, llvm::Module& module, llvm::Value* table,
                                   llvm::Value* index);

// The same table's entries at index and at index + 1 mod 256 (a pair of
// noise lattice cells), both from the one byte permute: 32 of its 64 byte
// lanes.
std::pair<llvm::Value*, llvm::Value*> x86_byte_table_pair_lookup(llvm::IRBuilderBase& builder, llvm::Module& module,
                                                                   llvm::Value* table, llvm::Value* index);

// A float table of `size` <= x86_small_table_entries entries (a spline's
// knots) in two registers, loaded under a mask so that nothing past its
// end is read: one vpermt2ps on the index's low 5 bits.
inline constexpr int x86_small_table_entries = 32;
llvm::Value* x86_small_table_lookup(llvm::IRBuilderBase& builder, llvm::Module& module, llvm::Value* table,
                                    llvm::Value* size, llvm::Value* index);

}  // namespace shadetree

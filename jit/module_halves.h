// A large kernel module's machine code generated on two threads.
//
// After the middle end, two thirds of a large kernel's cold compile is the
// back end (instruction selection, its DAG combiner most, and register
// allocation), and LLVM runs it on one thread. Most of a large kernel is
// one basic block: the body of its sample loop, or of a turbulence's octave
// loop. So the first half of that block, cut where the fewest of its values
// are used after the cut, becomes a function of its own (LLVM's
// CodeExtractor: the values it reads come in as arguments, those it leaves
// go out through pointers), and moves to a second module, which another
// thread compiles in an LLVM context of its own. The block calls the half;
// the two objects link in the JIT under the kernel's resource tracker.
// The instructions are the same, so the values are the same to the bit.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <llvm/ADT/SmallVector.h>
#include <llvm/ADT/StringRef.h>

#include "graph/diagnostic.h"

namespace llvm {
class LLVMContext;
class Module;
}  // namespace llvm

namespace shadetree {

// Blocks shorter than this compile whole: the half's call, its arguments
// and results through memory, and the second module's start cost more than
// a thread saves (the largest blocks of noise, turbulence and marble are
// under it).
constexpr unsigned min_block_to_halve = 900;

// Cuts the largest block of `module` in two if it is long enough and moves
// its first half to a function named `half_name`, which `module` then only
// declares. Returns the bitcode the half's module is made from
// (half_module), or nothing when `module` stays whole.
std::optional<llvm::SmallVector<char, 0>> split_off_half(llvm::Module& module, const std::string& half_name);

// The module that defines `half_name` (and what it calls), read into
// `context` from split_off_half's bitcode.
Result<std::unique_ptr<llvm::Module>> half_module(llvm::StringRef bitcode, const std::string& half_name,
                                                  llvm::LLVMContext& context);

}  // namespace shadetree

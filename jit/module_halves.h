// A large kernel module's machine code generated on two threads.
//
// After the middle end, two thirds of a large kernel's cold compile is the
// back end (instruction selection, its DAG combiner most, and register
// allocation), and LLVM runs it on one thread. So the instructions of
// about half a large module's code generation (a shuffle counting twice)
// become a function of their own (LLVM's
// CodeExtractor: the values they read come in as arguments, those they
// leave go out through pointers), which moves to a second module that
// another thread compiles in an LLVM context of its own. That half is a
// stretch of the sample loop that every sample runs through (its octave
// loops and conditional regions with it), called once per vector of
// samples; or, where one block is most of the kernel (the octave loop of
// a 4D turbulence), the first part of that block, cut where the fewest of
// its values are read after the cut. The two objects link in the JIT
// under the kernel's resource tracker. The instructions are the same, so
// the values are the same to the bit.
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

// Modules of fewer instructions than this compile whole: the half's call,
// its arguments and results through memory, and the second module's start
// cost more than a thread saves (noise, turbulence and marble are under
// it).
constexpr unsigned min_instructions_to_halve = 1300;
// A block shorter than this is never cut.
constexpr unsigned min_block_to_halve = 900;

// Moves about half of `module`, if it is large enough, to a function named
// `half_name`, which `module` then only declares. Returns the bitcode the
// half's module is made from (half_module), or nothing when `module` stays
// whole.
std::optional<llvm::SmallVector<char, 0>> split_off_half(llvm::Module& module, const std::string& half_name);

// The module that defines `half_name` (and what it calls), read into
// `context` from split_off_half's bitcode.
Result<std::unique_ptr<llvm::Module>> half_module(llvm::StringRef bitcode, const std::string& half_name,
                                                  llvm::LLVMContext& context);

}  // namespace shadetree

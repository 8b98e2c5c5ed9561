// The op library's functions inlined into the kernel.
//
// Every function of the op library is always_inline: a kernel is their
// bodies inlined into its sample loop, and each op's body with the
// helpers it calls (table lookups, splines' knots). LLVM's
// AlwaysInlinerPass computes the block frequencies of the caller and of
// the callee for every call it inlines, to scale profile counts, and then
// drops the caller's, so that the next call computes them again over the
// grown kernel: its time grew with calls times the kernel's size, and it
// inlined helpers into library functions that were then deleted. A
// kernel has no profile, so here each call is inlined with nothing to
// keep up to date, and only into the functions that stay.
#pragma once

namespace llvm {
class Module;
}

namespace shadetree {

// Inlines every call to an always_inline function with a body, in the
// functions that are not always_inline, until none is left (a callee's
// own calls are inlined where its body lands), then erases the
// always_inline functions of local linkage that nothing uses any more.
void inline_library_calls(llvm::Module& module);

}  // namespace shadetree

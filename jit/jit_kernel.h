// The JIT backend behind the Kernel interface.
#pragma once

#include <memory>

#include "ir/kernel.h"
#include "jit/jit_compiler.h"

namespace shadetree {

// Compiles `ir` (or finds it in the caches) at `width` lanes (0: host).
Result<std::unique_ptr<Kernel>> make_jit_kernel(ShadeIR ir, int width = 0, const JitSettings& settings = {});

// The kernel of `compiled`, which compile_kernel made from `ir`.
std::unique_ptr<Kernel> make_jit_kernel(ShadeIR ir, const CompiledKernel& compiled);

}  // namespace shadetree

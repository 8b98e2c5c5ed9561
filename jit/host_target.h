// What the host CPU offers the JIT: its vector width, the table lookups
// it is best at, and its name and features (part of every cached kernel's
// key, since the machine code is made for them).
#pragma once

#include <string>

#include "codegen/emit_kernel.h"

namespace shadetree {

// 16 with AVX-512, 8 with AVX2, else 4.
int host_vector_width();

// The table lookup strategy used when JitSettings::gathers is empty.
GatherStrategy host_gather_strategy();

// Whether the host has an LLVM-named feature ("avx512vbmi").
bool host_has(const char* feature);

// The host CPU as LLVM names it, and its features as one string.
std::string host_cpu_name();
std::string host_features();

}  // namespace shadetree

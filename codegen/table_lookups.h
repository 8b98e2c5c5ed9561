// The op library's table lookups (st_gather_<type>_w<W> and, for
// 256-entry tables, st_gather256_<type>_w<W>) are declared in its bitcode
// and defined here, for each kernel, by the strategy the host is best at:
// the generic ones (a hardware gather, one load per lane) in
// table_lookups.cpp, x86's register permutes in x86_table_lookups.cpp.
#pragma once

#include "codegen/emit_kernel.h"

namespace llvm {
class Module;
}

namespace shadetree {

void define_table_lookups(llvm::Module& module, GatherStrategy strategy);

}  // namespace shadetree

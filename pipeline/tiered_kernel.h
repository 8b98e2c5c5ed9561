// Tiered execution: a kernel that runs on the interpreter while the JIT
// compiles it in the background, and on the JIT from the first run after
// the compile is done. The backends agree to the bit (the differential
// tests check it), so an image rendered partly by each is the image either
// would render alone. A graph that takes seconds to compile starts
// rendering at once; one that is in the kernel cache switches at once.
#pragma once

#include <memory>

#include "ir/kernel.h"
#include "jit/jit_compiler.h"

namespace shadetree {

// What the tiered kernel did, for the render summary.
struct TieredReport {
  bool jit_ready = false;
  bool jit_failed = false;           // the program ran on the interpreter throughout
  double jit_ready_milliseconds = 0;  // from make_tiered_kernel to the compile's end
  long interpreted_runs = 0, compiled_runs = 0;
};

class TieredKernel : public Kernel {
 public:
  using Kernel::Kernel;
  virtual TieredReport report() const = 0;
};

// Starts compiling `ir` at `width` (0: host) on a thread of its own.
std::unique_ptr<TieredKernel> make_tiered_kernel(ShadeIR ir, int width = 0, const JitSettings& settings = {});

}  // namespace shadetree

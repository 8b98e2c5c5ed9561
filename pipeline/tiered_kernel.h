// Tiered execution: a kernel that runs on the interpreter while the JIT
// compiles it in the background, and on the JIT from the first run after
// the compile is done. The backends agree to the bit (the differential
// tests check it), so an image rendered partly by each is the image either
// would render alone. A graph that takes seconds to compile starts
// rendering at once; one that is in the kernel cache switches at once.
//
// With quick_first (the editor's previews), a quick kernel is compiled
// first (JitSettings::optimization) and runs until the full one is ready,
// which is compiled next at a lower thread priority, so that it takes what
// CPU the preview leaves rather than slowing it down.
#pragma once

#include <memory>
#include <string>

#include "ir/kernel.h"
#include "jit/jit_compiler.h"

namespace shadetree {

// What the tiered kernel did, for the render summary.
struct TieredReport {
  bool jit_ready = false;             // the full kernel: compiled, or failed to
  bool jit_failed = false;            // the program ran on the interpreter (or the quick kernel) throughout
  std::string jit_error;              // and why the JIT failed
  double jit_ready_milliseconds = 0;  // from make_tiered_kernel to the full compile's end
  double quick_ready_milliseconds = 0;  // and to the quick one's (0: none)
  long interpreted_runs = 0, quick_runs = 0, compiled_runs = 0;
};

class TieredKernel : public Kernel {
 public:
  using Kernel::Kernel;
  virtual TieredReport report() const = 0;
};

// Starts compiling `ir` at `width` (0: host) on a thread of its own; with
// `quick_first`, a quick kernel before the full one, unless the full one
// is cached.
std::unique_ptr<TieredKernel> make_tiered_kernel(ShadeIR ir, int width = 0, const JitSettings& settings = {},
                                                 bool quick_first = false);

}  // namespace shadetree

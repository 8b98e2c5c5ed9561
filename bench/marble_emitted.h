// graphs/marble.json as the C++ that `shadetree emit --cpp` writes, built
// by g++ and by clang++ (-O2 -march=native), to compare with the JIT and
// the yardsticks.
#pragma once

#include "bench/plane_kernel.h"

namespace shadetree::emitted {

PlaneKernel marble_gcc, marble_clang;

}  // namespace shadetree::emitted

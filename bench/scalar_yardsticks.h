// The hand-written scalar yardsticks: bench/graphs/noise.json,
// graphs/turbulence.json and graphs/marble.json at their default params as
// plain C++ loops, to measure the JIT against. CMakeLists.txt builds
// bench/scalar_yardsticks.cpp once per compiler (-O3 -march=native), each
// build into its own namespace.
#pragma once

#include "bench/plane_kernel.h"

namespace shadetree::yardstick {

namespace gcc {
PlaneKernel noise, turbulence, marble;
}

namespace clang {
PlaneKernel noise, turbulence, marble;
}

}  // namespace shadetree::yardstick

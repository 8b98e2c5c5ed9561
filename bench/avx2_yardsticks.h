// The hand-written AVX2 yardsticks: the kernels of
// bench/scalar_yardsticks.h in intrinsics (AVX2 and FMA), 8 samples at a
// time, as on hosts without AVX-512. They compile on any x86-64 host;
// call them only where host_has_avx2().
#pragma once

#include "bench/plane_kernel.h"

namespace shadetree::yardstick {

bool host_has_avx2();

// vpgatherdd / vgatherdps from the tables in memory: six gathers a knot
// row.
namespace avx2_gathers {
extern PlaneKernel* const noise;
extern PlaneKernel* const turbulence;
extern PlaneKernel* const marble;
}

// A knot row's gradients from the interleaved table: two 16-byte loads a
// lane and a transpose in registers; the permutation by gathers.
namespace avx2_interleaved {
extern PlaneKernel* const noise;
extern PlaneKernel* const turbulence;
extern PlaneKernel* const marble;
}

}  // namespace shadetree::yardstick

// The hand-written AVX-512 yardsticks: the kernels of
// bench/scalar_yardsticks.h in intrinsics, 16 samples at a time, with the
// noise tables read by hardware gathers or held in registers. They compile
// on any x86-64 host; call them only where host_has_avx512().
#pragma once

#include "bench/plane_kernel.h"

namespace shadetree::yardstick {

bool host_has_avx512();

// vpgatherdd / vgatherdps from the tables in memory.
namespace avx512_gathers {
extern PlaneKernel* const noise;
extern PlaneKernel* const turbulence;
extern PlaneKernel* const marble;
}

// Each 256-entry table in sixteen zmm registers: vpermt2ps picks by an
// index's low 5 bits within each pair of registers, blends on bits 5, 6
// and 7 pick the pair.
namespace avx512_in_register {
extern PlaneKernel* const noise;
extern PlaneKernel* const turbulence;
extern PlaneKernel* const marble;
}

}  // namespace shadetree::yardstick

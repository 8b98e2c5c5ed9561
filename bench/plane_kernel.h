// The signature of the texture kernels written outside the JIT (the
// hand-written yardsticks, the emitted C++): P and filter_width planes in,
// colour planes out, `count` samples, the graph's params at their defaults.
#pragma once

#include <cstddef>

namespace shadetree {

using PlaneKernel = void(const float* x, const float* y, const float* z, const float* filter_width, float* red,
                         float* green, float* blue, std::size_t count);

}  // namespace shadetree

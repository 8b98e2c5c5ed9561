// graphs/marble.json as the C++ that `shadetree emit --cpp` writes, built
// by g++ and by clang++ (-O2 -march=native), to compare with the JIT and
// the yardstick. Same signature as yardstick::marble.
#pragma once

#include <cstddef>

namespace shadetree::emitted {

void marble_gcc(const float* x, const float* y, const float* z, const float* filter_width, float* red, float* green,
                float* blue, std::size_t count);
void marble_clang(const float* x, const float* y, const float* z, const float* filter_width, float* red, float* green,
                  float* blue, std::size_t count);

}  // namespace shadetree::emitted

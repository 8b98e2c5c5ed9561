// The hand-written yardstick: graphs/marble.json as a plain scalar C++
// loop, compiled with -O3 -march=native, to measure the JIT against.
#pragma once

#include <cstddef>

namespace shadetree::yardstick {

// Marble at default params for `count` samples; rgb planes out.
void marble(const float* x, const float* y, const float* z, const float* filter_width, float* red, float* green,
            float* blue, std::size_t count);

}  // namespace shadetree::yardstick

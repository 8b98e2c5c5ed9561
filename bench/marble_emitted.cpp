// One of the functions of bench/marble_emitted.h, over the header that
// `shadetree emit graphs/marble.json --cpp --name KERNEL` wrote at build
// time. CMakeLists.txt compiles this file once per compiler, with KERNEL
// the function's name (marble_gcc, marble_clang) and its own namespace for
// the emitted library, so the two builds never share an inline function.
#include "bench/marble_emitted.h"

#define SHADETREE_PASTE_(a, b) a##b
#define SHADETREE_PASTE(a, b) SHADETREE_PASTE_(a, b)
#define SHADETREE_STRING_(a) #a
#define SHADETREE_STRING(a) SHADETREE_STRING_(a)
#define shadetree_emitted SHADETREE_PASTE(shadetree_emitted_, KERNEL)
#include SHADETREE_STRING(KERNEL.h)

namespace shadetree::emitted {

void KERNEL(const float* x, const float* y, const float* z, const float* filter_width, float* red, float* green,
            float* blue, std::size_t count) {
  const SHADETREE_PASTE(KERNEL, _params) params;
  SHADETREE_PASTE(KERNEL, _inputs) inputs;
  inputs.P[0] = x;
  inputs.P[1] = y;
  inputs.P[2] = z;
  inputs.filter_width = filter_width;
  SHADETREE_PASTE(KERNEL, _outputs) outputs;
  outputs.color[0] = red;
  outputs.color[1] = green;
  outputs.color[2] = blue;
  SHADETREE_PASTE(KERNEL, _run)(&params, &inputs, &outputs, count);
}

}  // namespace shadetree::emitted

// One kernel interface for every backend: evaluate a graph over `count`
// samples held in structure-of-arrays buffers. Drivers never know which
// backend made the kernel.
#pragma once

#include <cstddef>
#include <memory>

#include "graph/shade_ir.h"

namespace shadetree {

// Varying inputs are planes of `count` floats (null where the graph does
// not read them); time and frame are the same for every sample of a call.
struct KernelInputs {
  const float* P[3] = {nullptr, nullptr, nullptr};
  const float* N[3] = {nullptr, nullptr, nullptr};
  const float* uv[2] = {nullptr, nullptr};
  const float* filter_width = nullptr;
  const float* density = nullptr;
  float time = 0.0f;
  float frame = 0.0f;

  // The same inputs starting `offset` samples later.
  KernelInputs advanced(std::size_t offset) const;
};

class Kernel {
 public:
  virtual ~Kernel() = default;

  // `params` is the uniform block (see lower.h: param_block); `outputs`
  // holds one plane per component of each of ir().outputs, in order.
  // Thread-safe: concurrent calls share nothing mutable.
  virtual void run(const float* params, const KernelInputs& inputs, float* const* outputs,
                   std::size_t count) const = 0;

  virtual const ShadeIR& ir() const = 0;
};

// Which inputs a program reads, so drivers can skip computing the rest.
struct InputUsage {
  bool P = false, N = false, uv = false, filter_width = false, density = false;
};
InputUsage input_usage(const ShadeIR& ir);

}  // namespace shadetree

// One kernel interface for every backend: evaluate a graph over `count`
// samples held in structure-of-arrays buffers. Drivers never know which
// backend made the kernel.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "ir/shade_ir.h"

namespace shadetree {

// The varying input planes, in one fixed order (also the order in which a
// JIT kernel receives them).
enum class InputPlane : int { P_x, P_y, P_z, N_x, N_y, N_z, u, v, filter_width, density };
inline constexpr int input_plane_count = 10;

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

  // The plane pointers in InputPlane order.
  void planes(const float* out[input_plane_count]) const;
};

// Storage for every varying input of `count` samples, zero-filled, plane
// after plane. Drivers fill the planes they have and hand out inputs().
class InputBuffers {
 public:
  explicit InputBuffers(std::size_t count)
      : count_(count), storage_(count * static_cast<std::size_t>(input_plane_count), 0.0f) {}

  float* plane(InputPlane which) { return storage_.data() + count_ * static_cast<std::size_t>(which); }
  const float* plane(InputPlane which) const { return storage_.data() + count_ * static_cast<std::size_t>(which); }
  std::size_t count() const { return count_; }

  KernelInputs inputs(float time = 0.0f, float frame = 0.0f) const;

 private:
  std::size_t count_;
  std::vector<float> storage_;
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

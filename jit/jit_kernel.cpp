// The JIT kernel: full vectors go straight to the compiled code; the tail
// (fewer than W samples) is copied into padded scratch planes, run as one
// more vector, and copied back, so the generated loop never needs a mask
// for memory.
#include "jit/jit_kernel.h"

#include <algorithm>
#include <vector>

namespace shadetree {
namespace {

class JitKernel final : public Kernel {
 public:
  JitKernel(ShadeIR ir, CompiledKernel compiled) : ir_(std::move(ir)), compiled_(compiled) {
    for (const IrOutput& output : ir_.outputs) output_planes_ += component_count(output.type);
  }

  const ShadeIR& ir() const override { return ir_; }

  void run(const float* params, const KernelInputs& inputs, float* const* outputs, std::size_t count) const override {
    const std::size_t width = static_cast<std::size_t>(compiled_.width);
    const std::size_t full = count / width * width;
    const float* planes[input_plane_count];
    inputs.planes(planes);
    if (full > 0)
      compiled_.function(params, planes, inputs.time, inputs.frame, outputs, static_cast<std::int64_t>(full));
    const std::size_t tail = count - full;
    if (tail == 0) return;
    // Padded copies: unused inputs stay null, the padding lanes read zeros.
    std::vector<float> scratch((input_plane_count + output_planes_) * width, 0.0f);
    const float* tail_planes[input_plane_count];
    for (int p = 0; p < input_plane_count; ++p) {
      tail_planes[p] = nullptr;
      if (!planes[p]) continue;
      float* copy = scratch.data() + p * width;
      std::copy(planes[p] + full, planes[p] + count, copy);
      tail_planes[p] = copy;
    }
    std::vector<float*> tail_outputs(output_planes_);
    for (std::size_t p = 0; p < output_planes_; ++p)
      tail_outputs[p] = scratch.data() + (input_plane_count + p) * width;
    compiled_.function(params, tail_planes, inputs.time, inputs.frame, tail_outputs.data(),
                       static_cast<std::int64_t>(width));
    for (std::size_t p = 0; p < output_planes_; ++p)
      std::copy(tail_outputs[p], tail_outputs[p] + tail, outputs[p] + full);
  }

 private:
  ShadeIR ir_;
  CompiledKernel compiled_;
  std::size_t output_planes_ = 0;
};

}  // namespace

Result<std::unique_ptr<Kernel>> make_jit_kernel(ShadeIR ir, int width, const JitSettings& settings) {
  Result<CompiledKernel> compiled = compile_kernel(ir, width, settings);
  if (!compiled) return compiled.error();
  return std::unique_ptr<Kernel>(std::make_unique<JitKernel>(std::move(ir), *compiled));
}

}  // namespace shadetree

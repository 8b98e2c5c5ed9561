// The JIT kernel. Binding runs the compiled bind function into a state
// block; runs hand full vectors straight to the compiled run function. The
// tail (fewer than W samples) is copied into padded scratch planes, run as
// one more vector, and copied back, so the generated loop never needs a
// mask for memory. State and scratch belong to the binding and are reused
// by every run.
#include "jit/jit_kernel.h"

#include <algorithm>
#include <vector>

// Calls into generated code. Clang's -fsanitize=function (part of
// -fsanitize=undefined) checks an indirect call by reading a type
// signature placed just before the callee; JIT code has none, and a kernel
// that began a page made that read fault (the fuzzer found it).
#if defined(__clang__)
#define SHADETREE_CALLS_JIT_CODE __attribute__((no_sanitize("function")))
#else
#define SHADETREE_CALLS_JIT_CODE
#endif

namespace shadetree {
namespace {

class JitKernel final : public Kernel {
 public:
  JitKernel(ShadeIR ir, CompiledKernel compiled)
      : Kernel(ir), ir_(std::move(ir)), compiled_(compiled) {}

  const ShadeIR& ir() const override { return ir_; }

  std::unique_ptr<BoundKernel> bind(const float* params, const UniformInputs& uniforms) const override;

  ShadeIR ir_;
  CompiledKernel compiled_;
};

class JitBinding final : public BoundKernel {
 public:
  SHADETREE_CALLS_JIT_CODE JitBinding(const JitKernel& kernel, const float* params, const UniformInputs& uniforms)
      : BoundKernel(kernel.reads(), kernel.outputs()),
        compiled_(kernel.compiled_),
        state_(static_cast<std::size_t>(std::max(kernel.compiled_.state_size, 1))),
        width_(static_cast<std::size_t>(kernel.compiled_.width)),
        output_planes_(static_cast<std::size_t>(kernel.outputs().plane_count)),
        provided_planes_(provided_planes(kernel.outputs())) {
    compiled_.bind(params, uniforms.values, state_.data());
    // Padded tail planes: the inputs the program reads, then every output.
    tail_inputs_ = varying_planes(kernel.reads());
    tail_scratch_.assign((tail_inputs_.size() + output_planes_) * width_, 0.0f);
    for (std::size_t i = 0; i < tail_inputs_.size(); ++i)
      tail_planes_.planes[tail_inputs_[i]] = tail_scratch_.data() + i * width_;
    for (std::size_t p = 0; p < output_planes_; ++p)
      tail_outputs_.push_back(tail_scratch_.data() + (tail_inputs_.size() + p) * width_);
  }

  SHADETREE_CALLS_JIT_CODE void run(const SampleInputs& inputs, float* const* outputs, std::size_t count) override {
    const std::size_t full = count / width_ * width_;
    if (full > 0) compiled_.run(state_.data(), inputs.planes, outputs, static_cast<std::int64_t>(full));
    const std::size_t tail = count - full;
    if (tail == 0) return;
    for (std::size_t i = 0; i < tail_inputs_.size(); ++i) {
      const float* from = inputs.planes[tail_inputs_[i]] + full;
      std::copy(from, from + tail, tail_scratch_.data() + i * width_);
    }
    compiled_.run(state_.data(), tail_planes_.planes, tail_outputs_.data(), static_cast<std::int64_t>(width_));
    for (int p : provided_planes_)
      if (outputs[p]) std::copy(tail_outputs_[p], tail_outputs_[p] + tail, outputs[p] + full);
  }

 private:
  CompiledKernel compiled_;
  std::vector<float> state_;
  std::size_t width_;
  std::size_t output_planes_;
  std::vector<int> provided_planes_;
  std::vector<int> tail_inputs_;
  std::vector<float> tail_scratch_;
  SampleInputs tail_planes_;
  std::vector<float*> tail_outputs_;
};

std::unique_ptr<BoundKernel> JitKernel::bind(const float* params, const UniformInputs& uniforms) const {
  return std::make_unique<JitBinding>(*this, params, uniforms);
}

}  // namespace

Result<std::unique_ptr<Kernel>> make_jit_kernel(ShadeIR ir, int width, const JitSettings& settings) {
  Result<CompiledKernel> compiled = compile_kernel(ir, width, settings);
  if (!compiled) return compiled.error();
  return make_jit_kernel(std::move(ir), *compiled);
}

std::unique_ptr<Kernel> make_jit_kernel(ShadeIR ir, const CompiledKernel& compiled) {
  return std::make_unique<JitKernel>(std::move(ir), compiled);
}

}  // namespace shadetree

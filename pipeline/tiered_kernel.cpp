#include "pipeline/tiered_kernel.h"

#include <atomic>
#include <chrono>
#include <future>

#include "interp/interpreter.h"
#include "jit/jit_kernel.h"

namespace shadetree {
namespace {

class Tiered final : public TieredKernel {
 public:
  Tiered(ShadeIR ir, int width, const JitSettings& settings)
      : TieredKernel(ir), interpreted_(make_interpreted_kernel(ir)), start_(std::chrono::steady_clock::now()) {
    compiled_ = std::async(std::launch::async, [this, ir = std::move(ir), width, settings]() mutable {
                  Result<std::unique_ptr<Kernel>> kernel = make_jit_kernel(std::move(ir), width, settings);
                  ready_milliseconds_ =
                      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
                  if (!kernel) return std::shared_ptr<Kernel>();
                  return std::shared_ptr<Kernel>(std::move(*kernel));
                }).share();
  }

  ~Tiered() override {
    if (compiled_.valid()) compiled_.wait();  // the compile thread reads this kernel
  }

  const ShadeIR& ir() const override { return interpreted_->ir(); }

  std::unique_ptr<BoundKernel> bind(const float* params, const UniformInputs& uniforms) const override;

  TieredReport report() const override {
    TieredReport report;
    report.jit_ready = ready();
    report.jit_failed = report.jit_ready && !compiled_.get();
    report.jit_ready_milliseconds = ready_milliseconds_;
    report.interpreted_runs = interpreted_runs_;
    report.compiled_runs = compiled_runs_;
    return report;
  }

  bool ready() const { return compiled_.wait_for(std::chrono::seconds(0)) == std::future_status::ready; }

  std::unique_ptr<Kernel> interpreted_;
  std::chrono::steady_clock::time_point start_;
  std::shared_future<std::shared_ptr<Kernel>> compiled_;
  std::atomic<double> ready_milliseconds_{0};
  mutable std::atomic<long> interpreted_runs_{0}, compiled_runs_{0};
};

// Binds the interpreter at once, and the JIT at the first run after its
// compile is done; params are copied, since that may be long after bind().
class TieredBinding final : public BoundKernel {
 public:
  TieredBinding(const Tiered& kernel, const float* params, const UniformInputs& uniforms)
      : BoundKernel(kernel.reads(), kernel.outputs()),
        kernel_(kernel),
        params_(params, params + kernel.ir().param_block_size),
        uniforms_(uniforms),
        interpreted_(kernel.interpreted_->bind(params, uniforms)) {}

  void run(const SampleInputs& inputs, float* const* outputs, std::size_t count) override {
    if (!compiled_ && kernel_.ready())
      if (const std::shared_ptr<Kernel>& jit = kernel_.compiled_.get()) compiled_ = jit->bind(params_.data(), uniforms_);
    (compiled_ ? kernel_.compiled_runs_ : kernel_.interpreted_runs_)++;
    (compiled_ ? *compiled_ : *interpreted_).run(inputs, outputs, count);
  }

 private:
  const Tiered& kernel_;
  std::vector<float> params_;
  UniformInputs uniforms_;
  std::unique_ptr<BoundKernel> interpreted_, compiled_;
};

std::unique_ptr<BoundKernel> Tiered::bind(const float* params, const UniformInputs& uniforms) const {
  return std::make_unique<TieredBinding>(*this, params, uniforms);
}

}  // namespace

std::unique_ptr<TieredKernel> make_tiered_kernel(ShadeIR ir, int width, const JitSettings& settings) {
  return std::make_unique<Tiered>(std::move(ir), width, settings);
}

}  // namespace shadetree

#include "pipeline/tiered_kernel.h"

#include <sys/resource.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>

#include "interp/interpreter.h"
#include "jit/jit_kernel.h"

namespace shadetree {
namespace {

enum class Tier { interpreter, quick, full };

// A nice value for the full compile after a quick one: under CPU pressure
// it gets about a tenth of a core (Linux's weights) until the preview ends.
constexpr int full_compile_nice = 10;

class Tiered final : public TieredKernel {
 public:
  Tiered(ShadeIR ir, int width, const JitSettings& settings, bool quick_first)
      : TieredKernel(ir), interpreted_(make_interpreted_kernel(ir)), start_(std::chrono::steady_clock::now()) {
    compiler_ = std::thread([this, ir = std::move(ir), width, settings, quick_first]() mutable {
      compile(std::move(ir), width, settings, quick_first);
    });
  }

  ~Tiered() override { compiler_.join(); }  // the compile thread reads this kernel

  const ShadeIR& ir() const override { return interpreted_->ir(); }

  std::unique_ptr<BoundKernel> bind(const float* params, const UniformInputs& uniforms) const override;

  TieredReport report() const override {
    TieredReport report;
    report.jit_ready = full_done_;
    report.jit_failed = report.jit_ready && tier_ != Tier::full;
    if (report.jit_failed) {
      std::lock_guard lock(mutex_);
      report.jit_error = jit_error_;
    }
    report.jit_ready_milliseconds = jit_ready_milliseconds_;
    report.quick_ready_milliseconds = quick_ready_milliseconds_;
    report.interpreted_runs = runs_[0];
    report.quick_runs = runs_[1];
    report.compiled_runs = runs_[2];
    return report;
  }

  // The most optimized kernel compiled so far (null: none yet), and its tier.
  std::pair<std::shared_ptr<const Kernel>, Tier> latest() const {
    std::lock_guard lock(mutex_);
    return {jit_, tier_};
  }

  std::unique_ptr<Kernel> interpreted_;
  std::atomic<Tier> tier_{Tier::interpreter};
  mutable std::atomic<long> runs_[3] = {0, 0, 0};  // by tier

 private:
  void compile(ShadeIR ir, int width, const JitSettings& settings, bool quick_first) {
    if (quick_first && !cached_kernel(ir, width, settings)) {
      JitSettings quick = settings;
      quick.optimization = Optimization::quick;
      if (Result<std::unique_ptr<Kernel>> kernel = make_jit_kernel(ir, width, quick)) {
        quick_ready_milliseconds_ = elapsed_milliseconds();
        publish(std::move(*kernel), Tier::quick);
      }
      // Raising one's own nice value needs no privilege; if it fails the
      // compile runs at the usual priority.
      setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), full_compile_nice);
    }
    Result<std::unique_ptr<Kernel>> kernel = make_jit_kernel(std::move(ir), width, settings);
    jit_ready_milliseconds_ = elapsed_milliseconds();
    if (kernel) {
      publish(std::move(*kernel), Tier::full);
    } else {
      std::lock_guard lock(mutex_);
      jit_error_ = kernel.error().message;
    }
    full_done_ = true;
  }

  void publish(std::unique_ptr<Kernel> kernel, Tier tier) {
    std::lock_guard lock(mutex_);
    jit_ = std::move(kernel);
    tier_ = tier;
  }

  double elapsed_milliseconds() const {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
  }

  std::chrono::steady_clock::time_point start_;
  mutable std::mutex mutex_;
  std::shared_ptr<const Kernel> jit_;
  std::string jit_error_;
  std::atomic<bool> full_done_{false};
  std::atomic<double> jit_ready_milliseconds_{0}, quick_ready_milliseconds_{0};
  std::thread compiler_;
};

// Binds the interpreter at once, and each JIT kernel at the first run after
// its compile is done; params are copied, since that may be long after
// bind(). A binding holds the kernel it runs, which a newer tier replaces.
class TieredBinding final : public BoundKernel {
 public:
  TieredBinding(const Tiered& kernel, const float* params, const UniformInputs& uniforms)
      : BoundKernel(kernel.reads(), kernel.outputs()),
        kernel_(kernel),
        params_(params, params + kernel.ir().param_block_size),
        uniforms_(uniforms),
        interpreted_(kernel.interpreted_->bind(params, uniforms)) {}

  void run(const SampleInputs& inputs, float* const* outputs, std::size_t count) override {
    if (kernel_.tier_ != tier_) {
      auto [jit, tier] = kernel_.latest();
      compiled_ = jit->bind(params_.data(), uniforms_);
      jit_ = std::move(jit);
      tier_ = tier;
    }
    kernel_.runs_[static_cast<int>(tier_)]++;
    (compiled_ ? *compiled_ : *interpreted_).run(inputs, outputs, count);
  }

 private:
  const Tiered& kernel_;
  std::vector<float> params_;
  UniformInputs uniforms_;
  std::unique_ptr<BoundKernel> interpreted_;
  Tier tier_ = Tier::interpreter;
  std::shared_ptr<const Kernel> jit_;
  std::unique_ptr<BoundKernel> compiled_;  // bound to jit_
};

std::unique_ptr<BoundKernel> Tiered::bind(const float* params, const UniformInputs& uniforms) const {
  return std::make_unique<TieredBinding>(*this, params, uniforms);
}

}  // namespace

std::unique_ptr<TieredKernel> make_tiered_kernel(ShadeIR ir, int width, const JitSettings& settings,
                                                 bool quick_first) {
  return std::make_unique<Tiered>(std::move(ir), width, settings, quick_first);
}

}  // namespace shadetree

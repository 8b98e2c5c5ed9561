#include "server/preview_kernels.h"

#include <algorithm>

#include "jit/jit_kernel.h"

namespace shadetree {

const char* source_name(PreviewKernel::Source source) {
  switch (source) {
    case PreviewKernel::Source::memory: return "memory";
    case PreviewKernel::Source::disk: return "disk";
    case PreviewKernel::Source::compiled: return "compiled";
    case PreviewKernel::Source::compiling: return "compiling";
  }
  return "";
}

CompileThread::CompileThread() : thread_([this] { work(); }) {}

CompileThread::~CompileThread() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_one();
  thread_.join();
}

Result<CompiledKernel> CompileThread::run(const std::function<Result<CompiledKernel>()>& compile) {
  std::packaged_task<Result<CompiledKernel>()> task(compile);
  std::future<Result<CompiledKernel>> compiled = task.get_future();
  {
    std::lock_guard lock(mutex_);
    tasks_.push_back(std::move(task));
  }
  wake_.notify_one();
  return compiled.get();
}

void CompileThread::work() {
  std::unique_lock lock(mutex_);
  for (;;) {
    wake_.wait(lock, [&] { return stopping_ || !tasks_.empty(); });
    if (tasks_.empty()) return;
    std::packaged_task<Result<CompiledKernel>()> task = std::move(tasks_.front());
    tasks_.pop_front();
    lock.unlock();
    task();
    lock.lock();
  }
}

PreviewKernels::PreviewKernels(JitSettings settings, int background_compiles)
    : settings_(std::move(settings)), background_compiles_(background_compiles) {}

PreviewKernels::~PreviewKernels() {
  std::lock_guard lock(mutex_);
  compiling_.clear();  // each tiered kernel waits for its compile
}

void PreviewKernels::forget_finished() {
  std::erase_if(compiling_, [](const Compiling& entry) { return entry.kernel->report().jit_ready; });
}

int PreviewKernels::compiling() {
  std::lock_guard lock(mutex_);
  forget_finished();
  return static_cast<int>(compiling_.size());
}

Result<PreviewKernel> PreviewKernels::kernel_for(const ShadeIR& ir) {
  {
    // A compile under way is looked for before the caches, under the lock:
    // one is forgotten only once its kernel is in the memory cache, so no
    // program starts compiling twice.
    const std::string identity = kernel_identity(ir, 0, settings_);
    std::lock_guard lock(mutex_);
    forget_finished();
    auto same = std::find_if(compiling_.begin(), compiling_.end(),
                             [&](const Compiling& entry) { return entry.identity == identity; });
    if (same != compiling_.end()) return PreviewKernel{same->kernel, PreviewKernel::Source::compiling};
    if (std::optional<CompiledKernel> cached = cached_kernel(ir, 0, settings_)) {
      const auto source = cached->cache == CacheHit::disk ? PreviewKernel::Source::disk : PreviewKernel::Source::memory;
      return PreviewKernel{make_jit_kernel(ir, *cached), source};
    }
    if (static_cast<int>(compiling_.size()) < background_compiles_) {
      std::shared_ptr<const TieredKernel> tiered = make_tiered_kernel(ir, 0, settings_, true);
      ++compiles_;
      compiling_.push_back({identity, tiered});
      return PreviewKernel{tiered, PreviewKernel::Source::compiling};
    }
  }
  Result<CompiledKernel> compiled = foreground_compiles_.run([&] { return compile_kernel(ir, 0, settings_); });
  if (!compiled) return compiled.error();
  if (compiled->cache == CacheHit::none) ++compiles_;
  return PreviewKernel{make_jit_kernel(ir, *compiled), PreviewKernel::Source::compiled};
}

}  // namespace shadetree

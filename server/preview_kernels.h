// The kernel each preview of `shadetree serve` renders with. A program the
// JIT has compiled (memory or disk cache) runs compiled. A new program, an
// edit of the graph, starts compiling in the background and renders on the
// interpreter meanwhile, switching between kernel runs to a quick JIT
// kernel once it is ready and later to the full one (pipeline/
// tiered_kernel.h, the backends agree to the bit): the edit's first
// preview waits for no compile. Requests for a program whose compiles are
// under way share them. At most `background_compiles` programs compile
// in the background at once (a graph opened draws a thumbnail per node,
// each its own program); past that, a new program compiles (fully) before
// it renders. Either way, each program starts compiling once, when first
// seen. Volumes too: their march is slower on the interpreter, but it
// switches to the JIT at its next run (bench/editor_latency_benchmark.cpp).
#pragma once

#include <atomic>
#include <condition_variable>
#include <deque>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <thread>
#include <string>
#include <vector>

#include "graph/diagnostic.h"
#include "ir/kernel.h"
#include "jit/jit_compiler.h"
#include "pipeline/tiered_kernel.h"

namespace shadetree {

struct PreviewKernel {
  enum class Source { memory, disk, compiled, compiling };
  std::shared_ptr<const Kernel> kernel;
  Source source = Source::compiled;
};

// "memory", "disk", "compiled" or "compiling" (X-Kernel).
const char* source_name(PreviewKernel::Source source);

// Runs compiles one at a time on a thread of its own. The JIT keeps a
// target machine (about 1 MB) for each thread that compiles, for good:
// compiled on the server's workers, a worker first used late grew the
// server's memory then (issue 21: about 8 KB per edit, with httplib's
// workers taken in turn).
class CompileThread {
 public:
  CompileThread();
  ~CompileThread();  // after the compiles queued
  Result<CompiledKernel> run(const std::function<Result<CompiledKernel>()>& compile);

 private:
  void work();
  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::packaged_task<Result<CompiledKernel>()>> tasks_;
  bool stopping_ = false;
  std::thread thread_;
};

class PreviewKernels {
 public:
  PreviewKernels(JitSettings settings, int background_compiles);
  ~PreviewKernels();  // waits for the compiles under way

  Result<PreviewKernel> kernel_for(const ShadeIR& ir);

  int compiling();  // background compiles under way
  long compiles() const { return compiles_; }  // started since construction, in either way

 private:
  struct Compiling {
    std::string identity;
    std::shared_ptr<const TieredKernel> kernel;
  };
  void forget_finished();  // under mutex_

  JitSettings settings_;
  int background_compiles_;
  std::mutex mutex_;
  std::vector<Compiling> compiling_;
  std::atomic<long> compiles_{0};
  CompileThread foreground_compiles_;  // past background_compiles_
};

}  // namespace shadetree

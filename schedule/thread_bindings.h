// Bind once, run many, per worker thread: each thread that renders binds
// the kernel (params and uniform globals) on its first tile and reuses the
// binding, with its scratch, for every tile after.
#pragma once

#include <memory>

#include <tbb/enumerable_thread_specific.h>

#include "ir/kernel.h"

namespace shadetree {

class ThreadBindings {
 public:
  ThreadBindings(const Kernel& kernel, const float* params, const UniformInputs& uniforms)
      : kernel_(kernel), params_(params), uniforms_(uniforms) {}

  BoundKernel& local() {
    std::unique_ptr<BoundKernel>& binding = bindings_.local();
    if (!binding) binding = kernel_.bind(params_, uniforms_);
    return *binding;
  }

 private:
  const Kernel& kernel_;
  const float* params_;
  UniformInputs uniforms_;
  tbb::enumerable_thread_specific<std::unique_ptr<BoundKernel>> bindings_;
};

}  // namespace shadetree

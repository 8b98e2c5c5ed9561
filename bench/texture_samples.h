// A texture graph's samples as its driver makes them, for benchmarks that
// run the graph's kernel and code written outside the JIT on the same
// samples: pixel centres of the graph's own render domain on a side x side
// grid, the globals the graph reads and P and filter_width in planes.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "bench/plane_kernel.h"
#include "ir/kernel.h"
#include "pipeline/compile_graph.h"

namespace shadetree {

class TextureSamples {
 public:
  // Exits with the graph's diagnostic if it does not compile.
  TextureSamples(const std::string& graph_path, int side);
  TextureSamples(const TextureSamples&) = delete;  // the output planes point into it
  TextureSamples& operator=(const TextureSamples&) = delete;

  const LoadedGraph& graph() const { return graph_; }
  std::size_t count() const { return input_.count(); }
  // The colour planes the last run wrote.
  const std::vector<float>& rgb(int component) const { return rgb_[component]; }

  // One binding, as a driver keeps per thread, run on all samples.
  void run(BoundKernel& kernel);
  void run(PlaneKernel* kernel);

 private:
  LoadedGraph graph_;
  SampleBuffers input_;
  std::vector<float> rgb_[3];
  std::vector<float*> outputs_;  // the kernel's output planes: rgb_ as its colour, null elsewhere
};

}  // namespace shadetree

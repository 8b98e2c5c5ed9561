// One kernel interface for every backend and every driver: evaluate a
// graph's program over samples held in structure-of-arrays planes.
//
// Inputs are the globals (nodes/globals.h): varying ones as planes of
// floats (SampleInputs), uniform ones as one block per call
// (UniformInputs). Outputs follow the graph kind's contract
// (nodes/output_contract.h): OutputLayout says which plane holds what.
//
// A kernel is bound once (params and uniform globals: everything uniform
// is computed then) and run many times on that binding, which keeps its
// scratch between runs. A binding belongs to one thread at a time; a
// Kernel is shared. Drivers never know which backend made the kernel.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ir/shade_ir.h"
#include "nodes/globals.h"
#include "nodes/output_contract.h"

namespace shadetree {

namespace lanes {
struct Interval;  // nodes/lane_interval.h
}  // namespace lanes

// The varying inputs of a run: one plane per component of each varying
// global, in the globals table's order (null where the program does not
// read it).
struct SampleInputs {
  const float* planes[varying_plane_count] = {};

  const float* plane(GlobalId id, int component = 0) const {
    return planes[global_def(id).first + component];
  }
};

// A compiled interval program (the JIT's: codegen/emit_interval_program.h)
// as its caller calls it: enclosures over a box of the varying globals,
// one interval per input plane, into one per output plane.
using IntervalProgramFunction = void (*)(const float* params, const float* uniform_globals,
                                         const lanes::Interval* box_planes, lanes::Interval* output_planes);

// The uniform globals of a binding.
struct UniformInputs {
  float values[uniform_value_count] = {};

  void set(GlobalId id, float value, int component = 0) { values[global_def(id).first + component] = value; }
  float get(GlobalId id, int component = 0) const { return values[global_def(id).first + component]; }
};

// The globals `ir` reads, and the input planes of those that are varying.
GlobalSet globals_read(const ShadeIR& ir);
std::vector<int> varying_planes(const GlobalSet& read);

// Floats from the start of one plane to the next in the buffers below:
// `count` rounded up to a cache line, plus one line. Planes a power of two
// apart map to the same cache sets and alias each other's stores; staggered
// by a line, a kernel streaming a dozen planes keeps them all in cache.
std::size_t plane_stride(std::size_t count);

// Zero-filled planes for the varying globals in `stored`, `count` samples
// each. Drivers fill the planes of the globals the program reads
// (has() says which) and hand out inputs().
class SampleBuffers {
 public:
  SampleBuffers(std::size_t count, const GlobalSet& stored);

  bool has(GlobalId id) const { return stored_.test(static_cast<std::size_t>(id)); }
  // Component `component` of global `id` (which must be stored).
  float* plane(GlobalId id, int component = 0) {
    return storage_.data() + offset_[global_def(id).first + component];
  }
  std::size_t count() const { return count_; }
  SampleInputs inputs() const;

 private:
  std::size_t count_;
  GlobalSet stored_;
  std::size_t offset_[varying_plane_count] = {};
  std::vector<float> storage_;
};

// Where a program's outputs are: the output planes of its kind's contract,
// and which of them the program provides.
struct OutputLayout {
  GraphKind kind = GraphKind::texture;
  int plane_count = 0;
  int first_plane[output_id_count] = {};  // -1 where the program does not provide it

  bool provides(OutputId id) const { return first_plane[static_cast<int>(id)] >= 0; }
  int plane(OutputId id, int component = 0) const { return first_plane[static_cast<int>(id)] + component; }
};

OutputLayout output_layout(const ShadeIR& ir);

// Planes for every output of a layout, `count` samples each.
class OutputBuffers {
 public:
  OutputBuffers(std::size_t count, const OutputLayout& layout);

  float* const* planes() { return planes_.data(); }
  const float* plane(int index) const { return planes_[static_cast<std::size_t>(index)]; }

 private:
  std::vector<float> storage_;
  std::vector<float*> planes_;
};

// The planes of the outputs a program provides, in layout order.
std::vector<int> provided_planes(const OutputLayout& layout);

// A canonical text of the kernel ABI: the op table, the globals table and
// the output contracts. Compiled kernels cached on disk are keyed on it.
std::string kernel_abi();

// A kernel with its params and uniform globals bound.
class BoundKernel {
 public:
  virtual ~BoundKernel() = default;

  // Samples 0 .. count-1. `outputs` holds the layout's plane_count planes;
  // those of outputs the program does not provide may be null.
  virtual void run(const SampleInputs& inputs, float* const* outputs, std::size_t count) = 0;

  // Only the samples listed in `index`: sample index[k] reads its inputs
  // and writes its outputs at index[k], so a driver can hand a compacted
  // list of live rays or visible pixels without copying planes.
  void run_indexed(const SampleInputs& inputs, float* const* outputs, const std::uint32_t* index,
                   std::size_t count);

 protected:
  BoundKernel(const GlobalSet& reads, const OutputLayout& layout) : reads_(reads), layout_(layout) {}

 private:
  GlobalSet reads_;
  OutputLayout layout_;
  std::vector<float> indexed_scratch_;  // gathered inputs and outputs, reused across calls
};

class Kernel {
 public:
  virtual ~Kernel() = default;

  virtual const ShadeIR& ir() const = 0;

  // `params` is the uniform block (see lower.h: param_block), read during
  // bind only. Thread-safe.
  virtual std::unique_ptr<BoundKernel> bind(const float* params, const UniformInputs& uniforms) const = 0;

  const OutputLayout& outputs() const { return outputs_; }
  const GlobalSet& reads() const { return reads_; }

 protected:
  explicit Kernel(const ShadeIR& ir) : outputs_(output_layout(ir)), reads_(globals_read(ir)) {}

 private:
  OutputLayout outputs_;
  GlobalSet reads_;
};

}  // namespace shadetree

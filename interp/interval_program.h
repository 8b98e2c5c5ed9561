// A graph's program evaluated over a box of its varying globals: for each
// output plane, an interval enclosing every value the lane backends
// compute for a sample in the box (every op's interval form,
// interp/interval_kernels.h). The volume ray marcher is meant to skip
// bricks whose density's upper bound is <= 0.
//
// A conditional region is evaluated over the whole box unless no sample
// of the box takes it, when it is passed over; where its condition is
// uncertain both branches are evaluated, and the `if` that joins them
// takes their hull. An enclosure with a NaN or infinite endpoint is
// returned as [-inf, +inf] (nothing is known there).
//
// As with kernels, an IntervalProgram is shared and a binding belongs to
// one thread; evaluate() allocates nothing.
#pragma once

#include <memory>
#include <vector>

#include "interp/interval_kernels.h"
#include "ir/kernel.h"

namespace shadetree {

// A box of the varying globals: one interval per input plane, in the
// order of SampleInputs. Planes left unset are unknown ([-inf, +inf]).
struct SampleBox {
  lanes::Interval planes[varying_plane_count];

  SampleBox();
  void set(GlobalId id, lanes::Interval value, int component = 0) { planes[global_def(id).first + component] = value; }
};

class BoundIntervalProgram;

class IntervalProgram {
 public:
  // Bounds `bounded` outputs (all where empty): the instructions no
  // bounded output depends on are not evaluated (a volume's colour where
  // only its opacity is bounded), and evaluate() leaves the other outputs'
  // planes alone.
  explicit IntervalProgram(ShadeIR ir, const std::vector<OutputId>& bounded = {});

  const ShadeIR& ir() const { return ir_; }
  const OutputLayout& outputs() const { return outputs_; }

  // Params and uniform globals, as Kernel::bind: the uniform values are
  // computed once, as points.
  BoundIntervalProgram bind(const float* params, const UniformInputs& uniforms) const;

  // Runs the same program compiled (the JIT's compile_interval_program,
  // jit/jit_compiler.h), whose enclosures are these to the bit, from now
  // on; `code` keeps `evaluate` callable.
  void use_compiled(IntervalProgramFunction evaluate, std::shared_ptr<const void> code);

 private:
  friend class BoundIntervalProgram;
  ShadeIR ir_;
  OutputLayout outputs_;
  std::vector<interp::IntervalKernel> kernels_;
  std::vector<OpConstants> constants_;
  std::vector<char> needed_;  // per instruction: a bounded output depends on it
  std::vector<char> bounded_;  // per output of the IR
  std::vector<char> lengths_read_;  // per instruction: its length is kept (ir/interval_lengths_read.h)
  IntervalProgramFunction compiled_ = nullptr;
  std::shared_ptr<const void> compiled_code_;
};

class BoundIntervalProgram {
 public:
  // Movable, not copyable: the planes point into the registers.
  BoundIntervalProgram(BoundIntervalProgram&&) = default;
  BoundIntervalProgram(const BoundIntervalProgram&) = delete;
  BoundIntervalProgram& operator=(const BoundIntervalProgram&) = delete;

  // outputs[p] for each plane p of the layout (outputs().plane_count);
  // the planes of outputs the program does not provide are left alone.
  void evaluate(const SampleBox& box, lanes::Interval* outputs);

 private:
  friend class IntervalProgram;
  BoundIntervalProgram(const IntervalProgram& program, const float* params, const UniformInputs& uniforms);
  void execute(bool uniform_pass, const SampleBox& box);

  const IntervalProgram* program_;
  // Per instruction: 3 components and a length (interval_planes_per_value);
  // then the unknown length.
  std::vector<lanes::Interval> registers_;
  std::vector<const lanes::Interval*> in_planes_;    // per instruction: max_op_args x 4
  std::vector<lanes::Interval*> out_planes_;         // per instruction: 4
  const float* params_ = nullptr;                    // during binding only
  std::vector<float> compiled_params_;               // for a compiled program, which reads them each time
  UniformInputs uniforms_;
};

}  // namespace shadetree

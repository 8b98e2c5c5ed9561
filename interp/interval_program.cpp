// Interval evaluation of a program (see interval_program.h): one interval
// register per component of each value and one for its length
// (nodes/interval_frame.h); binding computes the uniform
// values, evaluate() the varying ones in program order, ignoring region
// markers. A dual instruction is bounded by its value alone, and a
// gradient is not bounded at all.
#include "interp/interval_program.h"

#include <algorithm>
#include <cmath>

#include "ir/interval_lengths_read.h"
#include "ir/op_constants.h"
#include "ir/output_dependencies.h"
#include "nodes/ops/interval_form.h"

namespace shadetree {

using lanes::Interval;

SampleBox::SampleBox() { std::fill(std::begin(planes), std::end(planes), lanes::everything()); }

IntervalProgram::IntervalProgram(ShadeIR ir, const std::vector<OutputId>& bounded)
    : ir_(std::move(ir)), outputs_(output_layout(ir_)) {
  kernels_.resize(ir_.code.size(), nullptr);
  constants_.resize(ir_.code.size());
  for (std::size_t i = 0; i < ir_.code.size(); ++i) {
    const IrInstr& instr = ir_.code[i];
    if (instr.kind != IrOpKind::op) continue;
    kernels_[i] = interp::interval_kernel(instr.op);
    constants_[i] = op_constants(ir_, instr);
  }
  lengths_read_ = interval_lengths_read(ir_);
  OutputDependencies needs = output_dependencies(ir_, bounded);
  needed_ = std::move(needs.instructions);
  bounded_ = std::move(needs.outputs);
}

BoundIntervalProgram IntervalProgram::bind(const float* params, const UniformInputs& uniforms) const {
  return BoundIntervalProgram(*this, params, uniforms);
}

void IntervalProgram::use_compiled(IntervalProgramFunction evaluate, std::shared_ptr<const void> code) {
  compiled_ = evaluate;
  compiled_code_ = std::move(code);
}

BoundIntervalProgram::BoundIntervalProgram(const IntervalProgram& program, const float* params,
                                           const UniformInputs& uniforms)
    : program_(&program), params_(params), uniforms_(uniforms) {
  if (program.compiled_) {
    if (params) compiled_params_.assign(params, params + program.ir_.param_block_size);
    params_ = nullptr;
    return;
  }
  const std::vector<IrInstr>& code = program.ir_.code;
  constexpr int planes = interval_planes_per_value;
  // A value's length is known only where an op found it; the others' (and
  // a scalar read as a vector, whose plane is its own) are the unknown,
  // after the registers.
  registers_.resize(code.size() * planes + 1);
  for (std::size_t i = 0; i < code.size(); ++i) registers_[i * planes + 3] = lanes::everything();
  registers_.back() = lanes::everything();
  const Interval* unknown_length = &registers_.back();
  in_planes_.resize(code.size() * planes * max_op_args);
  out_planes_.resize(code.size() * planes);
  auto plane = [&](std::int32_t value, int component) {
    const int components = component_count(code[static_cast<std::size_t>(value)].type);
    return &registers_[static_cast<std::size_t>(value) * planes + static_cast<std::size_t>(std::min(component, components - 1))];
  };
  for (std::size_t i = 0; i < code.size(); ++i) {
    for (int a = 0; a < code[i].arg_count; ++a) {
      const std::int32_t value = code[i].args[a];
      for (int c = 0; c < 3; ++c) in_planes_[(i * max_op_args + a) * planes + c] = plane(value, c);
      const bool whole = component_count(code[static_cast<std::size_t>(value)].type) ==
                         component_count(argument_type(code[i], a));
      in_planes_[(i * max_op_args + a) * planes + 3] =
          whole ? &registers_[static_cast<std::size_t>(value) * planes + 3] : unknown_length;
    }
    for (int c = 0; c < 3; ++c) out_planes_[i * planes + c] = &registers_[i * planes + c];
    out_planes_[i * planes + 3] = program.lengths_read_[i] ? &registers_[i * planes + 3] : nullptr;
  }
  execute(/*uniform_pass=*/true, SampleBox{});
  params_ = nullptr;
}

void BoundIntervalProgram::execute(bool uniform_pass, const SampleBox& box) {
  const ShadeIR& ir = program_->ir_;
  for (std::size_t i = 0; i < ir.code.size(); ++i) {
    const IrInstr& instr = ir.code[i];
    if (instr.uniform != uniform_pass || !program_->needed_[i]) continue;
    constexpr int planes = interval_planes_per_value;
    Interval* const* out = &out_planes_[i * planes];
    const int components = component_count(instr.type);
    switch (instr.kind) {
      case IrOpKind::op:
        program_->kernels_[i](
            IntervalFrame{{&program_->constants_[i]}, &in_planes_[i * max_op_args * planes], out});
        break;
      case IrOpKind::constant:
        for (int c = 0; c < components; ++c) *out[c] = ir.data[instr.data_offset + std::min(c, instr.data_count - 1)];
        break;
      case IrOpKind::param:
        for (int c = 0; c < components; ++c) *out[c] = params_[instr.immediate[0] + c];
        break;
      case IrOpKind::global: {
        const auto id = static_cast<GlobalId>(instr.immediate[0]);
        for (int c = 0; c < components; ++c)
          *out[c] = instr.uniform ? Interval(uniforms_.get(id, c)) : box.planes[global_def(id).first + c];
        break;
      }
      case IrOpKind::extract:
        *out[0] = *in_planes_[i * max_op_args * planes + static_cast<std::size_t>(instr.immediate[0])];
        break;
      case IrOpKind::partials:
        for (int c = 0; c < components; ++c) *out[c] = lanes::everything();
        break;
      case IrOpKind::begin_region: {
        // A region that no sample of the box takes is passed over: the
        // `if` that joins it takes the other side where its condition is
        // certain, as it then is.
        if (!region_may_run(*in_planes_[i * max_op_args * planes], instr.immediate[0]))
          i = static_cast<std::size_t>(instr.immediate[1]);
        break;
      }
      case IrOpKind::end_region:
        break;
    }
  }
}

void BoundIntervalProgram::evaluate(const SampleBox& box, Interval* outputs) {
  if (program_->compiled_) {
    program_->compiled_(compiled_params_.data(), uniforms_.values, box.planes, outputs);
    return;
  }
  execute(/*uniform_pass=*/false, box);
  const OutputLayout& layout = program_->outputs_;
  for (std::size_t o = 0; o < program_->ir_.outputs.size(); ++o) {
    if (!program_->bounded_[o]) continue;
    const IrOutput& output = program_->ir_.outputs[o];
    // A scalar value read as a vector output repeats, as on the lanes.
    const int held = component_count(program_->ir_.code[static_cast<std::size_t>(output.value)].type);
    for (int c = 0; c < component_count(output.type); ++c) {
      const Interval value =
          registers_[static_cast<std::size_t>(output.value) * interval_planes_per_value +
                     static_cast<std::size_t>(std::min(c, held - 1))];
      outputs[layout.plane(output.id, c)] = reported_enclosure(value);
    }
  }
}

}  // namespace shadetree

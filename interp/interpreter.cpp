// The interpreted backend (see interpreter.h). Every ShadeIR value gets a
// register of `components` planes of one block. Binding computes the
// uniform values once (params, constants, uniform globals and everything
// that depends only on them), and they stay in their registers for every
// run of the binding; runs compute the varying values block by block.
// Conditional regions narrow the lane list to the samples that take the
// branch and skip the region when none does. A dual value (see
// ir/differentiate.h) takes four planes per component: value and partials.
#include "interp/interpreter.h"

#include <algorithm>
#include <cstring>
#include <vector>

#include "interp/dual_kernels.h"
#include "interp/exec_context.h"
#include "ir/op_constants.h"

namespace shadetree {
namespace {

using interp::Lanes;

constexpr int block = interpreter_block_size;

class InterpretedKernel final : public Kernel {
 public:
  explicit InterpretedKernel(ShadeIR ir) : Kernel(ir), ir_(std::move(ir)) {
    register_offset_.resize(ir_.code.size());
    kernels_.resize(ir_.code.size(), nullptr);
    constants_.resize(ir_.code.size());
    std::size_t offset = 0;
    int depth = 0;
    for (std::size_t i = 0; i < ir_.code.size(); ++i) {
      const IrInstr& instr = ir_.code[i];
      register_offset_[i] = offset;
      offset += static_cast<std::size_t>(stored_components(instr) * block);
      if (instr.kind == IrOpKind::begin_region) max_region_depth_ = std::max(max_region_depth_, ++depth);
      if (instr.kind == IrOpKind::end_region) --depth;
      if (instr.kind != IrOpKind::op) continue;
      kernels_[i] = instr.dual ? interp::dual_op_kernel(instr.op) : interp::op_kernel(instr.op);
      constants_[i] = op_constants(ir_, instr);
    }
    register_floats_ = offset;
  }

  const ShadeIR& ir() const override { return ir_; }

  std::unique_ptr<BoundKernel> bind(const float* params, const UniformInputs& uniforms) const override;

  // The first plane of value v's component c (a scalar's one plane for
  // every c); of its part `part` (0: value, 1 to 3: partials) if v is dual.
  std::size_t plane_offset(std::int32_t value, int component, int part = 0) const {
    const int components = component_count(ir_.code[value].type);
    const int c = std::min(component, components - 1);
    const int plane = ir_.code[value].dual ? dual_floats * c + part : c;
    return register_offset_[value] + static_cast<std::size_t>(plane * block);
  }

  ShadeIR ir_;
  std::vector<std::size_t> register_offset_;
  std::vector<interp::OpKernel> kernels_;
  std::vector<OpConstants> constants_;
  std::size_t register_floats_ = 0;
  int max_region_depth_ = 0;
};

class InterpretedBinding final : public BoundKernel {
 public:
  InterpretedBinding(const InterpretedKernel& kernel, const float* params, const UniformInputs& uniforms)
      : BoundKernel(kernel.reads(), kernel.outputs()),
        kernel_(kernel),
        ir_(kernel.ir_),
        registers_(kernel.register_floats_),
        zeros_(block, 0.0f),
        lane_lists_(static_cast<std::size_t>(kernel.max_region_depth_) * block),
        uniforms_(uniforms) {
    region_stack_.reserve(static_cast<std::size_t>(kernel.max_region_depth_));
    // 3 planes per argument and result component; 4 times as many for a dual.
    first_plane_.resize(ir_.code.size() + 1);
    for (std::size_t i = 0; i < ir_.code.size(); ++i)
      first_plane_[i + 1] = first_plane_[i] + 3 * static_cast<std::size_t>(ir_.code[i].dual ? dual_floats : 1);
    in_planes_.resize(first_plane_.back() * max_op_args);
    out_planes_.resize(first_plane_.back());
    for (std::size_t i = 0; i < ir_.code.size(); ++i) {
      const IrInstr& instr = ir_.code[i];
      const int parts = instr.dual ? dual_floats : 1;
      const float** in = &in_planes_[first_plane_[i] * max_op_args];
      for (int a = 0; a < instr.arg_count; ++a)
        for (int c = 0; c < 3; ++c)
          for (int part = 0; part < parts; ++part)
            in[(3 * a + c) * parts + part] = part > 0 && !ir_.code[instr.args[a]].dual
                                                 ? zeros_.data()
                                                 : registers_.data() + kernel.plane_offset(instr.args[a], c, part);
      for (int c = 0; c < component_count(instr.type); ++c)
        for (int part = 0; part < parts; ++part)
          out_planes_[first_plane_[i] + static_cast<std::size_t>(c * parts + part)] =
              registers_.data() + kernel.plane_offset(static_cast<std::int32_t>(i), c, part);
    }
    params_ = params;
    execute(Lanes{nullptr, block, true}, /*uniform_pass=*/true, SampleInputs{}, 0);
    params_ = nullptr;
  }

  void run(const SampleInputs& inputs, float* const* outputs, std::size_t count) override {
    for (std::size_t start = 0; start < count; start += block) {
      const int block_count = static_cast<int>(std::min<std::size_t>(block, count - start));
      execute(Lanes{nullptr, block_count, true}, false, inputs, start);
      write_outputs(outputs, start, block_count);
    }
  }

  // The components of value v, from lane 0 of its register.
  std::vector<float> value(std::int32_t v) const {
    std::vector<float> components;
    for (int c = 0; c < component_count(ir_.code[v].type); ++c)
      components.push_back(registers_[kernel_.plane_offset(v, c)]);
    return components;
  }

 private:
  // Plane `plane` of the result: component c, or part k of component c of
  // a dual (plane 4c + k).
  float* out(std::size_t instruction, int plane) { return out_planes_[first_plane_[instruction] + plane]; }
  // Plane `plane` of the first argument, laid out as out() lays out results.
  const float* first_in(std::size_t instruction, int plane) const {
    return in_planes_[first_plane_[instruction] * max_op_args + plane];
  }

  static void fill(float value, float* to, const Lanes& lanes) {
    interp::for_lanes(lanes, [&](int lane) { to[lane] = value; });
  }
  static void copy(const float* from, float* to, const Lanes& lanes) {
    interp::for_lanes(lanes, [&](int lane) { to[lane] = from[lane]; });
  }
  // d value / d P_k of the dual float `value`.
  const float* partial_plane(std::int32_t value, int k) const {
    return registers_.data() + kernel_.plane_offset(value, 0, 1 + k);
  }

  void execute(Lanes lanes, bool uniform_pass, const SampleInputs& inputs, std::size_t start) {
    region_stack_.clear();
    for (std::size_t i = 0; i < ir_.code.size(); ++i) {
      const IrInstr& instr = ir_.code[i];
      const bool marker = instr.kind == IrOpKind::begin_region || instr.kind == IrOpKind::end_region;
      if (instr.uniform != uniform_pass && !marker) continue;
      switch (instr.kind) {
        case IrOpKind::op:
          kernel_.kernels_[i](interp::InstructionPlanes{&in_planes_[first_plane_[i] * max_op_args],
                                                        &out_planes_[first_plane_[i]], &kernel_.constants_[i]},
                              lanes);
          break;
        case IrOpKind::constant:
          for (int c = 0; c < component_count(instr.type); ++c)
            fill(ir_.data[instr.data_offset + std::min(c, instr.data_count - 1)], out(i, c), lanes);
          break;
        case IrOpKind::param:
          for (int c = 0; c < component_count(instr.type); ++c) fill(params_[instr.immediate[0] + c], out(i, c), lanes);
          break;
        case IrOpKind::global: {
          const auto id = static_cast<GlobalId>(instr.immediate[0]);
          for (int c = 0; c < component_count(instr.type); ++c) {
            if (instr.uniform) {
              fill(uniforms_.get(id, c), out(i, c), lanes);
              continue;
            }
            const float* from = inputs.plane(id, c) + start;
            if (!instr.dual) {
              copy(from, out(i, c), lanes);
              continue;
            }
            // P's partials: dP_c / dP_k is 1 where k = c.
            copy(from, out(i, dual_floats * c), lanes);
            for (int k = 0; k < 3; ++k) fill(k == c ? 1.0f : 0.0f, out(i, dual_floats * c + 1 + k), lanes);
          }
          break;
        }
        case IrOpKind::extract:
          // A dual's component brings its partials.
          for (int part = 0; part < (instr.dual ? dual_floats : 1); ++part)
            copy(first_in(i, instr.dual ? dual_floats * instr.immediate[0] + part : instr.immediate[0]), out(i, part),
                 lanes);
          break;
        case IrOpKind::partials:
          for (int k = 0; k < 3; ++k) copy(partial_plane(instr.args[0], k), out(i, k), lanes);
          break;
        case IrOpKind::begin_region: {
          // Regions hold only varying code: the uniform pass skips them.
          if (uniform_pass) {
            i = static_cast<std::size_t>(instr.immediate[1]);
            break;
          }
          std::uint16_t* list = lane_lists_.data() + region_stack_.size() * block;
          const float* condition = first_in(i, 0);
          const bool want = instr.immediate[0] == 0;
          int taken = 0;
          interp::for_lanes(lanes, [&](int lane) {
            list[taken] = static_cast<std::uint16_t>(lane);
            taken += (condition[lane] != 0.0f) == want;
          });
          if (taken == 0) {
            i = static_cast<std::size_t>(instr.immediate[1]);
            break;
          }
          region_stack_.push_back(lanes);
          lanes = Lanes{list, taken, false};
          break;
        }
        case IrOpKind::end_region:
          if (uniform_pass) break;
          lanes = region_stack_.back();
          region_stack_.pop_back();
          break;
      }
    }
  }

  void write_outputs(float* const* outputs, std::size_t start, int block_count) const {
    const OutputLayout& layout = kernel_.outputs();
    for (const IrOutput& output : ir_.outputs) {
      for (int c = 0; c < component_count(output.type); ++c) {
        float* to = outputs[layout.plane(output.id, c)];
        if (!to) continue;
        std::memcpy(to + start, registers_.data() + kernel_.plane_offset(output.value, c),
                    sizeof(float) * static_cast<std::size_t>(block_count));
      }
    }
  }

  const InterpretedKernel& kernel_;
  const ShadeIR& ir_;
  std::vector<float> registers_;
  // One lane list per nesting level of regions, allocated for the deepest
  // nesting up front: a region's list must not move while inner ones open.
  std::vector<std::uint16_t> lane_lists_;
  std::vector<Lanes> region_stack_;
  std::vector<float> zeros_;  // the partials of values that do not depend on P
  // Instruction i's result planes start at out_planes_[first_plane_[i]],
  // its argument planes at in_planes_[first_plane_[i] * max_op_args].
  std::vector<std::size_t> first_plane_;
  std::vector<const float*> in_planes_;
  std::vector<float*> out_planes_;
  UniformInputs uniforms_;
  const float* params_ = nullptr;  // during binding only
};

std::unique_ptr<BoundKernel> InterpretedKernel::bind(const float* params, const UniformInputs& uniforms) const {
  return std::make_unique<InterpretedBinding>(*this, params, uniforms);
}

}  // namespace

std::vector<float> evaluate_constant_program(const ShadeIR& program) {
  InterpretedKernel kernel(program);
  InterpretedBinding binding(kernel, nullptr, UniformInputs{});
  return binding.value(static_cast<std::int32_t>(program.code.size() - 1));
}

std::unique_ptr<Kernel> make_interpreted_kernel(ShadeIR ir) {
  return std::make_unique<InterpretedKernel>(std::move(ir));
}

}  // namespace shadetree

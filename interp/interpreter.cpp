// The interpreted backend (see interpreter.h). Every ShadeIR value gets a
// register of `components` planes of one block; uniform values are
// computed once per run() call and stay in their registers, varying values
// once per block. Conditional regions narrow the lane list to the samples
// that take the branch and skip the region when none does.
#include "interp/interpreter.h"

#include <cstring>
#include <vector>

#include "interp/exec_context.h"
#include "nodes/registry.h"

namespace shadetree {
namespace {

using interp::ExecContext;
using interp::Lanes;

class InterpretedKernel final : public Kernel {
 public:
  explicit InterpretedKernel(ShadeIR ir) : ir_(std::move(ir)) {
    register_offset_.resize(ir_.code.size());
    kernels_.resize(ir_.code.size(), nullptr);
    tables_.resize(ir_.code.size(), nullptr);
    std::size_t offset = 0;
    for (std::size_t i = 0; i < ir_.code.size(); ++i) {
      const IrInstr& instr = ir_.code[i];
      register_offset_[i] = offset;
      offset += static_cast<std::size_t>(component_count(instr.type) * interpreter_block_size);
      if (instr.kind != IrOpKind::op) continue;
      kernels_[i] = interp::op_kernel(instr.op);
      if (uses_noise_tables(instr.op))
        tables_[i] = &noise_tables(static_cast<std::uint32_t>(instr.immediate[0]));
    }
    register_floats_ = offset;
  }

  const ShadeIR& ir() const override { return ir_; }

  void run(const float* params, const KernelInputs& inputs, float* const* outputs,
           std::size_t count) const override {
    std::vector<float> registers(register_floats_);
    std::vector<std::uint16_t> lane_lists;  // one block-sized list per open region
    const Lanes all{nullptr, interpreter_block_size, true};
    execute(registers.data(), params, inputs, all, /*uniform_pass=*/true, lane_lists);
    for (std::size_t start = 0; start < count; start += interpreter_block_size) {
      const int block_count = static_cast<int>(std::min<std::size_t>(interpreter_block_size, count - start));
      const KernelInputs block_inputs = inputs.advanced(start);
      execute(registers.data(), params, block_inputs, Lanes{nullptr, block_count, true}, false, lane_lists);
      write_outputs(registers.data(), outputs, start, block_count);
    }
  }

 private:
  void execute(float* registers, const float* params, const KernelInputs& inputs, Lanes lanes, bool uniform_pass,
               std::vector<std::uint16_t>& lane_lists) const {
    std::vector<Lanes> stack;
    ExecContext context{&ir_, nullptr, 0, registers, register_offset_.data(), interpreter_block_size,
                        lanes, nullptr, params, &inputs};
    for (std::size_t i = 0; i < ir_.code.size(); ++i) {
      const IrInstr& instr = ir_.code[i];
      if (instr.uniform != uniform_pass && instr.kind != IrOpKind::end_region &&
          instr.kind != IrOpKind::begin_region)
        continue;
      context.instr = &instr;
      context.self = static_cast<std::int32_t>(i);
      switch (instr.kind) {
        case IrOpKind::op:
          context.tables = tables_[i];
          kernels_[i](context);
          break;
        case IrOpKind::constant:
          for (int c = 0; c < component_count(instr.type); ++c)
            fill(ir_.data[instr.data_offset + std::min(c, instr.data_count - 1)], context.out(c), context.lanes);
          break;
        case IrOpKind::param:
          for (int c = 0; c < component_count(instr.type); ++c)
            fill(params[instr.immediate[0] + c], context.out(c), context.lanes);
          break;
        case IrOpKind::extract: {
          const float* from = context.in(0, instr.immediate[0]);
          float* to = context.out();
          interp::for_lanes(context.lanes, [&](int lane) { to[lane] = from[lane]; });
          break;
        }
        case IrOpKind::begin_region: {
          // Regions hold only varying code: the uniform pass skips them.
          if (uniform_pass) {
            i = static_cast<std::size_t>(instr.immediate[1]);
            break;
          }
          const std::size_t depth = stack.size();
          lane_lists.resize(std::max(lane_lists.size(), (depth + 1) * interpreter_block_size));
          std::uint16_t* list = lane_lists.data() + depth * interpreter_block_size;
          const float* condition = context.in(0);
          const bool want = instr.immediate[0] == 0;
          int taken = 0;
          interp::for_lanes(context.lanes, [&](int lane) {
            list[taken] = static_cast<std::uint16_t>(lane);
            taken += (condition[lane] != 0.0f) == want;
          });
          if (taken == 0) {
            i = static_cast<std::size_t>(instr.immediate[1]);
            break;
          }
          stack.push_back(context.lanes);
          context.lanes = Lanes{list, taken, false};
          break;
        }
        case IrOpKind::end_region:
          if (uniform_pass) break;
          context.lanes = stack.back();
          stack.pop_back();
          break;
      }
    }
  }

  static void fill(float value, float* to, const Lanes& lanes) {
    interp::for_lanes(lanes, [&](int lane) { to[lane] = value; });
  }

  void write_outputs(const float* registers, float* const* outputs, std::size_t start, int block_count) const {
    std::size_t plane = 0;
    for (const IrOutput& output : ir_.outputs) {
      const int produced = component_count(ir_.code[output.value].type);
      for (int c = 0; c < component_count(output.type); ++c, ++plane) {
        const float* from = registers + register_offset_[output.value] + std::min(c, produced - 1) * interpreter_block_size;
        std::memcpy(outputs[plane] + start, from, sizeof(float) * static_cast<std::size_t>(block_count));
      }
    }
  }

  ShadeIR ir_;
  std::vector<std::size_t> register_offset_;
  std::vector<interp::OpKernel> kernels_;
  std::vector<const NoiseTables*> tables_;
  std::size_t register_floats_ = 0;
};

}  // namespace

std::vector<float> evaluate_constant_program(const ShadeIR& program) {
  std::size_t planes = 0;
  for (const IrOutput& output : program.outputs) planes += static_cast<std::size_t>(component_count(output.type));
  std::vector<float> values(planes);
  std::vector<float*> pointers;
  for (float& value : values) pointers.push_back(&value);
  InterpretedKernel(program).run(nullptr, KernelInputs{}, pointers.data(), 1);
  return values;
}

std::unique_ptr<Kernel> make_interpreted_kernel(ShadeIR ir) {
  return std::make_unique<InterpretedKernel>(std::move(ir));
}

}  // namespace shadetree

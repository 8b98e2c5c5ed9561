// What an op kernel of the interpreter sees: its instruction, register
// planes for its arguments and result, and the lanes to compute.
#pragma once

#include <algorithm>
#include <cstdint>

#include "ir/kernel.h"
#include "nodes/noise_tables.h"

namespace shadetree::interp {

// The samples of a block an instruction computes: all of them (dense), or
// those listed in `index` (inside a conditional region).
struct Lanes {
  const std::uint16_t* index = nullptr;
  int count = 0;
  bool dense = true;
};

template <class Body>
inline void for_lanes(const Lanes& lanes, Body body) {
  if (lanes.dense) {
    for (int i = 0; i < lanes.count; ++i) body(i);
  } else {
    for (int k = 0; k < lanes.count; ++k) body(static_cast<int>(lanes.index[k]));
  }
}

struct ExecContext {
  const ShadeIR* ir;
  const IrInstr* instr;
  std::int32_t self;
  float* registers;
  const std::size_t* register_offset;  // value -> first float of its planes
  int block;                            // floats per plane
  Lanes lanes;
  const NoiseTables* tables;  // resolved from the seed, for noise ops
  const float* params;
  const KernelInputs* inputs;  // already advanced to this block's first sample

  // Component c of argument `arg`; scalars are read as splatted vectors.
  const float* in(int arg, int c = 0) const {
    const std::int32_t value = instr->args[arg];
    const int components = component_count(ir->code[value].type);
    return registers + register_offset[value] + std::min(c, components - 1) * block;
  }
  float* out(int c = 0) const { return registers + register_offset[self] + c * block; }
  int out_components() const { return component_count(instr->type); }
  const float* data() const { return ir->data.data() + instr->data_offset; }
};

using OpKernel = void (*)(const ExecContext&);

// The kernel of each library op, indexed by OpId.
OpKernel op_kernel(OpId op);

}  // namespace shadetree::interp

// ShadeIR: a flat, typed SSA program, the product of lowering and the input
// of every backend. Instructions are plain data in a vector; value i is the
// result of instruction i. Conditional regions (the `if` node) are
// bracketed by begin_region / end_region so that a backend can run a
// region only for the samples that take it.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "nodes/type.h"
#include "nodes/graph_kind.h"
#include "nodes/limits.h"
#include "nodes/op_id.h"
#include "nodes/output_contract.h"

namespace shadetree {

enum class IrOpKind : std::uint8_t {
  op,            // a library op: `op` says which
  constant,      // data[data_offset ..] holds one value per component
  param,         // the uniform param block, from slot `immediate[0]`
  global,        // the global immediate[0] (a GlobalId; nodes/globals.h)
  extract,       // component immediate[0] of args[0]
  begin_region,  // run until the matching end_region only where args[0] is
                 // true (immediate[0] = 0) or false (immediate[0] = 1);
                 // immediate[1] is the index of the matching end_region
  end_region,
  partials,      // the gradient, as a vec3, of args[0]: a dual float
};

struct IrInstr {
  IrOpKind kind = IrOpKind::op;
  OpId op = OpId::add;
  Type type = Type::float_;
  Type generic = Type::float_;  // the op's type variable T, where it has one
  bool uniform = false;  // depends only on params, constants and uniform globals
  // A dual instruction (ir/differentiate.h) computes its value and its
  // partial derivatives with respect to P: an op evaluated over duals, P
  // itself, or a component of a dual. Its arguments may be dual or not.
  bool dual = false;
  std::uint8_t arg_count = 0;
  std::array<std::int32_t, max_op_args> args{-1, -1, -1, -1, -1, -1};
  std::int32_t data_offset = 0;  // into ShadeIR::data
  std::int32_t data_count = 0;
  std::array<std::int32_t, 2> immediate{0, 0};
  std::string source;  // the graph node it came from, for emit and messages
};

// An output of the graph's contract (nodes/output_contract.h), converted
// to the contract's type.
struct IrOutput {
  OutputId id;
  Type type;
  std::int32_t value;
};

struct IrParam {
  std::string name;
  Type type;
  std::int32_t slot;  // first float of the param in the uniform block
};

struct ShadeIR {
  GraphKind kind = GraphKind::texture;
  std::vector<IrInstr> code;
  std::vector<float> data;
  std::vector<IrOutput> outputs;  // in contract order
  std::vector<IrParam> params;
  int param_block_size = 0;  // floats
};

// Floats per sample that value `instr` takes: its components, four times
// over for a dual (value and three partials, component by component).
int stored_components(const IrInstr& instr);

// Keeps the instructions listed in `order` (old indices, each argument
// before its users), renumbering arguments and outputs.
void reorder_shade_ir(ShadeIR& ir, const std::vector<std::int32_t>& order);

// The type argument `a` of `instr` (an op) is converted to: its declared
// type in the op's signature, with T resolved. The value it names may have
// fewer components (a scalar read splatted).
Type argument_type(const IrInstr& instr, int a);

// What `instr` computes, for a comment in generated source: its op (or
// constant, param, global, component, gradient), whether with its
// gradient, and its node, quoted by graph/generated_names.h's quoted_text.
std::string instruction_comment(const IrInstr& instr);

// A canonical text of everything `ir` computes (its instructions, their
// constants and its outputs; not the nodes they came from): two programs
// with the same text compute the same values. Caches key on it.
std::string program_key_text(const ShadeIR& ir);

// Human-readable listing, one instruction a line (shadetree emit --graph).
std::string format_shade_ir(const ShadeIR& ir);

}  // namespace shadetree

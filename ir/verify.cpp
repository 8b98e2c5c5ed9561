#include "ir/verify.h"

#include <vector>

#include "nodes/registry.h"

namespace shadetree {
namespace {

std::string at(std::size_t i) { return "%" + std::to_string(i) + ": "; }

// A value of type `from` may stand where `to` is declared: the same type,
// an implicit conversion, or a scalar read splatted.
bool fits(Type from, Type to) {
  return converts_to(from, to) || component_count(from) == 1 || component_count(from) == component_count(to);
}

std::string verify_op(const ShadeIR& ir, const IrInstr& instr, std::size_t i) {
  const OpDef& op = op_def(instr.op);
  if (instr.arg_count != op.inputs.size())
    return at(i) + op.name + " takes " + std::to_string(op.inputs.size()) + " arguments, has " +
           std::to_string(instr.arg_count);
  for (int a = 0; a < instr.arg_count; ++a) {
    const Type given = ir.code[instr.args[a]].type;
    if (!fits(given, argument_type(instr, a)))
      return at(i) + op.name + " argument " + std::to_string(a) + " is " + std::string(type_name(given)) +
             ", declared " + std::string(type_name(argument_type(instr, a)));
  }
  const PortSpec& result = op.outputs[0];
  const Type declared = result.rule == TypeRule::generic ? instr.generic : result.type;
  if (instr.type != declared)
    return at(i) + op.name + " returns " + std::string(type_name(declared)) + ", typed " +
           std::string(type_name(instr.type));
  return "";
}

// Dual instructions: varying values of floats, made only of ops, P and
// components of duals, at least one argument of which is dual.
std::string verify_dual(const ShadeIR& ir, const IrInstr& instr, std::size_t i) {
  if (!instr.dual) return "";
  if (instr.uniform || instr.type == Type::int_ || instr.type == Type::bool_)
    return at(i) + "a dual that is uniform or not made of floats";
  bool reads_dual = false;
  for (int a = 0; a < instr.arg_count; ++a) reads_dual = reads_dual || ir.code[instr.args[a]].dual;
  const bool is_p = instr.kind == IrOpKind::global && instr.immediate[0] == static_cast<int>(GlobalId::P);
  if (!is_p && !((instr.kind == IrOpKind::op || instr.kind == IrOpKind::extract) && reads_dual))
    return at(i) + "a dual that is neither P nor computed from a dual";
  return "";
}

std::string verify_instruction(const ShadeIR& ir, const IrInstr& instr, std::size_t i) {
  if (instr.arg_count > max_op_args) return at(i) + "too many arguments";
  for (int a = 0; a < instr.arg_count; ++a) {
    if (instr.args[a] < 0 || static_cast<std::size_t>(instr.args[a]) >= i)
      return at(i) + "argument " + std::to_string(a) + " (%" + std::to_string(instr.args[a]) +
             ") does not precede its user";
    const IrInstr& argument = ir.code[instr.args[a]];
    if (argument.kind == IrOpKind::begin_region || argument.kind == IrOpKind::end_region)
      return at(i) + "argument " + std::to_string(a) + " is a region marker";
    if (instr.uniform && !argument.uniform && instr.kind != IrOpKind::begin_region)
      return at(i) + "uniform, but reads the varying %" + std::to_string(instr.args[a]);
    if (argument.dual && !instr.dual && instr.kind != IrOpKind::partials)
      return at(i) + "reads the dual %" + std::to_string(instr.args[a]) + " but is not dual";
  }
  if (std::string problem = verify_dual(ir, instr, i); !problem.empty()) return problem;
  switch (instr.kind) {
    case IrOpKind::op: return verify_op(ir, instr, i);
    case IrOpKind::constant:
      if (instr.data_count != 1 && instr.data_count != component_count(instr.type))
        return at(i) + "constant with " + std::to_string(instr.data_count) + " values for " +
               std::string(type_name(instr.type));
      break;
    case IrOpKind::param:
      if (instr.immediate[0] < 0 || instr.immediate[0] + component_count(instr.type) > ir.param_block_size)
        return at(i) + "param slot outside the uniform block";
      break;
    case IrOpKind::global: {
      if (instr.immediate[0] < 0 || instr.immediate[0] >= global_count) return at(i) + "unknown global";
      const GlobalDef& global = global_def(static_cast<GlobalId>(instr.immediate[0]));
      if (instr.type != global.type || instr.uniform != (global.variability == Variability::uniform))
        return at(i) + "global " + std::string(global.name) + " with the wrong type or variability";
      break;
    }
    case IrOpKind::extract:
      if (instr.arg_count != 1 || instr.immediate[0] < 0 ||
          instr.immediate[0] >= component_count(ir.code[instr.args[0]].type))
        return at(i) + "extract of a component the value does not have";
      break;
    case IrOpKind::begin_region:
      if (instr.arg_count != 1 || ir.code[instr.args[0]].type != Type::bool_)
        return at(i) + "a region needs one bool condition";
      if (instr.uniform) return at(i) + "a region marker marked uniform";
      break;
    case IrOpKind::end_region: break;
    case IrOpKind::partials:
      if (instr.arg_count != 1 || !ir.code[instr.args[0]].dual || ir.code[instr.args[0]].type != Type::float_ ||
          instr.type != Type::vec3 || instr.dual)
        return at(i) + "partials of something other than a dual float";
      break;
  }
  if (instr.data_offset < 0 || instr.data_count < 0 ||
      static_cast<std::size_t>(instr.data_offset) + static_cast<std::size_t>(instr.data_count) > ir.data.size())
    return at(i) + "data outside the program's data";
  return "";
}

}  // namespace

std::string verify_shade_ir(const ShadeIR& ir) {
  std::vector<std::size_t> open_regions;
  for (std::size_t i = 0; i < ir.code.size(); ++i) {
    const IrInstr& instr = ir.code[i];
    if (std::string problem = verify_instruction(ir, instr, i); !problem.empty()) return problem;
    if (instr.kind == IrOpKind::begin_region) open_regions.push_back(i);
    if (instr.kind == IrOpKind::end_region) {
      if (open_regions.empty()) return at(i) + "end_region without a region";
      const IrInstr& begin = ir.code[open_regions.back()];
      if (begin.immediate[1] != static_cast<std::int32_t>(i))
        return at(open_regions.back()) + "region ends at %" + std::to_string(i) + ", not %" +
               std::to_string(begin.immediate[1]);
      open_regions.pop_back();
    }
    if (!open_regions.empty() && instr.uniform) return at(i) + "uniform code inside a region";
  }
  if (!open_regions.empty()) return at(open_regions.back()) + "region never ends";
  const auto contract = output_contract(ir.kind);
  std::size_t next = 0;
  for (const IrOutput& output : ir.outputs) {
    if (output.value < 0 || static_cast<std::size_t>(output.value) >= ir.code.size() ||
        ir.code[output.value].dual)
      return "output " + std::string(output_id_name(output.id)) + " names no plain value";
    while (next < contract.size() && contract[next].id != output.id) ++next;
    if (next == contract.size())
      return "output " + std::string(output_id_name(output.id)) + " is not (in this order) in the contract of " +
             std::string(graph_kind_name(ir.kind)) + " graphs";
    if (output.type != contract[next].type) return "output " + std::string(contract[next].name) + " has the wrong type";
    ++next;
  }
  return "";
}

}  // namespace shadetree

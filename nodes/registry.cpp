// The op table, generated from the op list: one input op per global, then
// each library op's definition from nodes/ops/, at the place the list
// gives it (so its OpId indexes the table).
#include "nodes/registry.h"

#include "nodes/op_definition.h"
#include "nodes/ops/all.h"

namespace shadetree {
namespace {

OpDef input_op(const GlobalDef& global) {
  return {.name = std::string(global.name), .family = OpFamily::input, .doc = std::string(global.doc),
          .outputs = {define::out(global.type)}, .kinds = global.kinds};
}

template <class Op>
OpDef definition_of() {
  OpDef definition = Op::definition();
  if constexpr (requires { &Op::lay_out; }) definition.lay_out = &Op::lay_out;
  return definition;
}

std::vector<OpDef> make_ops() {
  std::vector<OpDef> ops;
  for (const GlobalDef& global : globals) ops.push_back(input_op(global));
#define SHADETREE_DEFINITION(name) ops.push_back(definition_of<ops::name>());
  SHADETREE_LIBRARY_OPS(SHADETREE_DEFINITION)
#undef SHADETREE_DEFINITION
  for (std::size_t i = 0; i < ops.size(); ++i) ops[i].id = static_cast<OpId>(i);
  return ops;
}

constexpr const char* symbols[] = {
#define SHADETREE_GLOBAL_SYMBOL(name, type, variability, kinds, doc) #name,
    SHADETREE_GLOBALS(SHADETREE_GLOBAL_SYMBOL)
#undef SHADETREE_GLOBAL_SYMBOL
#define SHADETREE_SYMBOL(name) #name,
    SHADETREE_LIBRARY_OPS(SHADETREE_SYMBOL)
#undef SHADETREE_SYMBOL
};
static_assert(std::size(symbols) == op_count);

}  // namespace

std::span<const OpDef> all_ops() {
  static const std::vector<OpDef> ops = make_ops();
  return ops;
}

const OpDef& op_def(OpId id) { return all_ops()[static_cast<std::size_t>(id)]; }

const char* op_symbol(OpId id) { return symbols[static_cast<std::size_t>(id)]; }

const OpDef* find_op(std::string_view name) {
  for (const OpDef& op : all_ops())
    if (op.name == name) return &op;
  return nullptr;
}

std::optional<GlobalId> global_of(OpId id) {
  if (static_cast<int>(id) >= global_count) return std::nullopt;
  return static_cast<GlobalId>(id);
}

std::string_view family_name(OpFamily family) {
  switch (family) {
    case OpFamily::input: return "inputs";
    case OpFamily::generator: return "generators";
    case OpFamily::arithmetic: return "arithmetic";
    case OpFamily::vector: return "vectors";
    case OpFamily::conditional: return "conditionals";
    case OpFamily::spline: return "splines and tables";
    case OpFamily::soft_object: return "soft objects";
    case OpFamily::derivative: return "derivatives";
  }
  return "?";
}

}  // namespace shadetree

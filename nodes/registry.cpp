#include "nodes/registry.h"

namespace shadetree {

const OpDef& op_def(OpId id) { return all_ops()[static_cast<std::size_t>(id)]; }

const OpDef* find_op(std::string_view name) {
  for (const OpDef& op : all_ops())
    if (op.name == name) return &op;
  return nullptr;
}

bool uses_noise_tables(OpId id) {
  return id == OpId::noise || id == OpId::dnoise || id == OpId::vnoise || id == OpId::turbulence || id == OpId::fbm;
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
  }
  return "?";
}

}  // namespace shadetree

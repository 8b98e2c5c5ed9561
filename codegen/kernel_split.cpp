#include "codegen/kernel_split.h"

#include <algorithm>

#include "codegen/op_library.h"

namespace shadetree {

namespace {

// What instruction `instr` costs the kernel's compile: its op's library
// instructions that its constant arguments do not fold away, or one for
// data movement.
unsigned weight(const ShadeIR& ir, const IrInstr& instr, int width) {
  if (instr.kind != IrOpKind::op) return 1;
  unsigned unknown = 0;
  for (int a = 0; a < instr.arg_count; ++a)
    if (ir.code[instr.args[a]].kind != IrOpKind::constant) unknown |= 1u << a;
  return std::max(1u, op_library_instructions(op_library_symbol(instr.op, instr.dual, width), width, unknown));
}

// Whether value `instr` reaches the second part through scratch: constants
// are emitted in both parts, uniform values read from the state block by
// both, and region markers are no values.
bool may_cross(const IrInstr& instr) {
  return !instr.uniform && instr.kind != IrOpKind::constant && instr.kind != IrOpKind::begin_region &&
         instr.kind != IrOpKind::end_region;
}

}  // namespace

std::optional<KernelSplit> kernel_split(const ShadeIR& ir, int width) {
  const int count = static_cast<int>(ir.code.size());
  std::vector<unsigned> before(static_cast<std::size_t>(count) + 1, 0);  // weight of the varying code before i
  for (int i = 0; i < count; ++i)
    before[i + 1] = before[i] + (ir.code[i].uniform ? 0 : weight(ir, ir.code[i], width));
  const unsigned total = before[count];
  if (total < split_threshold) return std::nullopt;

  // The last reader of each value (count: an output).
  std::vector<int> last_use(static_cast<std::size_t>(count), -1);
  for (int i = 0; i < count; ++i)
    for (int a = 0; a < ir.code[i].arg_count; ++a) last_use[ir.code[i].args[a]] = i;
  for (const IrOutput& output : ir.outputs) last_use[output.value] = count;
  // Stored components of the crossing values ending before each cut.
  std::vector<int> ending(static_cast<std::size_t>(count) + 2, 0);
  for (int v = 0; v < count; ++v)
    if (may_cross(ir.code[v]) && last_use[v] > v) ending[last_use[v] + 1] += stored_components(ir.code[v]);

  // A cut before instruction c: outside every region, the first part
  // holding between a quarter and three quarters of the weight. Of those, the
  // one whose larger part, with the crossing values' stores and loads,
  // weighs least: the two threads finish together.
  std::optional<int> best;
  unsigned best_cost = 0;
  int best_vectors = 0;
  int live = 0, depth = 0;
  for (int c = 0; c < count; ++c) {
    live -= ending[c];
    if (c > 0 && may_cross(ir.code[c - 1]) && last_use[c - 1] >= c) live += stored_components(ir.code[c - 1]);
    const IrInstr& instr = ir.code[c];
    const bool at_top = depth == 0 && !instr.uniform && instr.kind != IrOpKind::end_region;
    if (!instr.uniform && instr.kind == IrOpKind::begin_region) ++depth;
    if (!instr.uniform && instr.kind == IrOpKind::end_region) --depth;
    if (!at_top || live > max_crossing_vectors || 4 * before[c] < total || 4 * before[c] > 3 * total) continue;
    const unsigned cost = std::max(before[c], total - before[c]) + crossing_vector_weight * static_cast<unsigned>(live);
    if (!best || cost < best_cost) {
      best = c;
      best_cost = cost;
      best_vectors = live;
    }
  }
  if (!best) return std::nullopt;
  KernelSplit split{.cut = *best, .crossing = {}, .crossing_vectors = best_vectors};
  for (int v = 0; v < split.cut; ++v)
    if (may_cross(ir.code[v]) && last_use[v] >= split.cut) split.crossing.push_back(v);
  return split;
}

}  // namespace shadetree

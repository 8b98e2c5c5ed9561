// Conditional region placement. The `if` node promises that each branch is
// evaluated only for the samples that take it (like the T-code conditionals
// that disable pixel processors, Rhoades et al. 1992). An instruction
// belongs to the innermost region that contains all of its uses: a value
// used by the `then` input of an if (and nowhere else) belongs to that if's
// then-region; a value used in two places belongs to their lowest common
// region. Uniform values stay outside all regions: they are computed once
// per call anyway. Regions are then scheduled as contiguous blocks,
// bracketed by begin_region / end_region, right before their `if`.
#include "ir/passes/place_conditional_regions.h"


namespace shadetree {
namespace {

struct RegionTree {
  std::vector<int> parent{-1};
  std::vector<int> depth{0};

  int add(int parent_region) {
    parent.push_back(parent_region);
    depth.push_back(depth[parent_region] + 1);
    return static_cast<int>(parent.size() - 1);
  }

  int common(int a, int b) const {
    if (a < 0) return b;
    while (depth[a] > depth[b]) a = parent[a];
    while (depth[b] > depth[a]) b = parent[b];
    while (a != b) {
      a = parent[a];
      b = parent[b];
    }
    return a;
  }
};

bool is_if(const IrInstr& instr) { return instr.kind == IrOpKind::op && instr.op == OpId::if_; }

}  // namespace

void place_conditional_regions(ShadeIR& ir) {
  const std::size_t count = ir.code.size();
  bool any_if = false;
  for (const IrInstr& instr : ir.code) any_if |= is_if(instr);
  if (!any_if) return;

  std::vector<std::vector<std::pair<int, int>>> uses(count);  // (user, argument slot)
  for (std::size_t u = 0; u < count; ++u)
    for (int a = 0; a < ir.code[u].arg_count; ++a) uses[ir.code[u].args[a]].push_back({static_cast<int>(u), a});
  std::vector<bool> is_output(count, false);
  for (const IrOutput& output : ir.outputs) is_output[output.value] = true;

  RegionTree tree;
  std::vector<int> region(count, 0);
  std::vector<int> then_region(count, -1), else_region(count, -1);
  for (std::size_t v = count; v-- > 0;) {
    const IrInstr& instr = ir.code[v];
    int placed = -1;
    if (is_output[v] || instr.uniform || uses[v].empty()) placed = 0;
    for (auto [user, slot] : uses[v]) {
      int use_region = region[user];
      if (is_if(ir.code[user]) && slot == 1) use_region = then_region[user];
      if (is_if(ir.code[user]) && slot == 2) use_region = else_region[user];
      placed = tree.common(placed, use_region);
    }
    region[v] = placed;
    if (is_if(instr)) {
      then_region[v] = tree.add(placed);
      else_region[v] = tree.add(placed);
    }
  }

  std::vector<std::vector<int>> members(tree.parent.size());
  for (std::size_t v = 0; v < count; ++v) members[region[v]].push_back(static_cast<int>(v));

  // New program: old instruction indices, with -1 / -2 marking where a
  // region begins / ends (the if and branch they belong to alongside).
  struct Slot {
    int old_index;
    int owner_if = -1;
    bool else_branch = false;
  };
  std::vector<Slot> schedule;
  // Walks the region tree with its own stack, since ifs may nest deeply.
  // A frame is a region, the member reached, and for an if member how many
  // of its two branches have been opened.
  struct Frame {
    int region;
    std::size_t member = 0;
    int branches_opened = 0;
  };
  std::vector<Frame> stack{{0}};
  while (!stack.empty()) {
    Frame& frame = stack.back();
    if (frame.member == members[frame.region].size()) {
      stack.pop_back();
      if (stack.empty()) break;
      const Frame& parent = stack.back();
      schedule.push_back({-2, members[parent.region][parent.member], parent.branches_opened == 2});
      continue;
    }
    const int v = members[frame.region][frame.member];
    if (is_if(ir.code[v]) && frame.branches_opened < 2) {
      const bool else_branch = frame.branches_opened++ == 1;
      const int branch = else_branch ? else_region[v] : then_region[v];
      if (!members[branch].empty()) {
        schedule.push_back({-1, v, else_branch});
        stack.push_back({branch});
      }
      continue;
    }
    schedule.push_back({v});
    ++frame.member;
    frame.branches_opened = 0;
  }

  std::vector<std::int32_t> new_index(count, -1);
  for (std::size_t s = 0; s < schedule.size(); ++s)
    if (schedule[s].old_index >= 0) new_index[schedule[s].old_index] = static_cast<std::int32_t>(s);
  std::vector<IrInstr> code;
  std::vector<std::size_t> open_regions;
  for (const Slot& slot : schedule) {
    if (slot.old_index >= 0) {
      IrInstr instr = ir.code[slot.old_index];
      for (int a = 0; a < instr.arg_count; ++a) instr.args[a] = new_index[instr.args[a]];
      code.push_back(std::move(instr));
      continue;
    }
    IrInstr marker;
    marker.source = ir.code[slot.owner_if].source;
    if (slot.old_index == -1) {
      marker.kind = IrOpKind::begin_region;
      marker.type = Type::bool_;
      marker.arg_count = 1;
      marker.args[0] = new_index[ir.code[slot.owner_if].args[0]];
      marker.immediate[0] = slot.else_branch ? 1 : 0;
      open_regions.push_back(code.size());
    } else {
      marker.kind = IrOpKind::end_region;
      code[open_regions.back()].immediate[1] = static_cast<std::int32_t>(code.size());
      open_regions.pop_back();
    }
    code.push_back(std::move(marker));
  }
  for (IrOutput& output : ir.outputs) output.value = new_index[output.value];
  ir.code = std::move(code);
}

}  // namespace shadetree

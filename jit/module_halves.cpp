#include "jit/module_halves.h"

#include <algorithm>
#include <string>
#include <vector>

#include <llvm/ADT/DenseMap.h>
#include <llvm/ADT/SmallPtrSet.h>
#include <llvm/Analysis/LoopInfo.h>
#include <llvm/Bitcode/BitcodeReader.h>
#include <llvm/Bitcode/BitcodeWriter.h>
#include <llvm/IR/Constants.h>
#include <llvm/IR/DataLayout.h>
#include <llvm/IR/Dominators.h>
#include <llvm/IR/Function.h>
#include <llvm/IR/GlobalVariable.h>
#include <llvm/IR/Instructions.h>
#include <llvm/IR/Module.h>
#include <llvm/Support/MemoryBufferRef.h>
#include <llvm/Support/raw_ostream.h>
#include <llvm/Transforms/Utils/Cloning.h>
#include <llvm/Transforms/Utils/CodeExtractor.h>
#include <llvm/Transforms/Utils/ValueMapper.h>

namespace shadetree {

namespace {

// Instructions of the module's function definitions.
unsigned instruction_count(const llvm::Module& module) {
  unsigned count = 0;
  for (const llvm::Function& function : module) count += function.getInstructionCount();
  return count;
}

// What an instruction costs the code generator, in ordinary instructions.
// X86's shuffle combiner searches each chain of shuffles for a shorter
// one, and a noise's knot rows are transposed by chains of three: the
// fireball's octave block, cut into halves of equal counts, gave the half
// with its row loads and transposes (288 shuffles of 1117 instructions)
// 31 ms of code generation and the rest (1028) 13 ms; a shuffle counted
// twice, 21-23 ms each. Counted three times or more, looping_turbulence's
// rest became the longer part (docs/architecture.md).
constexpr unsigned shuffle_cost = 2;

unsigned generation_cost(const llvm::Instruction& instr) {
  return llvm::isa<llvm::ShuffleVectorInst>(instr) ? shuffle_cost : 1;
}

unsigned generation_cost(const llvm::BasicBlock& block) {
  unsigned cost = 0;
  for (const llvm::Instruction& instr : block) cost += generation_cost(instr);
  return cost;
}

unsigned generation_cost(const llvm::Module& module) {
  unsigned cost = 0;
  for (const llvm::Function& function : module)
    for (const llvm::BasicBlock& block : function) cost += generation_cost(block);
  return cost;
}

// The module's longest basic block.
llvm::BasicBlock* longest_block(llvm::Module& module) {
  llvm::BasicBlock* longest = nullptr;
  for (llvm::Function& function : module)
    for (llvm::BasicBlock& block : function)
      if (!longest || block.size() > longest->size()) longest = &block;
  return longest;
}

// Whether a region of code generation cost `weight`, moved out of a module
// of `total`, leaves the two halves balanced enough to be worth a thread.
bool balanced(unsigned weight, unsigned total) { return 10 * weight >= 3 * total && 10 * weight <= 7 * total; }

// The blocks of a stretch of the function's outermost loop (the sample
// loop, or a split kernel's chunk loop) that every iteration runs through
// from its first block to its last, with the inner loops and conditional
// blocks between: the first listed is its only entry. Of such stretches,
// the one whose code generation cost comes closest to `target`, within
// the balance of `total`; nothing if none is.
std::vector<llvm::BasicBlock*> loop_stretch(llvm::Function& function, unsigned target, unsigned total) {
  llvm::DominatorTree dominators(function);
  llvm::LoopInfo loops(dominators);
  std::vector<llvm::BasicBlock*> best;
  unsigned best_distance = 0;
  for (llvm::Loop* loop : loops) {
    llvm::BasicBlock* latch = loop->getLoopLatch();
    if (!latch) continue;
    // The spine: the loop's own blocks that dominate its latch, in the
    // order an iteration runs them.
    std::vector<llvm::BasicBlock*> spine;
    for (llvm::BasicBlock* block : loop->blocks())
      if (loops.getLoopFor(block) == loop && dominators.dominates(block, latch)) spine.push_back(block);
    std::sort(spine.begin(), spine.end(), [&](llvm::BasicBlock* a, llvm::BasicBlock* b) {
      return dominators.getNode(a)->getLevel() < dominators.getNode(b)->getLevel();
    });
    // Each block of the loop belongs to the last spine block dominating it.
    std::vector<unsigned> weight(spine.size(), 0);
    std::vector<std::vector<llvm::BasicBlock*>> owned(spine.size());
    for (llvm::BasicBlock* block : loop->blocks())
      for (std::size_t s = spine.size(); s-- > 0;)
        if (dominators.dominates(spine[s], block)) {
          weight[s] += generation_cost(*block);
          owned[s].push_back(block);
          break;
        }
    // Stretches from spine block i up to, not including, spine block j;
    // never the header (the loop's PHIs) nor the latch (its exit branch).
    for (std::size_t i = 1; i + 1 < spine.size(); ++i) {
      unsigned stretch = 0;
      for (std::size_t j = i + 1; j < spine.size(); ++j) {
        stretch += weight[j - 1];
        const unsigned distance = stretch > target ? stretch - target : target - stretch;
        if (!balanced(stretch, total) || (!best.empty() && distance >= best_distance)) continue;
        best.clear();
        for (std::size_t s = i; s < j; ++s) {
          std::vector<llvm::BasicBlock*> blocks = owned[s];
          std::stable_partition(blocks.begin(), blocks.end(), [&](llvm::BasicBlock* b) { return b == spine[s]; });
          best.insert(best.end(), blocks.begin(), blocks.end());
        }
        best_distance = distance;
      }
    }
  }
  return best;
}

// Where to cut `block` (an index into its instructions after its PHIs)
// so that its first part costs about `target` to generate: within a
// tenth of the block of it, where the fewest values of the first part are
// still to be read, so that little goes out through memory. Nothing if
// the block is too short.
std::optional<std::size_t> cut_position(llvm::BasicBlock& block, unsigned target) {
  std::vector<llvm::Instruction*> body;
  llvm::DenseMap<const llvm::Instruction*, std::size_t> position;
  for (llvm::Instruction& instr : block)
    if (!llvm::isa<llvm::PHINode>(instr) && !instr.isTerminator()) {
      position[&instr] = body.size();
      body.push_back(&instr);
    }
  const std::size_t count = body.size();
  if (count < min_block_to_halve) return std::nullopt;
  // cost_before[i]: what the first i instructions cost to generate.
  std::vector<std::size_t> cost_before(count + 1, 0);
  for (std::size_t i = 0; i < count; ++i) cost_before[i + 1] = cost_before[i] + generation_cost(*body[i]);
  const std::size_t cost = cost_before[count];
  const std::size_t aim =
      std::lower_bound(cost_before.begin(), cost_before.end(), std::clamp<std::size_t>(target, cost / 3, 5 * cost / 6)) -
      cost_before.begin();
  // The last reader of each value (count: after the block or its branch),
  // and how many values are last read at each position.
  std::vector<std::size_t> last_read(count);
  std::vector<int> last_reads_at(count + 1, 0);
  for (std::size_t i = 0; i < count; ++i) {
    last_read[i] = i;
    for (const llvm::User* user : body[i]->users()) {
      auto found = position.find(llvm::cast<llvm::Instruction>(user));
      last_read[i] = std::max(last_read[i], found == position.end() ? count : found->second);
    }
    if (last_read[i] > i) ++last_reads_at[last_read[i]];
  }
  std::optional<std::size_t> best;
  int best_live = 0;
  int live = 0;  // values before position c read at c or later
  for (std::size_t c = 1; c < count; ++c) {
    live += (last_read[c - 1] >= c ? 1 : 0) - last_reads_at[c - 1];
    if (10 * (c > aim ? c - aim : aim - c) > count) continue;
    if (!best || live < best_live) {
      best = c;
      best_live = live;
    }
  }
  return best;
}

// The first part of the module's longest block, cut off as a block of its
// own, to cost about `target` to generate; nothing if it is too short.
std::vector<llvm::BasicBlock*> block_part(llvm::Module& module, unsigned target) {
  llvm::BasicBlock* block = longest_block(module);
  if (!block) return {};
  const std::optional<std::size_t> cut = cut_position(*block, target);
  if (!cut) return {};
  llvm::Instruction* first = block->getFirstNonPHI();
  llvm::Instruction* after = first;
  for (std::size_t i = 0; i < *cut; ++i) after = after->getNextNode();
  // Should the part not be extracted after all, the code generator merges
  // the blocks again.
  llvm::BasicBlock* part = block->splitBasicBlock(first, "half");
  part->splitBasicBlock(after, "after_half");
  return {part};
}

// Addresses at constant offsets into the stack (GEPs of an alloca with
// constant indices, which LICM hoists out of the loops) that `region`
// reads, recomputed at its entry: passed in, each would be an argument of
// the half, and a noise's knot-row slots are a hundred of them.
void recompute_stack_addresses(const std::vector<llvm::BasicBlock*>& region) {
  const llvm::SmallPtrSet<const llvm::BasicBlock*, 32> inside(region.begin(), region.end());
  llvm::DenseMap<llvm::GetElementPtrInst*, llvm::Instruction*> copies;
  llvm::Instruction* entry = &*region.front()->getFirstInsertionPt();
  for (llvm::BasicBlock* block : region)
    for (llvm::Instruction& instr : *block)
      for (llvm::Use& use : instr.operands()) {
        if (llvm::isa<llvm::PHINode>(instr)) break;  // its values come from the edges in
        auto* address = llvm::dyn_cast<llvm::GetElementPtrInst>(use.get());
        if (!address || inside.contains(address->getParent()) || !address->hasAllConstantIndices() ||
            !llvm::isa<llvm::AllocaInst>(address->getPointerOperand()))
          continue;
        llvm::Instruction*& copy = copies[address];
        if (!copy) {
          copy = address->clone();
          copy->insertBefore(entry);
        }
        use.set(copy);
      }
  for (auto& [address, copy] : copies)
    if (address->use_empty()) address->eraseFromParent();
}

// `function` and the functions and globals it uses, directly or through
// the functions it calls.
llvm::SmallPtrSet<const llvm::GlobalValue*, 16> used_by(const llvm::Function& function) {
  llvm::SmallPtrSet<const llvm::GlobalValue*, 16> used{&function};
  llvm::SmallPtrSet<const llvm::Constant*, 32> seen;
  std::vector<const llvm::Value*> pending;
  for (const llvm::Function* next = &function; next;) {
    for (const llvm::BasicBlock& block : *next)
      for (const llvm::Instruction& instr : block)
        for (const llvm::Value* operand : instr.operands()) pending.push_back(operand);
    next = nullptr;
    while (!pending.empty() && !next) {
      const auto* constant = llvm::dyn_cast<llvm::Constant>(pending.back());
      pending.pop_back();
      if (!constant || !seen.insert(constant).second) continue;
      if (const auto* global = llvm::dyn_cast<llvm::GlobalValue>(constant)) {
        used.insert(global);
        if (const auto* callee = llvm::dyn_cast<llvm::Function>(global); callee && !callee->isDeclaration())
          next = callee;
        else if (const auto* variable = llvm::dyn_cast<llvm::GlobalVariable>(global); variable && variable->hasInitializer())
          pending.push_back(variable->getInitializer());
        continue;
      }
      for (const llvm::Value* operand : constant->operands()) pending.push_back(operand);
    }
  }
  return used;
}

// Removes what nothing in `module` uses any more: functions and globals
// that are not exported.
void drop_unused(llvm::Module& module) {
  for (bool dropped = true; dropped;) {
    dropped = false;
    for (llvm::GlobalValue& value : llvm::make_early_inc_range(module.global_values())) {
      value.removeDeadConstantUsers();
      if (value.use_empty() && (value.hasLocalLinkage() || value.isDeclaration())) {
        value.eraseFromParent();
        dropped = true;
      }
    }
  }
}

}  // namespace

std::optional<llvm::SmallVector<char, 0>> split_off_half(llvm::Module& module, const std::string& half_name) {
  if (instruction_count(module) < min_instructions_to_halve) return std::nullopt;
  const unsigned total = generation_cost(module);
  llvm::Function* largest = nullptr;
  for (llvm::Function& function : module)
    if (!largest || function.getInstructionCount() > largest->getInstructionCount()) largest = &function;
  std::vector<llvm::BasicBlock*> region = loop_stretch(*largest, total / 2, total);
  if (region.empty()) region = block_part(module, total / 2);
  if (region.empty()) return std::nullopt;
  llvm::Function& function = *region.front()->getParent();
  recompute_stack_addresses(region);
  const llvm::CodeExtractorAnalysisCache analyses(function);
  llvm::CodeExtractor extractor(region);
  if (!extractor.isEligible()) return std::nullopt;
  llvm::Function* extracted = extractor.extractCodeRegion(analyses);
  if (!extracted) return std::nullopt;
  extracted->setName(half_name);
  extracted->setLinkage(llvm::GlobalValue::ExternalLinkage);
  // The half's module: the half, the functions it calls and the tables it
  // reads, copied (their addresses fold into its instructions). Large data
  // (a graph's image or mesh) is only declared by the kernel's modules
  // (codegen/emit_kernel.h), so the half declares it too.
  const llvm::SmallPtrSet<const llvm::GlobalValue*, 16> used = used_by(*extracted);
  llvm::ValueToValueMapTy copies;
  std::unique_ptr<llvm::Module> half = llvm::CloneModule(module, copies, [&](const llvm::GlobalValue* value) {
    return value == extracted || (used.contains(value) && value->hasLocalLinkage());
  });
  drop_unused(*half);
  llvm::SmallVector<char, 0> bitcode;
  llvm::raw_svector_ostream stream(bitcode);
  llvm::WriteBitcodeToFile(*half, stream);
  extracted->deleteBody();
  drop_unused(module);
  return bitcode;
}

Result<std::unique_ptr<llvm::Module>> half_module(llvm::StringRef bitcode, const std::string& half_name,
                                                  llvm::LLVMContext& context) {
  llvm::Expected<std::unique_ptr<llvm::Module>> module =
      llvm::parseBitcodeFile(llvm::MemoryBufferRef(bitcode, half_name), context);
  if (!module) {
    std::string text;
    llvm::handleAllErrors(module.takeError(), [&](const llvm::ErrorInfoBase& info) { text = info.message(); });
    return failure("JIT: the kernel's second half: " + text);
  }
  return std::move(*module);
}

}  // namespace shadetree

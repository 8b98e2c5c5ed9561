#include "jit/module_halves.h"

#include <algorithm>
#include <vector>

#include <llvm/ADT/DenseMap.h>
#include <llvm/Bitcode/BitcodeReader.h>
#include <llvm/Bitcode/BitcodeWriter.h>
#include <llvm/IR/Constants.h>
#include <llvm/IR/Function.h>
#include <llvm/IR/GlobalVariable.h>
#include <llvm/IR/Instructions.h>
#include <llvm/IR/Module.h>
#include <llvm/Support/MemoryBufferRef.h>
#include <llvm/Support/raw_ostream.h>
#include <llvm/Transforms/Utils/CodeExtractor.h>

namespace shadetree {

namespace {

// The module's longest basic block.
llvm::BasicBlock* longest_block(llvm::Module& module) {
  llvm::BasicBlock* longest = nullptr;
  for (llvm::Function& function : module)
    for (llvm::BasicBlock& block : function)
      if (!longest || block.size() > longest->size()) longest = &block;
  return longest;
}

// Where to cut `block` (an index into its instructions after its PHIs):
// within its middle third, where the fewest values of the first half are
// still to be read, so that little goes out through memory. Nothing if the
// block is too short.
std::optional<std::size_t> cut_position(llvm::BasicBlock& block) {
  std::vector<llvm::Instruction*> body;
  llvm::DenseMap<const llvm::Instruction*, std::size_t> position;
  for (llvm::Instruction& instr : block)
    if (!llvm::isa<llvm::PHINode>(instr) && !instr.isTerminator()) {
      position[&instr] = body.size();
      body.push_back(&instr);
    }
  const std::size_t count = body.size();
  if (count < min_block_to_halve) return std::nullopt;
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
    if (3 * c < count || 3 * c > 2 * count) continue;
    if (!best || live < best_live) {
      best = c;
      best_live = live;
    }
  }
  return best;
}

// Whether the half may be compiled apart: every global it can reach is a
// constant, so the copy in each module reads the same.
bool reads_only_constants(const llvm::Module& module) {
  for (const llvm::GlobalVariable& global : module.globals())
    if (!global.isConstant()) return false;
  return true;
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
  if (!reads_only_constants(module)) return std::nullopt;
  llvm::BasicBlock* block = longest_block(module);
  if (!block) return std::nullopt;
  const std::optional<std::size_t> cut = cut_position(*block);
  if (!cut) return std::nullopt;
  llvm::Instruction* first = block->getFirstNonPHI();
  llvm::Instruction* after = first;
  for (std::size_t i = 0; i < *cut; ++i) after = after->getNextNode();
  // Split blocks that end up not extracted are merged again by the code
  // generator.
  llvm::BasicBlock* half = block->splitBasicBlock(first, "half");
  half->splitBasicBlock(after, "after_half");
  llvm::Function& function = *block->getParent();
  const llvm::CodeExtractorAnalysisCache analyses(function);
  const llvm::SmallVector<llvm::BasicBlock*, 1> region{half};
  llvm::CodeExtractor extractor(region);
  if (!extractor.isEligible()) return std::nullopt;
  llvm::Function* extracted = extractor.extractCodeRegion(analyses);
  if (!extracted) return std::nullopt;
  extracted->setName(half_name);
  extracted->setLinkage(llvm::GlobalValue::ExternalLinkage);
  llvm::SmallVector<char, 0> bitcode;
  llvm::raw_svector_ostream stream(bitcode);
  llvm::WriteBitcodeToFile(module, stream);
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
  // Everything but the half is kept only where the half calls it.
  for (llvm::Function& function : **module)
    if (!function.isDeclaration() && function.getName() != half_name)
      function.setLinkage(llvm::GlobalValue::InternalLinkage);
  drop_unused(**module);
  return std::move(*module);
}

}  // namespace shadetree

#include "jit/library_inliner.h"

#include <algorithm>
#include <map>
#include <vector>

#include <llvm/Analysis/InlineCost.h>
#include <llvm/IR/InstIterator.h>
#include <llvm/IR/Instructions.h>
#include <llvm/IR/Module.h>
#include <llvm/Transforms/Utils/Cloning.h>

namespace shadetree {

namespace {

// Whether `call` calls an always_inline function that can be inlined: one
// that calls itself cannot (inlining it would never end), as LLVM's
// isInlineViable tells, once per function.
class Inlinable {
 public:
  bool operator()(const llvm::CallBase& call) {
    llvm::Function* callee = call.getCalledFunction();
    if (!callee || callee->isDeclaration() || !callee->hasFnAttribute(llvm::Attribute::AlwaysInline)) return false;
    const auto [known, added] = viable_.try_emplace(callee, false);
    if (added) known->second = llvm::isInlineViable(*callee).isSuccess();
    return known->second;
  }

 private:
  std::map<const llvm::Function*, bool> viable_;
};

}  // namespace

void inline_library_calls(llvm::Module& module) {
  Inlinable inlinable;
  std::vector<llvm::CallBase*> calls;
  for (llvm::Function& function : module)
    if (!function.hasFnAttribute(llvm::Attribute::AlwaysInline))
      for (llvm::Instruction& instr : llvm::instructions(function))
        if (auto* call = llvm::dyn_cast<llvm::CallBase>(&instr); call && inlinable(*call)) calls.push_back(call);
  std::reverse(calls.begin(), calls.end());
  // In the order of the calls; a body's own calls right after it, in
  // theirs, as a depth-first walk of the calls would meet them.
  while (!calls.empty()) {
    llvm::CallBase* call = calls.back();
    calls.pop_back();
    llvm::InlineFunctionInfo info;
    // Merging the callee's attributes (its minimum legal vector width)
    // into the caller, as the always-inliner does.
    if (!llvm::InlineFunction(*call, info, /*MergeAttributes=*/true).isSuccess()) continue;
    for (auto inlined = info.InlinedCallSites.rbegin(); inlined != info.InlinedCallSites.rend(); ++inlined)
      if (inlinable(**inlined)) calls.push_back(*inlined);
  }
  for (llvm::Function& function : llvm::make_early_inc_range(module)) {
    if (function.isDeclaration() || !function.hasFnAttribute(llvm::Attribute::AlwaysInline) ||
        !function.hasLocalLinkage())
      continue;
    function.removeDeadConstantUsers();
    if (function.use_empty()) function.eraseFromParent();
  }
}

}  // namespace shadetree

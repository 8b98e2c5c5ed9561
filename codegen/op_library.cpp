#include "codegen/op_library.h"

#include <algorithm>
#include <map>
#include <mutex>
#include <set>
#include <tuple>
#include <utility>

#include <llvm/Analysis/ValueTracking.h>
#include <llvm/Bitcode/BitcodeReader.h>
#include <llvm/IR/IntrinsicInst.h>
#include <llvm/IR/LLVMContext.h>
#include <llvm/IR/Module.h>
#include <llvm/Support/Error.h>
#include <llvm/Support/MemoryBuffer.h>
#include <llvm/Support/xxhash.h>

#include "nodes/limits.h"

extern const unsigned char shadetree_ops_bitcode_w4[];
extern const unsigned long shadetree_ops_bitcode_w4_size;
extern const unsigned char shadetree_ops_bitcode_w8[];
extern const unsigned long shadetree_ops_bitcode_w8_size;
extern const unsigned char shadetree_ops_bitcode_w16[];
extern const unsigned long shadetree_ops_bitcode_w16_size;

namespace shadetree {

namespace {
llvm::StringRef as_text(const unsigned char* bytes, unsigned long size) {
  return llvm::StringRef(reinterpret_cast<const char*>(bytes), size);
}

// The library of `width`; empty for any other width.
llvm::StringRef bitcode(int width) {
  switch (width) {
    case 4: return as_text(shadetree_ops_bitcode_w4, shadetree_ops_bitcode_w4_size);
    case 8: return as_text(shadetree_ops_bitcode_w8, shadetree_ops_bitcode_w8_size);
    case 16: return as_text(shadetree_ops_bitcode_w16, shadetree_ops_bitcode_w16_size);
    default: return {};
  }
}
}  // namespace

std::uint64_t op_library_hash() {
  static const std::uint64_t hash = [] {
    std::uint64_t combined = 0;
    for (int width : {4, 8, 16}) combined = llvm::xxh3_64bits(bitcode(width)) ^ (combined * 0x9e3779b97f4a7c15ull);
    return combined;
  }();
  return hash;
}

std::unique_ptr<llvm::Module> load_op_library(llvm::LLVMContext& context, int width) {
  const llvm::StringRef library = bitcode(width);
  if (library.empty()) return nullptr;
  auto module = llvm::getLazyBitcodeModule(llvm::MemoryBufferRef(library, "shadetree_ops"), context);
  if (!module) {
    llvm::consumeError(module.takeError());
    return nullptr;
  }
  return std::move(*module);
}

void make_library_inlined(llvm::Module& module) {
  for (llvm::Function& function : module) {
    if (function.isDeclaration()) continue;
    function.setLinkage(llvm::GlobalValue::InternalLinkage);
    function.removeFnAttr(llvm::Attribute::NoInline);
    function.removeFnAttr(llvm::Attribute::OptimizeNone);
    function.addFnAttr(llvm::Attribute::AlwaysInline);
  }
  for (llvm::GlobalVariable& global : module.globals())
    if (!global.isDeclaration()) global.setLinkage(llvm::GlobalValue::InternalLinkage);
}

bool materialize_called(llvm::Module& module) {
  for (bool read = true; read;) {
    read = false;
    for (llvm::Function& function : module) {
      if (!function.isMaterializable() || function.use_empty()) continue;
      if (llvm::Error error = function.materialize()) {
        llvm::consumeError(std::move(error));
        return false;
      }
      read = true;
    }
  }
  return true;
}

bool drop_uncalled(llvm::Module& module, const std::vector<llvm::Function*>& entry_points) {
  for (bool erased = true; erased;) {
    erased = false;
    for (llvm::Function& function : llvm::make_early_inc_range(module)) {
      if (std::ranges::find(entry_points, &function) != entry_points.end() || !function.use_empty()) continue;
      function.eraseFromParent();
      erased = true;
    }
  }
  if (llvm::Error error = module.materializeAll()) {
    llvm::consumeError(std::move(error));
    return false;
  }
  return true;
}

std::string op_library_symbol(OpId op, bool dual, int width) {
  return std::string("st_") + op_symbol(op) + (dual ? "_dual" : "") + "_w" + std::to_string(width);
}

namespace {

// What a call to the lookup of a noise cell's rows of knots weighs: the
// lookups and slot arithmetic it took the place of in the library's noise
// (codegen/table_lookups.cpp defines it when a kernel is emitted), so
// that the weights of noise ops, which kernel_split.h's and the
// outlining's thresholds were measured with, stay what they were at
// every width (turbulence weighed 1097 with them, 1036 with the 3D call
// counted as one; turbulence4 628 and 429 with the 4D call; where the
// axes wrap, pturbulence 465 and 338, pturbulence4 1139 and 589).
unsigned knot_rows_lookup_weight(llvm::StringRef callee) {
  if (callee.starts_with("st_gather256_knot_rows_w")) return 62;
  if (callee.starts_with("st_gather256_knot_rows4_w")) return 200;
  if (callee.starts_with("st_gather256_knot_rows_apart_w")) return 128;
  if (callee.starts_with("st_gather256_knot_rows4_apart_w")) return 551;
  return 0;
}

unsigned weight_of(const llvm::Value* value) {
  if (const auto* call = llvm::dyn_cast<llvm::CallInst>(value))
    if (const llvm::Function* callee = call->getCalledFunction())
      if (const unsigned weight = knot_rows_lookup_weight(callee->getName())) return weight;
  return llvm::isa<llvm::Instruction>(value) ? 1 : 0;
}

// The instructions of `function` that depend, through values or memory,
// on one of the arguments in `unknown` (the others are constants), each
// counted by its weight.
unsigned instructions_depending_on(llvm::Function& function, unsigned unknown) {
  std::set<const llvm::Value*> depending;
  for (unsigned input = 0; input < max_op_args; ++input)
    if (unknown & (1u << input) && input + 1 < function.arg_size()) depending.insert(function.getArg(input + 1));
  // Loops carry values around their phis, and memory carries them from a
  // store (or a call) to the loads of the same object, so repeat until
  // nothing changes.
  for (bool grew = true; grew;) {
    grew = false;
    for (llvm::BasicBlock& block : function)
      for (llvm::Instruction& instruction : block) {
        if (depending.contains(&instruction)) continue;
        if (std::ranges::none_of(instruction.operands(), [&](const llvm::Use& use) { return depending.contains(use.get()); }))
          continue;
        depending.insert(&instruction);
        grew = true;
        if (!llvm::isa<llvm::StoreInst, llvm::CallInst, llvm::MemIntrinsic>(instruction)) continue;
        for (const llvm::Use& use : instruction.operands())
          if (use->getType()->isPointerTy()) depending.insert(llvm::getUnderlyingObject(use.get()));
      }
  }
  unsigned weight = 0;
  for (const llvm::Value* value : depending) weight += weight_of(value);
  return weight;
}

}  // namespace

unsigned op_library_instructions(const std::string& symbol, int width, unsigned unknown_inputs) {
  static std::mutex mutex;
  static std::map<std::tuple<std::string, int, unsigned>, unsigned> sizes;
  static llvm::LLVMContext* context = new llvm::LLVMContext;  // never destroyed, like the JIT
  static auto* libraries = new std::map<int, std::unique_ptr<llvm::Module>>;
  std::lock_guard lock(mutex);
  const auto key = std::make_tuple(symbol, width, unknown_inputs);
  if (auto found = sizes.find(key); found != sizes.end()) return found->second;
  std::unique_ptr<llvm::Module>& library = (*libraries)[width];
  if (!library) library = load_op_library(*context, width);
  llvm::Function* function = library ? library->getFunction(symbol) : nullptr;
  unsigned size = 0;
  if (function && !function->isDeclaration()) {
    if (llvm::Error error = function->materialize())
      llvm::consumeError(std::move(error));
    else
      size = instructions_depending_on(*function, unknown_inputs);
  }
  return sizes[key] = size;
}

}  // namespace shadetree

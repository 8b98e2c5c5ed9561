// ShadeIR -> LLVM IR (see emit_kernel.h).
//
// Every ShadeIR value lives in an alloca of [components x <W x float>];
// instructions load their arguments, call the op library through its one
// calling convention (codegen/ops_bitcode.cpp) or, for pure data movement,
// move values themselves, and store their result. mem2reg and SROA turn
// this into SSA after the op library is inlined, and conditional regions
// need no hand-built phis. Constants are emitted where they are used, so
// the optimizer folds them into the op library's code. The other uniform
// values are computed by the bind function and kept in the state block,
// from which the run function loads them once, before its sample loop.
// Varying values are computed inside the loop. A region becomes a branch
// that skips its blocks when no active lane takes it (ISPC-style masked
// control flow); inside, all W lanes compute and the `if` selects per lane.
// A dual value (ir/differentiate.h) takes four vectors per component
// (value, then its partials with respect to P) and its ops are the op
// library's dual forms.
#include "codegen/emit_kernel.h"

#include <algorithm>
#include <map>

#include <llvm/IR/Constants.h>
#include <llvm/IR/IRBuilder.h>
#include <llvm/IR/LLVMContext.h>
#include <llvm/IR/Module.h>
#include <llvm/IR/Verifier.h>
#include <llvm/Support/Error.h>
#include <llvm/Support/raw_ostream.h>

#include "codegen/kernel_split.h"
#include "codegen/op_constant_globals.h"
#include "codegen/op_library.h"
#include "codegen/table_lookups.h"
#include "nodes/dual_frame.h"

namespace shadetree {

UniformStateLayout uniform_state_layout(const ShadeIR& ir) {
  UniformStateLayout layout;
  layout.slots.assign(ir.code.size(), -1);
  for (std::size_t i = 0; i < ir.code.size(); ++i) {
    const IrInstr& instr = ir.code[i];
    if (!instr.uniform || instr.kind == IrOpKind::constant) continue;
    layout.slots[i] = layout.size;
    layout.size += component_count(instr.type);
  }
  return layout;
}

namespace {

class KernelEmitter {
 public:
  KernelEmitter(const ShadeIR& ir, int width, llvm::Module& module, const std::string& data_symbol)
      : ir_(ir),
        width_(width),
        module_(module),
        context_(module.getContext()),
        builder_(context_),
        state_(uniform_state_layout(ir)),
        layout_(output_layout(ir)),
        constants_(ir, module, data_symbol) {
    float_ = builder_.getFloatTy();
    vector_ = llvm::FixedVectorType::get(float_, static_cast<unsigned>(width));
    ptr_ = builder_.getPtrTy();
  }

  // void bind(const float* params, const float* uniform_globals, float* state)
  Result<llvm::Function*> emit_bind(const std::string& name) {
    llvm::Function* function = begin_function(name, {ptr_, ptr_, ptr_});
    auto args = function->arg_begin();
    params_ = &*args++;
    uniforms_ = &*args++;
    llvm::Value* state = &*args;
    for (std::size_t i = 0; i < ir_.code.size(); ++i) {
      if (!ir_.code[i].uniform) continue;
      Status status = emit_instruction(static_cast<int>(i));
      if (!status) return status.error();
      if (state_.slots[i] < 0) continue;
      for (int c = 0; c < component_count(ir_.code[i].type); ++c)
        builder_.CreateStore(builder_.CreateExtractElement(load(static_cast<int>(i), c), std::uint64_t{0}),
                             builder_.CreateConstInBoundsGEP1_32(float_, state, static_cast<unsigned>(state_.slots[i] + c)));
    }
    builder_.CreateRetVoid();
    return finish(function);
  }

  // void run(const float* state, const float* const* input_planes,
  //          float* const* output_planes, int64_t count)
  Result<llvm::Function*> emit_run(const std::string& name) {
    llvm::Function* function = begin_function(name, {ptr_, ptr_, ptr_, builder_.getInt64Ty()});
    auto args = function->arg_begin();
    llvm::Value* state = &*args++;
    inputs_ = &*args++;
    outputs_ = &*args++;
    llvm::Value* count = &*args;
    Status status = emit_prelude(state);
    if (!status) return status.error();
    status = emit_sample_loop(function, builder_.getInt64(0), count, [&]() -> Status {
      Status body = emit_varying(function, 0, static_cast<int>(ir_.code.size()));
      if (body) store_outputs();
      return body;
    });
    if (!status) return status.error();
    builder_.CreateRetVoid();
    return finish(function);
  }

  // A part of a split kernel (codegen/kernel_split.h), over samples
  // [start, end) of a chunk:
  //   void part(const float* state, const float* const* input_planes,
  //             float* const* output_planes, float* scratch,
  //             int64_t start, int64_t end)
  // The first leaves the crossing values in scratch, each vector of them
  // a row of kernel_split_chunk floats; the second reads them back.
  Result<llvm::Function*> emit_part(const std::string& name, const KernelSplit& split, bool first) {
    llvm::Function* function = part_function(name);
    begin_body(function);
    auto args = function->arg_begin();
    llvm::Value* state = &*args++;
    inputs_ = &*args++;
    outputs_ = &*args++;
    llvm::Value* scratch = &*args++;
    llvm::Value* start = &*args++;
    llvm::Value* end = &*args;
    Status status = emit_prelude(state);
    if (!status) return status.error();
    status = emit_sample_loop(function, start, end, [&]() -> Status {
      // Moves the crossing values to scratch (first part) or back.
      auto cross = [&] {
        int row = 0;
        for (int value : split.crossing)
          for (int vector = 0; vector < stored_components(ir_.code[value]); ++vector, ++row) {
            llvm::Value* offset = builder_.CreateAdd(builder_.CreateSub(index_, start),
                                                     builder_.getInt64(std::int64_t{kernel_split_chunk} * row));
            llvm::Value* address = builder_.CreateInBoundsGEP(float_, scratch, offset);
            if (first)
              builder_.CreateAlignedStore(load_stored(value, vector), address, llvm::Align(4));
            else
              store_stored(value, vector, builder_.CreateAlignedLoad(vector_, address, llvm::Align(4)));
          }
      };
      if (!first) cross();
      Status body = first ? emit_varying(function, 0, split.cut)
                          : emit_varying(function, split.cut, static_cast<int>(ir_.code.size()));
      if (!body) return body;
      if (first)
        cross();
      else
        store_outputs();
      return success();
    });
    if (!status) return status.error();
    builder_.CreateRetVoid();
    return finish(function);
  }

  // The run function of a split kernel: both parts, chunk by chunk, the
  // crossing values in a scratch block on the stack.
  Result<llvm::Function*> emit_split_run(const std::string& name, llvm::Function* first, llvm::Function* second,
                                         const KernelSplit& split) {
    llvm::Function* function = llvm::Function::Create(
        llvm::FunctionType::get(builder_.getVoidTy(), {ptr_, ptr_, ptr_, builder_.getInt64Ty()}, false),
        llvm::Function::ExternalLinkage, name, module_);
    builder_.SetInsertPoint(llvm::BasicBlock::Create(context_, "entry", function));
    auto args = function->arg_begin();
    llvm::Value* state = &*args++;
    llvm::Value* inputs = &*args++;
    llvm::Value* outputs = &*args++;
    llvm::Value* count = &*args;
    llvm::AllocaInst* scratch = builder_.CreateAlloca(
        llvm::ArrayType::get(float_, static_cast<std::uint64_t>(std::max(1, split.crossing_vectors)) * kernel_split_chunk));
    scratch->setAlignment(llvm::Align(64));
    llvm::BasicBlock* entry = builder_.GetInsertBlock();
    llvm::BasicBlock* loop = llvm::BasicBlock::Create(context_, "chunk", function);
    llvm::BasicBlock* exit = llvm::BasicBlock::Create(context_, "exit", function);
    builder_.CreateCondBr(builder_.CreateICmpSGT(count, builder_.getInt64(0)), loop, exit);
    builder_.SetInsertPoint(loop);
    llvm::PHINode* start = builder_.CreatePHI(builder_.getInt64Ty(), 2, "chunk_start");
    start->addIncoming(builder_.getInt64(0), entry);
    llvm::Value* next = builder_.CreateAdd(start, builder_.getInt64(kernel_split_chunk), "next_chunk");
    llvm::Value* end = builder_.CreateSelect(builder_.CreateICmpSLT(next, count), next, count);
    for (llvm::Function* part : {first, second}) builder_.CreateCall(part, {state, inputs, outputs, scratch, start, end});
    start->addIncoming(next, loop);
    builder_.CreateCondBr(builder_.CreateICmpSLT(next, count), loop, exit);
    builder_.SetInsertPoint(exit);
    builder_.CreateRetVoid();
    return finish(function);
  }

  // The declaration of a part of a split kernel.
  llvm::Function* part_function(const std::string& name) {
    if (llvm::Function* declared = module_.getFunction(name)) return declared;
    auto* type = llvm::FunctionType::get(builder_.getVoidTy(), {ptr_, ptr_, ptr_, ptr_, builder_.getInt64Ty(), builder_.getInt64Ty()}, false);
    return llvm::Function::Create(type, llvm::Function::ExternalLinkage, name, module_);
  }

 private:
  llvm::Function* begin_function(const std::string& name, std::vector<llvm::Type*> parameters) {
    auto* type = llvm::FunctionType::get(builder_.getVoidTy(), parameters, false);
    llvm::Function* function = llvm::Function::Create(type, llvm::Function::ExternalLinkage, name, module_);
    begin_body(function);
    return function;
  }

  // The entry block of `function`, with a register for every value.
  void begin_body(llvm::Function* function) {
    entry_ = llvm::BasicBlock::Create(context_, "entry", function);
    builder_.SetInsertPoint(entry_);
    registers_.clear();
    for (const IrInstr& instr : ir_.code)
      registers_.push_back(
          builder_.CreateAlloca(llvm::ArrayType::get(vector_, static_cast<std::uint64_t>(stored_components(instr)))));
  }

  // Constants, and the uniform values the bind function left in `state`,
  // before the sample loop.
  Status emit_prelude(llvm::Value* state) {
    for (std::size_t i = 0; i < ir_.code.size(); ++i) {
      const IrInstr& instr = ir_.code[i];
      if (instr.kind == IrOpKind::constant) {
        Status status = emit_instruction(static_cast<int>(i));
        if (!status) return status;
      }
      if (state_.slots[i] < 0) continue;
      for (int c = 0; c < component_count(instr.type); ++c)
        store(static_cast<int>(i), c,
              splat(builder_.CreateLoad(float_, builder_.CreateConstInBoundsGEP1_32(
                                                    float_, state, static_cast<unsigned>(state_.slots[i] + c)))));
    }
    return success();
  }

  // A loop over the samples from `begin` to `end`, `width_` at a time:
  // index_ is the first sample of an iteration, whose code `body` emits.
  template <class Body>
  Status emit_sample_loop(llvm::Function* function, llvm::Value* begin, llvm::Value* end, Body body) {
    llvm::BasicBlock* entry = builder_.GetInsertBlock();
    llvm::BasicBlock* loop = llvm::BasicBlock::Create(context_, "loop", function);
    llvm::BasicBlock* exit = llvm::BasicBlock::Create(context_, "exit", function);
    builder_.CreateCondBr(builder_.CreateICmpSLT(begin, end), loop, exit);
    builder_.SetInsertPoint(loop);
    llvm::PHINode* index = builder_.CreatePHI(builder_.getInt64Ty(), 2, "sample");
    index->addIncoming(begin, entry);
    index_ = index;
    Status status = body();
    if (!status) return status;
    llvm::Value* next = builder_.CreateAdd(index_, builder_.getInt64(width_), "next_sample");
    index->addIncoming(next, builder_.GetInsertBlock());
    builder_.CreateCondBr(builder_.CreateICmpSLT(next, end), loop, exit);
    builder_.SetInsertPoint(exit);
    return success();
  }

  // The varying instructions from `begin` to `end` (outside any region at
  // both ends): a region becomes a branch over its blocks, taken when any
  // lane takes it.
  Status emit_varying(llvm::Function* function, int begin, int end) {
    llvm::Value* mask = llvm::ConstantInt::getTrue(llvm::FixedVectorType::get(builder_.getInt1Ty(), width_));
    std::vector<std::pair<llvm::Value*, llvm::BasicBlock*>> regions;  // (outer mask, merge block)
    for (int i = begin; i < end; ++i) {
      const IrInstr& instr = ir_.code[i];
      if (instr.uniform) continue;
      if (instr.kind == IrOpKind::begin_region) {
        llvm::Value* condition = builder_.CreateFCmpUNE(load(instr.args[0], 0), llvm::ConstantFP::get(vector_, 0.0));
        if (instr.immediate[0] != 0) condition = builder_.CreateNot(condition);
        llvm::Value* region_mask = builder_.CreateAnd(mask, condition);
        llvm::Value* any = builder_.CreateICmpNE(
            builder_.CreateBitCast(region_mask, builder_.getIntNTy(static_cast<unsigned>(width_))),
            builder_.getIntN(static_cast<unsigned>(width_), 0));
        auto* body = llvm::BasicBlock::Create(context_, "region", function);
        auto* merge = llvm::BasicBlock::Create(context_, "after_region", function);
        builder_.CreateCondBr(any, body, merge);
        builder_.SetInsertPoint(body);
        regions.push_back({mask, merge});
        mask = region_mask;
        continue;
      }
      if (instr.kind == IrOpKind::end_region) {
        builder_.CreateBr(regions.back().second);
        builder_.SetInsertPoint(regions.back().second);
        mask = regions.back().first;
        regions.pop_back();
        continue;
      }
      Status status = emit_instruction(i);
      if (!status) return status;
    }
    return success();
  }

  Result<llvm::Function*> finish(llvm::Function* function) {
    std::string problems;
    llvm::raw_string_ostream stream(problems);
    if (llvm::verifyFunction(*function, &stream)) return failure("codegen produced invalid IR: " + problems);
    return function;
  }

  // Pointer to component c of value v, reading scalars as splatted vectors;
  // to its part `part` (0: value, 1 to 3: partials) if v is dual.
  llvm::Value* component_pointer(int value, int component, int part = 0) {
    const int components = component_count(ir_.code[value].type);
    const int c = std::min(component, components - 1);
    const int index = ir_.code[value].dual ? dual_floats * c + part : c;
    return builder_.CreateConstInBoundsGEP2_32(registers_[value]->getAllocatedType(), registers_[value], 0,
                                               static_cast<unsigned>(index));
  }

  llvm::Value* load(int value, int component, int part = 0) {
    return builder_.CreateLoad(vector_, component_pointer(value, component, part));
  }

  void store(int value, int component, llvm::Value* vector, int part = 0) {
    builder_.CreateStore(vector, component_pointer(value, component, part));
  }

  // Vector `vector` of value v's register, of stored_components(v).
  llvm::Value* stored_pointer(int value, int vector) {
    return builder_.CreateConstInBoundsGEP2_32(registers_[value]->getAllocatedType(), registers_[value], 0,
                                               static_cast<unsigned>(vector));
  }
  llvm::Value* load_stored(int value, int vector) { return builder_.CreateLoad(vector_, stored_pointer(value, vector)); }
  void store_stored(int value, int vector, llvm::Value* contents) {
    builder_.CreateStore(contents, stored_pointer(value, vector));
  }

  // A pointer to `components` consecutive vectors holding argument `value`
  // (duals, for a dual user: `parts` = 4); a scalar passed where a vector is
  // expected is splatted into a copy, and a value that does not depend on P
  // gets zero partials in a copy.
  llvm::Value* array_pointer(int value, int components, int parts) {
    const bool as_stored = ir_.code[value].dual == (parts > 1);
    if (as_stored && component_count(ir_.code[value].type) >= components) return component_pointer(value, 0);
    llvm::IRBuilder<> entry_builder(entry_, entry_->begin());
    auto* copy =
        entry_builder.CreateAlloca(llvm::ArrayType::get(vector_, static_cast<std::uint64_t>(components * parts)));
    for (int c = 0; c < components; ++c)
      for (int part = 0; part < parts; ++part)
        builder_.CreateStore(part > 0 && !ir_.code[value].dual ? llvm::ConstantFP::get(vector_, 0.0)
                                                               : load(value, c, part),
                             builder_.CreateConstInBoundsGEP2_32(copy->getAllocatedType(), copy, 0,
                                                                 static_cast<unsigned>(c * parts + part)));
    return copy;
  }

  llvm::Value* splat(llvm::Value* scalar) { return builder_.CreateVectorSplat(static_cast<unsigned>(width_), scalar); }

  Status emit_instruction(int self) {
    const IrInstr& instr = ir_.code[self];
    switch (instr.kind) {
      case IrOpKind::constant:
        for (int c = 0; c < component_count(instr.type); ++c)
          store(self, c, llvm::ConstantFP::get(vector_, ir_.data[instr.data_offset + std::min(c, instr.data_count - 1)]));
        return success();
      case IrOpKind::param:
        for (int c = 0; c < component_count(instr.type); ++c)
          store(self, c, splat(load_float(params_, instr.immediate[0] + c)));
        return success();
      case IrOpKind::global: {
        const GlobalDef& global = global_def(static_cast<GlobalId>(instr.immediate[0]));
        for (int c = 0; c < global.components; ++c) {
          if (instr.uniform) {
            store(self, c, splat(load_float(uniforms_, global.first + c)));
            continue;
          }
          llvm::Value* plane = builder_.CreateLoad(
              ptr_, builder_.CreateConstInBoundsGEP1_32(ptr_, inputs_, static_cast<unsigned>(global.first + c)));
          llvm::Value* address = builder_.CreateInBoundsGEP(float_, plane, index_);
          store(self, c, builder_.CreateAlignedLoad(vector_, address, llvm::Align(4)));
          if (!instr.dual) continue;
          // P's partials: dP_c / dP_k is 1 where k = c.
          for (int k = 0; k < 3; ++k) store(self, c, llvm::ConstantFP::get(vector_, k == c ? 1.0 : 0.0), 1 + k);
        }
        return success();
      }
      case IrOpKind::extract:
        for (int part = 0; part < (instr.dual ? dual_floats : 1); ++part)
          store(self, 0, load(instr.args[0], instr.immediate[0], part), part);
        return success();
      case IrOpKind::partials:
        for (int k = 0; k < 3; ++k) store(self, k, load(instr.args[0], 0, 1 + k));
        return success();
      case IrOpKind::begin_region:
      case IrOpKind::end_region:
        return failure("codegen: a region marker outside the sample loop");
      case IrOpKind::op:
        return emit_op(self);
    }
    return success();
  }

  llvm::Value* load_float(llvm::Value* base, int index) {
    return builder_.CreateLoad(float_, builder_.CreateConstInBoundsGEP1_32(float_, base, static_cast<unsigned>(index)));
  }

  // st_<op>_w<W>(result, a0 .. a5, constants), st_<op>_dual_w<W> for a
  // dual: codegen/ops_bitcode.cpp.
  Status emit_op(int self) {
    const IrInstr& instr = ir_.code[self];
    const std::string symbol = op_library_symbol(instr.op, instr.dual, width_);
    llvm::Function* callee = module_.getFunction(symbol);
    if (!callee) return failure("codegen: the op library has no " + symbol);
    std::vector<llvm::Value*> arguments{component_pointer(self, 0)};
    for (int a = 0; a < max_op_args; ++a)
      arguments.push_back(a < instr.arg_count
                              ? array_pointer(instr.args[a], component_count(argument_type(instr, a)),
                                              instr.dual ? dual_floats : 1)
                              : llvm::ConstantPointerNull::get(ptr_));
    arguments.push_back(constants_.of(instr));
    builder_.CreateCall(callee, arguments);
    return success();
  }

  void store_outputs() {
    for (const IrOutput& output : ir_.outputs) {
      for (int c = 0; c < component_count(output.type); ++c) {
        const unsigned plane = static_cast<unsigned>(layout_.plane(output.id, c));
        llvm::Value* base = builder_.CreateLoad(ptr_, builder_.CreateConstInBoundsGEP1_32(ptr_, outputs_, plane));
        builder_.CreateAlignedStore(load(output.value, c), builder_.CreateInBoundsGEP(float_, base, index_),
                                    llvm::Align(4));
      }
    }
  }

  const ShadeIR& ir_;
  int width_;
  llvm::Module& module_;
  llvm::LLVMContext& context_;
  llvm::IRBuilder<> builder_;
  UniformStateLayout state_;
  OutputLayout layout_;
  llvm::Type* float_ = nullptr;
  llvm::FixedVectorType* vector_ = nullptr;
  llvm::PointerType* ptr_ = nullptr;
  llvm::BasicBlock* entry_ = nullptr;
  llvm::Value *params_ = nullptr, *uniforms_ = nullptr, *inputs_ = nullptr, *outputs_ = nullptr, *index_ = nullptr;
  std::vector<llvm::AllocaInst*> registers_;
  OpConstantGlobals constants_;
};

// The instructions `function` brings when inlined: its own and those of
// the functions it calls (the library's ops are flattened when it is
// built, so these are the table lookups the code generator defines).
unsigned inlined_size(llvm::Function& function, std::map<llvm::Function*, unsigned>& sizes) {
  if (auto found = sizes.find(&function); found != sizes.end()) return found->second;
  unsigned size = function.getInstructionCount();
  for (llvm::BasicBlock& block : function)
    for (llvm::Instruction& instruction : block)
      if (auto* call = llvm::dyn_cast<llvm::CallInst>(&instruction))
        if (llvm::Function* callee = call->getCalledFunction(); callee && !callee->isDeclaration())
          size += inlined_size(*callee, sizes);
  return sizes[&function] = size;
}

// Inlining every op into one kernel hands the optimizer and the register
// allocator a body that grows with the graph, and their time grows faster
// than the body (a chain of 500 `exp` took 5 s, 100 noises more). Past a
// budget of inlined instructions, the largest ops that a kernel calls more
// than once are called instead, largest first, until the rest fits or no
// op of at least smallest_outlined_op instructions is left: each is
// compiled once per kernel however many nodes use it, with its constants
// read at run time. Small graphs, the common case, keep everything
// inlined. The budget counts the flattened library's instructions: sponge
// (3792, four noises) and vector_fields (3542, three) call their noise and
// compile in 31-44 ms, where inlined they took 66-78 ms.
constexpr unsigned inline_budget = 3400;
// An op this small costs less inlined than its call does (arguments
// through memory, constants read at run time), and outlining it would
// save the compiler next to nothing.
constexpr unsigned smallest_outlined_op = 100;

// Outlines by the whole kernel's calls (`ir`'s op instructions), so that
// the two modules of a split kernel decide as the kernel would whole.
bool outline_large_ops(llvm::Module& module, const ShadeIR& ir, int width) {
  std::map<std::string, unsigned> calls;
  for (const IrInstr& instr : ir.code)
    if (instr.kind == IrOpKind::op) ++calls[op_library_symbol(instr.op, instr.dual, width)];
  std::map<llvm::Function*, unsigned> sizes;
  std::vector<std::pair<unsigned, std::pair<llvm::Function*, unsigned>>> ops;  // (size, (op, calls))
  unsigned total = 0;
  for (const auto& [symbol, count] : calls) {
    llvm::Function* function = module.getFunction(symbol);
    if (!function) continue;
    if (llvm::Error error = function->materialize()) {
      llvm::consumeError(std::move(error));
      return false;
    }
    const unsigned size = inlined_size(*function, sizes);
    total += size * count;
    ops.push_back({size, {function, count}});
  }
  std::sort(ops.begin(), ops.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  for (auto& [size, op] : ops) {
    auto [function, count] = op;
    if (total <= inline_budget) break;
    if (count < 2 || size < smallest_outlined_op) continue;
    function->removeFnAttr(llvm::Attribute::AlwaysInline);
    function->addFnAttr(llvm::Attribute::NoInline);
    total -= size * (count - 1);
  }
  return true;
}

}  // namespace

Result<std::unique_ptr<llvm::Module>> emit_kernel_module(const ShadeIR& ir, int width, llvm::LLVMContext& context,
                                                         const std::string& function_name, GatherStrategy gathers,
                                                         KernelPart part, const KernelSplit& split) {
  if (width != 4 && width != 8 && width != 16) return invalid_input("vector width must be 4, 8 or 16");
  std::unique_ptr<llvm::Module> module = load_op_library(context, width);
  if (!module) return failure("the embedded op library bitcode is unreadable");
  module->setModuleIdentifier(function_name);
  define_table_lookups(*module, gathers);
  make_library_inlined(*module);
  KernelEmitter emitter(ir, width, *module, kernel_data_symbol(function_name));
  std::vector<llvm::Function*> entry_points;
  if (part == KernelPart::first) {
    Result<llvm::Function*> first = emitter.emit_part(function_name + "_first", split, true);
    if (!first) return first.error();
    entry_points = {*first};
  } else {
    Result<llvm::Function*> bind = emitter.emit_bind(function_name + "_bind");
    if (!bind) return bind.error();
    // The second part is inlined into the run function, which calls the
    // first part in the other module.
    auto split_run = [&]() -> Result<llvm::Function*> {
      Result<llvm::Function*> second = emitter.emit_part(function_name + "_second", split, false);
      if (!second) return second.error();
      (*second)->setLinkage(llvm::GlobalValue::InternalLinkage);
      (*second)->addFnAttr(llvm::Attribute::AlwaysInline);
      return emitter.emit_split_run(function_name + "_run", emitter.part_function(function_name + "_first"), *second,
                                    split);
    };
    Result<llvm::Function*> run = part == KernelPart::second ? split_run() : emitter.emit_run(function_name + "_run");
    if (!run) return run.error();
    entry_points = {*bind, *run};
  }
  if (!materialize_called(*module)) return failure("the embedded op library bitcode is unreadable");
  if (!outline_large_ops(*module, ir, width)) return failure("the embedded op library bitcode is unreadable");
  if (!drop_uncalled(*module, entry_points)) return failure("the embedded op library bitcode is unreadable");
  return module;
}

}  // namespace shadetree

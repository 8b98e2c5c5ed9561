// ShadeIR -> LLVM IR for interval programs (see emit_interval_program.h).
//
// Each value lives in an alloca of its components' intervals and its
// length's ([4 x [2 x float]], nodes/interval_frame.h), as the
// interpreter's registers: the components zeroed on entry, the length
// unknown; an op is called with IntervalFrame's planes, arrays of pointers
// to its arguments' components and lengths and to its result's. Once the library is inlined SROA makes the
// registers SSA values. As in the interpreter, the uniform instructions
// run first (a pass of their own, whose regions may be passed over too),
// then the varying ones, and only those a bounded output depends on.
#include "codegen/emit_interval_program.h"

#include <algorithm>
#include <map>

#include <llvm/IR/Constants.h>
#include <llvm/IR/IRBuilder.h>
#include <llvm/IR/LLVMContext.h>
#include <llvm/IR/Module.h>
#include <llvm/IR/Verifier.h>
#include <llvm/Support/raw_ostream.h>

#include "codegen/emit_kernel.h"
#include "codegen/op_constant_globals.h"
#include "codegen/op_library.h"
#include "ir/interval_lengths_read.h"
#include "ir/kernel.h"
#include "ir/output_dependencies.h"
#include "nodes/limits.h"

namespace shadetree {

namespace {

// The op library whose functions include the interval forms.
constexpr int interval_library_width = 4;

class IntervalEmitter {
 public:
  IntervalEmitter(const ShadeIR& ir, const std::vector<OutputId>& bounded, llvm::Module& module,
                  const std::string& data_symbol)
      : ir_(ir),
        needs_(output_dependencies(ir, bounded)),
        lengths_read_(interval_lengths_read(ir)),
        layout_(output_layout(ir)),
        module_(module),
        builder_(module.getContext()),
        constants_(ir, module, data_symbol) {
    float_ = builder_.getFloatTy();
    ptr_ = builder_.getPtrTy();
    interval_ = llvm::ArrayType::get(float_, 2);
    register_ = llvm::ArrayType::get(interval_, interval_planes_per_value);
  }

  Result<llvm::Function*> emit(const std::string& name) {
    auto* type = llvm::FunctionType::get(builder_.getVoidTy(), {ptr_, ptr_, ptr_, ptr_}, false);
    function_ = llvm::Function::Create(type, llvm::GlobalValue::ExternalLinkage, name, module_);
    auto args = function_->arg_begin();
    params_ = &*args++;
    uniforms_ = &*args++;
    box_ = &*args++;
    llvm::Value* outputs = &*args;
    entry_ = llvm::BasicBlock::Create(module_.getContext(), "entry", function_);
    builder_.SetInsertPoint(entry_);
    // Components 0, the length unknown (as the interpreter's registers).
    std::vector<llvm::Constant*> planes(interval_planes_per_value, llvm::ConstantAggregateZero::get(interval_));
    planes[3] = everything();
    llvm::Constant* initial = llvm::ConstantArray::get(register_, planes);
    unknown_length_ = entry_alloca(interval_);
    builder_.CreateStore(everything(), unknown_length_);
    registers_.assign(ir_.code.size(), nullptr);
    for (std::size_t i = 0; i < ir_.code.size(); ++i) {
      if (!needs_.instructions[i]) continue;
      registers_[i] = entry_alloca(register_);
      builder_.CreateStore(initial, registers_[i]);
    }
    for (bool uniform_pass : {true, false})
      if (Status status = emit_pass(uniform_pass); !status) return status.error();
    llvm::Function* reported = module_.getFunction("st_interval_reported");
    if (!reported) return failure("codegen: the op library has no interval forms");
    for (std::size_t o = 0; o < ir_.outputs.size(); ++o) {
      if (!needs_.outputs[o]) continue;
      const IrOutput& output = ir_.outputs[o];
      // A scalar value read as a vector output repeats, as on the lanes.
      const int held = component_count(ir_.code[static_cast<std::size_t>(output.value)].type);
      for (int c = 0; c < component_count(output.type); ++c)
        builder_.CreateCall(reported, {component(output.value, std::min(c, held - 1)),
                                       interval_at(outputs, layout_.plane(output.id, c))});
    }
    builder_.CreateRetVoid();
    std::string problems;
    llvm::raw_string_ostream stream(problems);
    if (llvm::verifyFunction(*function_, &stream)) return failure("codegen: invalid interval program: " + problems);
    return function_;
  }

 private:
  // The instructions of one pass in program order; a region no sample of
  // the box may run is passed over, to the instruction after its end.
  Status emit_pass(bool uniform_pass) {
    std::map<std::size_t, llvm::BasicBlock*> after_region;  // by the index of the region's end
    for (std::size_t i = 0; i < ir_.code.size(); ++i) {
      const IrInstr& instr = ir_.code[i];
      if (instr.uniform == uniform_pass && needs_.instructions[i]) {
        Status status = emit_instruction(static_cast<int>(i), after_region);
        if (!status) return status;
      }
      if (auto ends = after_region.find(i); ends != after_region.end()) {
        builder_.CreateBr(ends->second);
        builder_.SetInsertPoint(ends->second);
        after_region.erase(ends);
      }
    }
    return success();
  }

  Status emit_instruction(int self, std::map<std::size_t, llvm::BasicBlock*>& after_region) {
    const IrInstr& instr = ir_.code[static_cast<std::size_t>(self)];
    const int components = component_count(instr.type);
    switch (instr.kind) {
      case IrOpKind::constant:
        for (int c = 0; c < components; ++c) {
          llvm::Value* value = llvm::ConstantFP::get(float_, ir_.data[instr.data_offset + std::min(c, instr.data_count - 1)]);
          store_point(self, c, value);
        }
        return success();
      case IrOpKind::param:
        for (int c = 0; c < components; ++c) store_point(self, c, load_float(params_, instr.immediate[0] + c));
        return success();
      case IrOpKind::global: {
        const int first = global_def(static_cast<GlobalId>(instr.immediate[0])).first;
        for (int c = 0; c < components; ++c) {
          if (instr.uniform)
            store_point(self, c, load_float(uniforms_, first + c));
          else
            builder_.CreateStore(builder_.CreateLoad(interval_, interval_at(box_, first + c)), component(self, c));
        }
        return success();
      }
      case IrOpKind::extract:
        builder_.CreateStore(builder_.CreateLoad(interval_, component(instr.args[0], instr.immediate[0])),
                             component(self, 0));
        return success();
      case IrOpKind::partials:
        for (int c = 0; c < components; ++c) builder_.CreateStore(everything(), component(self, c));
        return success();
      case IrOpKind::begin_region: {
        llvm::Function* may_run = module_.getFunction("st_interval_region_may_run");
        if (!may_run) return failure("codegen: the op library has no interval forms");
        llvm::Value* runs = builder_.CreateCall(may_run, {component(instr.args[0], 0), builder_.getInt32(instr.immediate[0])});
        auto* body = llvm::BasicBlock::Create(module_.getContext(), "region", function_);
        auto* after = llvm::BasicBlock::Create(module_.getContext(), "after_region", function_);
        builder_.CreateCondBr(builder_.CreateICmpNE(runs, builder_.getInt32(0)), body, after);
        builder_.SetInsertPoint(body);
        after_region[static_cast<std::size_t>(instr.immediate[1])] = after;
        return success();
      }
      case IrOpKind::end_region:
        return success();
      case IrOpKind::op:
        return emit_op(self);
    }
    return success();
  }

  // st_<op>_interval(constants, in_planes, out_planes), with the planes
  // as the interpreter binds them: component c of argument a (its last
  // component repeated) at 4a + c and its length at 4a + 3 (the unknown
  // one for a scalar read as a vector), none for the arguments it lacks.
  Status emit_op(int self) {
    const IrInstr& instr = ir_.code[static_cast<std::size_t>(self)];
    const std::string symbol = std::string("st_") + op_symbol(instr.op) + "_interval";
    llvm::Function* callee = module_.getFunction(symbol);
    if (!callee) return failure("codegen: the op library has no " + symbol);
    constexpr int planes = interval_planes_per_value;
    llvm::Value* in_planes = entry_alloca(llvm::ArrayType::get(ptr_, max_op_args * planes));
    for (int a = 0; a < max_op_args; ++a)
      for (int c = 0; c < planes; ++c) {
        llvm::Value* plane = llvm::ConstantPointerNull::get(ptr_);
        if (a < instr.arg_count) {
          const int held = component_count(ir_.code[static_cast<std::size_t>(instr.args[a])].type);
          if (c < 3)
            plane = component(instr.args[a], std::min(c, held - 1));
          else
            plane = held == component_count(argument_type(instr, a)) ? component(instr.args[a], c) : unknown_length_;
        }
        builder_.CreateStore(plane, builder_.CreateConstInBoundsGEP1_32(ptr_, in_planes, static_cast<unsigned>(planes * a + c)));
      }
    llvm::Value* out_planes = entry_alloca(llvm::ArrayType::get(ptr_, planes));
    for (int c = 0; c < planes; ++c) {
      llvm::Value* plane = c < 3 || lengths_read_[static_cast<std::size_t>(self)]
                               ? component(self, c)
                               : llvm::ConstantPointerNull::get(ptr_);
      builder_.CreateStore(plane, builder_.CreateConstInBoundsGEP1_32(ptr_, out_planes, static_cast<unsigned>(c)));
    }
    builder_.CreateCall(callee, {constants_.of(instr), in_planes, out_planes});
    return success();
  }

  // Stack memory in the entry block, where SROA promotes it.
  llvm::AllocaInst* entry_alloca(llvm::Type* type) {
    llvm::IRBuilder<> at_entry(entry_, entry_->begin());
    return at_entry.CreateAlloca(type);
  }

  llvm::Value* component(int value, int c) {
    return builder_.CreateConstInBoundsGEP2_32(register_, registers_[static_cast<std::size_t>(value)], 0,
                                               static_cast<unsigned>(c));
  }
  llvm::Value* interval_at(llvm::Value* base, int index) {
    return builder_.CreateConstInBoundsGEP1_32(interval_, base, static_cast<unsigned>(index));
  }
  llvm::Value* load_float(llvm::Value* base, int index) {
    return builder_.CreateLoad(float_, builder_.CreateConstInBoundsGEP1_32(float_, base, static_cast<unsigned>(index)));
  }
  // [-inf, +inf]: nothing known.
  llvm::Constant* everything() {
    const double infinity = std::numeric_limits<double>::infinity();
    return llvm::ConstantArray::get(interval_,
                                    {llvm::ConstantFP::get(float_, -infinity), llvm::ConstantFP::get(float_, infinity)});
  }
  // The point interval [value, value].
  void store_point(int self, int c, llvm::Value* value) {
    llvm::Value* interval = builder_.CreateInsertValue(llvm::PoisonValue::get(interval_), value, 0);
    builder_.CreateStore(builder_.CreateInsertValue(interval, value, 1), component(self, c));
  }

  const ShadeIR& ir_;
  OutputDependencies needs_;
  std::vector<char> lengths_read_;  // per instruction: its length is kept (ir/interval_lengths_read.h)
  OutputLayout layout_;
  llvm::Module& module_;
  llvm::IRBuilder<> builder_;
  OpConstantGlobals constants_;
  llvm::Type* float_ = nullptr;
  llvm::PointerType* ptr_ = nullptr;
  llvm::ArrayType *interval_ = nullptr, *register_ = nullptr;
  llvm::Function* function_ = nullptr;
  llvm::BasicBlock* entry_ = nullptr;
  llvm::Value *params_ = nullptr, *uniforms_ = nullptr, *box_ = nullptr;
  std::vector<llvm::AllocaInst*> registers_;
  llvm::AllocaInst* unknown_length_ = nullptr;
};

}  // namespace

Result<std::unique_ptr<llvm::Module>> emit_interval_module(const ShadeIR& ir, const std::vector<OutputId>& bounded,
                                                           llvm::LLVMContext& context,
                                                           const std::string& function_name) {
  std::unique_ptr<llvm::Module> module = load_op_library(context, interval_library_width);
  if (!module) return failure("the embedded op library bitcode is unreadable");
  module->setModuleIdentifier(function_name);
  make_library_inlined(*module);
  IntervalEmitter emitter(ir, bounded, *module, kernel_data_symbol(function_name));
  Result<llvm::Function*> function = emitter.emit(function_name);
  if (!function) return function.error();
  if (!materialize_called(*module) || !drop_uncalled(*module, {*function}))
    return failure("the embedded op library bitcode is unreadable");
  return module;
}

}  // namespace shadetree

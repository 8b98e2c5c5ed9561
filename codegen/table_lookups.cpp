#include "codegen/table_lookups.h"

#include <string>

#include <llvm/IR/IRBuilder.h>
#include <llvm/IR/Module.h>

#include "codegen/x86_table_lookups.h"

namespace shadetree {
namespace {

// One lookup per lane: extract the index, load, insert.
llvm::Value* per_lane_lookup(llvm::IRBuilder<>& builder, llvm::Type* element, llvm::Value* table, llvm::Value* index,
                             int width) {
  llvm::Value* result = llvm::PoisonValue::get(llvm::FixedVectorType::get(element, static_cast<unsigned>(width)));
  for (int lane = 0; lane < width; ++lane) {
    llvm::Value* address = builder.CreateInBoundsGEP(element, table, builder.CreateExtractElement(index, lane));
    result = builder.CreateInsertElement(result, builder.CreateLoad(element, address), lane);
  }
  return result;
}

// A gather as the strategy does it where no register lookup applies.
llvm::Value* memory_lookup(llvm::IRBuilder<>& builder, GatherStrategy strategy, llvm::Type* element, llvm::Value* table,
                           llvm::Value* index, int width) {
  if (strategy == GatherStrategy::per_lane) return per_lane_lookup(builder, element, table, index, width);
  auto* vector = llvm::FixedVectorType::get(element, static_cast<unsigned>(width));
  return builder.CreateMaskedGather(vector, builder.CreateInBoundsGEP(element, table, index), llvm::Align(4));
}

// st_gather_small_f32_w<width>(out, table, size, index): in registers
// where the table fits (a branch on the size, which inlining into a kernel
// folds away), else as any gather.
void define_small_table_lookup(llvm::Module& module, GatherStrategy strategy, int width, bool in_register) {
  llvm::Function* function = module.getFunction("st_gather_small_f32_w" + std::to_string(width));
  if (!function || !function->isDeclaration()) return;
  llvm::LLVMContext& context = module.getContext();
  llvm::IRBuilder<> builder(llvm::BasicBlock::Create(context, "entry", function));
  auto args = function->arg_begin();
  llvm::Value* out = &*args++;
  llvm::Value* table = &*args++;
  llvm::Value* size = &*args++;
  llvm::Value* index =
      builder.CreateLoad(llvm::FixedVectorType::get(builder.getInt32Ty(), static_cast<unsigned>(width)), &*args);
  if (!in_register) {
    builder.CreateStore(memory_lookup(builder, strategy, builder.getFloatTy(), table, index, width), out);
    builder.CreateRetVoid();
    return;
  }
  auto* small = llvm::BasicBlock::Create(context, "small", function);
  auto* large = llvm::BasicBlock::Create(context, "large", function);
  builder.CreateCondBr(builder.CreateICmpSLE(size, builder.getInt32(x86_small_table_entries)), small, large);
  builder.SetInsertPoint(small);
  builder.CreateStore(x86_small_table_lookup(builder, module, table, size, index), out);
  builder.CreateRetVoid();
  builder.SetInsertPoint(large);
  builder.CreateStore(memory_lookup(builder, GatherStrategy::hardware, builder.getFloatTy(), table, index, width), out);
  builder.CreateRetVoid();
}

}  // namespace

void define_table_lookups(llvm::Module& module, GatherStrategy strategy) {
  const bool byte_permutes = strategy == GatherStrategy::in_register_byte_permutes ||
                             strategy == GatherStrategy::byte_permutes_and_gathers;
  const bool float_tables_in_registers =
      strategy == GatherStrategy::in_register || strategy == GatherStrategy::in_register_byte_permutes;
  const bool register_strategy = float_tables_in_registers || byte_permutes;
  llvm::LLVMContext& context = module.getContext();
  for (int width : {4, 8, 16}) {
    const bool in_register = register_strategy && width == 16;
    define_small_table_lookup(module, strategy, width, in_register);
    for (bool table256 : {false, true}) {
      for (bool is_float : {true, false}) {
        const std::string name = std::string(table256 ? "st_gather256_" : "st_gather_") + (is_float ? "f32" : "i32") +
                                 "_w" + std::to_string(width);
        llvm::Function* function = module.getFunction(name);
        if (!function || !function->isDeclaration()) continue;
        llvm::IRBuilder<> builder(llvm::BasicBlock::Create(context, "entry", function));
        llvm::Type* element = is_float ? builder.getFloatTy() : builder.getInt32Ty();
        auto* index_type = llvm::FixedVectorType::get(builder.getInt32Ty(), static_cast<unsigned>(width));
        auto args = function->arg_begin();
        llvm::Value* out = &*args++;
        llvm::Value* table = &*args++;
        llvm::Value* index = builder.CreateLoad(index_type, &*args);
        llvm::Value* result;
        if (in_register && table256 && byte_permutes && !is_float) {
          result = x86_byte_table_lookup(builder, module, table, index);
        } else if (in_register && table256 && float_tables_in_registers) {
          result = x86_register_table_lookup(builder, module, is_float, table, index);
        } else {
          const GatherStrategy memory = in_register ? GatherStrategy::hardware : strategy;
          result = memory_lookup(builder, memory, element, table, index, width);
        }
        builder.CreateStore(result, out);
        builder.CreateRetVoid();
      }
    }
  }
}

}  // namespace shadetree

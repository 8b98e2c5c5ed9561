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

}  // namespace

void define_table_lookups(llvm::Module& module, GatherStrategy strategy) {
  llvm::LLVMContext& context = module.getContext();
  for (int width : {4, 8, 16}) {
    for (bool table256 : {false, true}) {
      for (bool is_float : {true, false}) {
        const std::string name = std::string(table256 ? "st_gather256_" : "st_gather_") + (is_float ? "f32" : "i32") +
                                 "_w" + std::to_string(width);
        llvm::Function* function = module.getFunction(name);
        if (!function || !function->isDeclaration()) continue;
        llvm::IRBuilder<> builder(llvm::BasicBlock::Create(context, "entry", function));
        llvm::Type* element = is_float ? builder.getFloatTy() : builder.getInt32Ty();
        auto* vector = llvm::FixedVectorType::get(element, static_cast<unsigned>(width));
        auto* index_type = llvm::FixedVectorType::get(builder.getInt32Ty(), static_cast<unsigned>(width));
        auto args = function->arg_begin();
        llvm::Value* out = &*args++;
        llvm::Value* table = &*args++;
        llvm::Value* index = builder.CreateLoad(index_type, &*args);
        llvm::Value* result;
        const bool byte_permutes = strategy == GatherStrategy::in_register_byte_permutes;
        const bool in_register = (strategy == GatherStrategy::in_register || byte_permutes) && width == 16;
        if (in_register && table256 && byte_permutes && !is_float) {
          result = x86_byte_table_lookup(builder, module, table, index);
        } else if (in_register && table256) {
          result = x86_register_table_lookup(builder, module, is_float, table, index);
        } else if (strategy == GatherStrategy::hardware || in_register) {
          result = builder.CreateMaskedGather(vector, builder.CreateInBoundsGEP(element, table, index), llvm::Align(4));
        } else {
          result = per_lane_lookup(builder, element, table, index, width);
        }
        builder.CreateStore(result, out);
        builder.CreateRetVoid();
      }
    }
  }
}

}  // namespace shadetree

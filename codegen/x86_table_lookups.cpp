#include "codegen/x86_table_lookups.h"

#include <algorithm>
#include <vector>

#include <llvm/IR/IRBuilder.h>
#include <llvm/IR/IntrinsicsX86.h>
#include <llvm/IR/Module.h>

namespace shadetree {

llvm::Value* x86_register_table_lookup(llvm::IRBuilderBase& builder, llvm::Module& module, bool is_float,
                                       llvm::Value* table, llvm::Value* index) {
  llvm::Type* element = is_float ? builder.getFloatTy() : builder.getInt32Ty();
  auto* vector = llvm::FixedVectorType::get(element, 16);
  llvm::Function* permute = llvm::Intrinsic::getDeclaration(
      &module, is_float ? llvm::Intrinsic::x86_avx512_vpermi2var_ps_512 : llvm::Intrinsic::x86_avx512_vpermi2var_d_512);
  std::vector<llvm::Value*> candidates;
  for (int pair = 0; pair < 8; ++pair) {
    llvm::Value* low = builder.CreateAlignedLoad(vector, builder.CreateConstInBoundsGEP1_32(element, table, 32 * pair),
                                                 llvm::Align(4));
    llvm::Value* high = builder.CreateAlignedLoad(
        vector, builder.CreateConstInBoundsGEP1_32(element, table, 32 * pair + 16), llvm::Align(4));
    candidates.push_back(builder.CreateCall(permute, {low, index, high}));
  }
  for (int bit = 5; bit < 8; ++bit) {
    llvm::Value* take_high = builder.CreateICmpNE(
        builder.CreateAnd(index, builder.CreateVectorSplat(16, builder.getInt32(1u << bit))),
        llvm::ConstantAggregateZero::get(index->getType()));
    std::vector<llvm::Value*> chosen;
    for (std::size_t c = 0; c < candidates.size(); c += 2)
      chosen.push_back(builder.CreateSelect(take_high, candidates[c + 1], candidates[c]));
    candidates = std::move(chosen);
  }
  return candidates[0];
}

namespace {

// The mask {first, first + 1, ..., first + count - 1} of a shuffle.
std::vector<int> lanes_from(int first, int count) {
  std::vector<int> lanes(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) lanes[static_cast<std::size_t>(i)] = first + i;
  return lanes;
}

// The 64 bytes that `byte_index` (64 indices into the table, as bytes)
// picks from the table's 256 ints narrowed to bytes: the table as four
// 64-byte registers (loop-invariant: hoisted out of the sample loop), two
// vpermi2b on each index's low 7 bits and a select on bit 7.
llvm::Value* byte_permute(llvm::IRBuilderBase& builder, llvm::Module& module, llvm::Value* table,
                          llvm::Value* byte_index) {
  auto* bytes = llvm::FixedVectorType::get(builder.getInt8Ty(), 64);
  auto* ints = llvm::FixedVectorType::get(builder.getInt32Ty(), 16);
  llvm::Function* permute = llvm::Intrinsic::getDeclaration(&module, llvm::Intrinsic::x86_avx512_vpermi2var_qi_512);
  std::vector<llvm::Value*> quarters;
  for (int quarter = 0; quarter < 4; ++quarter) {
    std::vector<llvm::Value*> parts;
    for (int part = 0; part < 4; ++part) {
      llvm::Value* chunk = builder.CreateAlignedLoad(
          ints, builder.CreateConstInBoundsGEP1_32(builder.getInt32Ty(), table, 64 * quarter + 16 * part),
          llvm::Align(4));
      parts.push_back(builder.CreateTrunc(chunk, llvm::FixedVectorType::get(builder.getInt8Ty(), 16)));
    }
    quarters.push_back(builder.CreateShuffleVector(builder.CreateShuffleVector(parts[0], parts[1], lanes_from(0, 32)),
                                                   builder.CreateShuffleVector(parts[2], parts[3], lanes_from(0, 32)),
                                                   lanes_from(0, 64)));
  }
  llvm::Value* low_half = builder.CreateCall(permute, {quarters[0], byte_index, quarters[1]});
  llvm::Value* high_half = builder.CreateCall(permute, {quarters[2], byte_index, quarters[3]});
  llvm::Value* upper = builder.CreateICmpSLT(byte_index, llvm::Constant::getNullValue(bytes));  // bit 7
  return builder.CreateSelect(upper, high_half, low_half);
}

// 16 int indices as bytes.
llvm::Value* narrow_index(llvm::IRBuilderBase& builder, llvm::Value* index) {
  return builder.CreateTrunc(index, llvm::FixedVectorType::get(builder.getInt8Ty(), 16));
}

// Byte indices as the first lanes of a 64-byte index register (the lanes
// after them look up entry 0, and are not read).
llvm::Value* index_register(llvm::IRBuilderBase& builder, llvm::Value* byte_indices) {
  const int count = static_cast<int>(llvm::cast<llvm::FixedVectorType>(byte_indices->getType())->getNumElements());
  std::vector<int> lanes = lanes_from(0, 64);
  for (int& lane : lanes) lane = std::min(lane, count);  // lane `count`: the first of the zeros
  return builder.CreateShuffleVector(byte_indices, llvm::Constant::getNullValue(byte_indices->getType()), lanes);
}

// 16 looked-up bytes from `first` on, as ints.
llvm::Value* widen_result(llvm::IRBuilderBase& builder, llvm::Value* chosen, int first) {
  return builder.CreateZExt(builder.CreateShuffleVector(chosen, lanes_from(first, 16)),
                            llvm::FixedVectorType::get(builder.getInt32Ty(), 16));
}

}  // namespace

llvm::Value* x86_byte_table_lookup(llvm::IRBuilderBase& builder, llvm::Module& module, llvm::Value* table,
                                   llvm::Value* index) {
  llvm::Value* byte_index = index_register(builder, narrow_index(builder, index));
  return widen_result(builder, byte_permute(builder, module, table, byte_index), 0);
}

std::pair<llvm::Value*, llvm::Value*> x86_byte_table_pair_lookup(llvm::IRBuilderBase& builder, llvm::Module& module,
                                                                   llvm::Value* table, llvm::Value* index) {
  // index and index + 1 as bytes 0-15 and 16-31 (a byte's add wraps mod 256).
  llvm::Value* narrow = narrow_index(builder, index);
  llvm::Value* next = builder.CreateAdd(narrow, llvm::ConstantInt::get(narrow->getType(), 1));
  llvm::Value* byte_index = index_register(builder, builder.CreateShuffleVector(narrow, next, lanes_from(0, 32)));
  llvm::Value* chosen = byte_permute(builder, module, table, byte_index);
  return {widen_result(builder, chosen, 0), widen_result(builder, chosen, 16)};
}

llvm::Value* x86_small_table_lookup(llvm::IRBuilderBase& builder, llvm::Module& module, llvm::Value* table,
                                    llvm::Value* size, llvm::Value* index) {
  auto* vector = llvm::FixedVectorType::get(builder.getFloatTy(), 16);
  llvm::Value* sizes = builder.CreateVectorSplat(16, size);
  // Lane i of the half from `first` holds entry first + i, read where it is below the size.
  auto half = [&](int first) {
    std::vector<llvm::Constant*> entries;
    for (int lane = 0; lane < 16; ++lane) entries.push_back(builder.getInt32(first + lane));
    llvm::Value* inside = builder.CreateICmpSLT(llvm::ConstantVector::get(entries), sizes);
    return builder.CreateMaskedLoad(vector, builder.CreateConstGEP1_32(builder.getFloatTy(), table, first),
                                    llvm::Align(4), inside, llvm::Constant::getNullValue(vector));
  };
  llvm::Function* permute = llvm::Intrinsic::getDeclaration(&module, llvm::Intrinsic::x86_avx512_vpermi2var_ps_512);
  return builder.CreateCall(permute, {half(0), index, half(16)});
}

}  // namespace shadetree

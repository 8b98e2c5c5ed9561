#include "jit/lane_index_chains.h"

#include <cstdint>
#include <vector>

#include <llvm/Analysis/VectorUtils.h>
#include <llvm/IR/Constants.h>
#include <llvm/IR/IRBuilder.h>
#include <llvm/IR/Instructions.h>
#include <llvm/IR/ValueHandle.h>
#include <llvm/Transforms/Utils/Local.h>

namespace shadetree {
namespace {

// How many operations deep a lane is followed: a chained lookup's index
// is the lookup's result plus a constant, masked to the table (two).
constexpr int max_depth = 3;

// `value` if it is an integer vector operation of two operands (lane by
// lane, as every binary operator is).
llvm::BinaryOperator* integer_vector_operation(llvm::Value* value) {
  auto* operation = llvm::dyn_cast<llvm::BinaryOperator>(value);
  return operation && operation->getType()->isVectorTy() && operation->getType()->isIntOrIntVectorTy() ? operation
                                                                                                      : nullptr;
}

// Whether lane `lane` of `value` is known as a scalar within `depth`
// operations: an inserted element, a constant's, or an operation on such.
bool lane_is_known(llvm::Value* value, unsigned lane, int depth) {
  if (llvm::findScalarElement(value, lane)) return true;
  llvm::BinaryOperator* operation = integer_vector_operation(value);
  return operation && depth > 0 && lane_is_known(operation->getOperand(0), lane, depth - 1) &&
         lane_is_known(operation->getOperand(1), lane, depth - 1);
}

// Lane `lane` of `value` (lane_is_known), built at `builder`.
llvm::Value* scalar_lane(llvm::Value* value, unsigned lane, llvm::IRBuilder<>& builder) {
  if (llvm::Value* known = llvm::findScalarElement(value, lane)) return known;
  llvm::BinaryOperator* operation = integer_vector_operation(value);
  llvm::Value* left = scalar_lane(operation->getOperand(0), lane, builder);
  llvm::Value* right = scalar_lane(operation->getOperand(1), lane, builder);
  llvm::Value* scalar = builder.CreateBinOp(operation->getOpcode(), left, right);
  if (auto* made = llvm::dyn_cast<llvm::Instruction>(scalar)) made->copyIRFlags(operation);
  return scalar;
}

}  // namespace

void index_lanes_in_general_registers(llvm::Function& function) {
  std::vector<llvm::ExtractElementInst*> extracts;
  for (llvm::BasicBlock& block : function)
    for (llvm::Instruction& instr : block)
      if (auto* extract = llvm::dyn_cast<llvm::ExtractElementInst>(&instr);
          extract && integer_vector_operation(extract->getVectorOperand()) &&
          llvm::isa<llvm::ConstantInt>(extract->getIndexOperand()))
        extracts.push_back(extract);
  // The vectors read are deleted once every lane is rewritten, if nothing
  // else reads them (the lookups' results usually are: they become floats).
  std::vector<llvm::WeakTrackingVH> read;
  for (llvm::ExtractElementInst* extract : extracts) {
    const auto* vector_type = llvm::dyn_cast<llvm::FixedVectorType>(extract->getVectorOperandType());
    const std::uint64_t lane = llvm::cast<llvm::ConstantInt>(extract->getIndexOperand())->getZExtValue();
    if (!vector_type || lane >= vector_type->getNumElements() ||
        !lane_is_known(extract->getVectorOperand(), static_cast<unsigned>(lane), max_depth))
      continue;
    llvm::IRBuilder<> builder(extract);
    llvm::Value* scalar = scalar_lane(extract->getVectorOperand(), static_cast<unsigned>(lane), builder);
    read.emplace_back(extract->getVectorOperand());
    extract->replaceAllUsesWith(scalar);
    extract->eraseFromParent();
  }
  for (llvm::WeakTrackingVH& vector : read)
    if (vector) llvm::RecursivelyDeleteTriviallyDeadInstructions(vector);
}

}  // namespace shadetree

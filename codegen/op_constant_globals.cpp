#include "codegen/op_constant_globals.h"

#include <vector>

#include <llvm/IR/Constants.h>
#include <llvm/IR/DerivedTypes.h>
#include <llvm/IR/GlobalVariable.h>
#include <llvm/IR/Module.h>

#include "codegen/emit_kernel.h"
#include "nodes/noise_tables.h"
#include "nodes/registry.h"

namespace shadetree {

OpConstantGlobals::OpConstantGlobals(const ShadeIR& ir, llvm::Module& module, const std::string& data_symbol)
    : module_(module) {
  llvm::LLVMContext& context = module.getContext();
  auto* ptr = llvm::PointerType::get(context, 0);
  auto* i32 = llvm::Type::getInt32Ty(context);
  type_ = llvm::StructType::get(context, {ptr, ptr, i32, llvm::ArrayType::get(i32, 2), i32,
                                          llvm::ArrayType::get(i32, max_op_args)});
  // The graph's data (spline knots, images, meshes) as raw bytes: LLVM
  // writes a byte array to the object in one piece, where it wrote an
  // array of floats one element at a time (2.4 MB of image took 40 ms).
  // Loads at constant offsets still fold. Large data is declared only
  // (max_embedded_data_bytes), and read through the global offset table.
  const std::size_t size = ir.data.size() * sizeof(float);
  auto* type = llvm::ArrayType::get(llvm::Type::getInt8Ty(context), size);
  if (size > max_embedded_data_bytes) {
    data_ = new llvm::GlobalVariable(module_, type, true, llvm::GlobalValue::ExternalLinkage, nullptr, data_symbol);
  } else if (size > 0) {
    const llvm::ArrayRef<std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(ir.data.data()), size);
    data_ = new llvm::GlobalVariable(module_, type, true, llvm::GlobalValue::InternalLinkage,
                                     llvm::ConstantDataArray::get(context, bytes), "shade_data");
  }
  if (data_) data_->setAlignment(llvm::Align(alignof(float)));
}

llvm::Constant* OpConstantGlobals::data_pointer(const IrInstr& instr) {
  if (!data_ || instr.data_count == 0) return llvm::ConstantPointerNull::get(llvm::PointerType::get(module_.getContext(), 0));
  auto* i64 = llvm::Type::getInt64Ty(module_.getContext());
  return llvm::ConstantExpr::getInBoundsGetElementPtr(
      data_->getValueType(), data_,
      llvm::ArrayRef<llvm::Constant*>{llvm::ConstantInt::get(i64, 0),
                                      llvm::ConstantInt::get(i64, static_cast<std::uint64_t>(instr.data_offset) * sizeof(float))});
}

llvm::Constant* OpConstantGlobals::noise_tables(std::uint32_t seed) {
  auto found = tables_.find(seed);
  if (found != tables_.end()) return found->second;
  llvm::LLVMContext& context = module_.getContext();
  const NoiseTables& tables = shadetree::noise_tables(seed);
  auto floats = [&](const GradientTable& values) {
    return llvm::ConstantDataArray::get(context, llvm::ArrayRef<float>(values.data(), values.size()));
  };
  llvm::Constant* fields[] = {
      llvm::ConstantDataArray::get(context, llvm::ArrayRef<float>(tables.hashed_gradient_xyzw.data(),
                                                                  tables.hashed_gradient_xyzw.size())),
      llvm::ConstantDataArray::get(context, llvm::ArrayRef<std::int32_t>(tables.permutation.data(),
                                                                          tables.permutation.size())),
      floats(tables.gradient_x),        floats(tables.gradient_y),        floats(tables.gradient_z),
      floats(tables.hashed_gradient_x), floats(tables.hashed_gradient_y), floats(tables.hashed_gradient_z)};
  llvm::Constant* initializer = llvm::ConstantStruct::getAnon(context, fields);
  auto* global = new llvm::GlobalVariable(module_, initializer->getType(), true, llvm::GlobalValue::InternalLinkage,
                                          initializer, "noise_tables_" + std::to_string(seed));
  global->setAlignment(llvm::Align(64));
  tables_[seed] = global;
  return global;
}

llvm::Constant* OpConstantGlobals::of(const IrInstr& instr) {
  auto* i32 = llvm::Type::getInt32Ty(module_.getContext());
  auto int_constant = [&](int value) { return llvm::ConstantInt::get(i32, static_cast<std::uint64_t>(value), true); };
  std::vector<llvm::Constant*> arg_components;
  for (int a = 0; a < max_op_args; ++a)
    arg_components.push_back(int_constant(a < instr.arg_count ? component_count(argument_type(instr, a)) : 0));
  llvm::Constant* tables = op_def(instr.op).tables == OpTables::noise
                               ? noise_tables(static_cast<std::uint32_t>(instr.immediate[0]))
                               : llvm::ConstantPointerNull::get(llvm::PointerType::get(module_.getContext(), 0));
  llvm::Constant* fields[] = {
      data_pointer(instr),
      tables,
      int_constant(instr.data_count),
      llvm::ConstantArray::get(llvm::ArrayType::get(i32, 2),
                               {int_constant(instr.immediate[0]), int_constant(instr.immediate[1])}),
      int_constant(component_count(instr.type)),
      llvm::ConstantArray::get(llvm::ArrayType::get(i32, max_op_args), arg_components)};
  return new llvm::GlobalVariable(module_, type_, true, llvm::GlobalValue::InternalLinkage,
                                  llvm::ConstantStruct::get(type_, fields), "op_constants");
}

}  // namespace shadetree

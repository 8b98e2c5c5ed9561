// Chained per-lane lookups indexed in general registers.
//
// A per-lane lookup (codegen/table_lookups.cpp) moves each lane's index
// out of a vector, loads that lane's value and inserts it into the result
// vector. Where the next lookup's index is computed from that result (a
// cellular cell's three hashes, Worley 1996: hash_y = phi(hash_x + 1),
// hash_z = phi(hash_y + 1)), every lane went back into a vector to be
// added to and moved out again. Instruction selection's DAG combiner
// found the scalar form itself, lane by lane, through its known-bits and
// demanded-elements analyses: half of a cellular kernel's code
// generation. Here each such lane is computed from the value loaded for
// it, by the same integer operations on scalars, before code generation.
// The values are the same to the bit (the operations are lane-wise).
#pragma once

namespace llvm {
class Function;
}

namespace shadetree {

// Rewrites every element extracted at a constant lane from an integer
// vector operation whose operands' lanes are known as scalars (inserted
// elements, constants, or such operations, a few levels deep) as the
// scalar operation on those lanes.
void index_lanes_in_general_registers(llvm::Function& function);

}  // namespace shadetree

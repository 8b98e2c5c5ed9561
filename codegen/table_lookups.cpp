#include "codegen/table_lookups.h"

#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <llvm/IR/IRBuilder.h>
#include <llvm/IR/Module.h>

#include "codegen/x86_table_lookups.h"
#include "nodes/noise_tables.h"

namespace shadetree {
namespace {

// A load of `loaded` (4-byte aligned) at entry `index` of a table of
// `element`s, in each lane, as the strategy does it where no register
// lookup applies. One lane at a time, the lane's index is moved out, not
// its address, and the load adds the table's address: a vector of
// addresses cost three vector instructions for each half of the lanes
// (widen, scale, add) before the same moves. An index is never negative
// (every table's is masked or clamped into it), so moving it out
// zero-extends it for free.
llvm::Value* memory_lookup(llvm::IRBuilder<>& builder, GatherStrategy strategy, llvm::Type* loaded, llvm::Type* element,
                           llvm::Value* table, llvm::Value* index, int width) {
  auto* vector = llvm::FixedVectorType::get(loaded, static_cast<unsigned>(width));
  if (strategy != GatherStrategy::per_lane)
    return builder.CreateMaskedGather(vector, builder.CreateInBoundsGEP(element, table, index), llvm::Align(4));
  llvm::Value* result = llvm::PoisonValue::get(vector);
  for (int lane = 0; lane < width; ++lane) {
    llvm::Value* entry = builder.CreateZExt(builder.CreateExtractElement(index, lane), builder.getInt64Ty());
    llvm::Value* address = builder.CreateInBoundsGEP(element, table, entry);
    result = builder.CreateInsertElement(result, builder.CreateAlignedLoad(loaded, address, llvm::Align(4)), lane);
  }
  return result;
}

llvm::Value* memory_lookup(llvm::IRBuilder<>& builder, GatherStrategy strategy, llvm::Type* element, llvm::Value* table,
                           llvm::Value* index, int width) {
  return memory_lookup(builder, strategy, element, element, table, index, width);
}

// How a kernel of one width looks up a 256-entry table.
struct Lookups256 {
  GatherStrategy memory;     // for tables not held in registers
  bool tables_in_registers;  // every 256-entry table in sixteen registers
  bool ints_as_bytes;        // int tables (the permutation) as bytes in four registers
};

llvm::Value* lookup256(llvm::IRBuilder<>& builder, llvm::Module& module, const Lookups256& how, bool is_float,
                       llvm::Value* table, llvm::Value* index, int width) {
  if (!is_float && how.ints_as_bytes) return x86_byte_table_lookup(builder, module, table, index);
  if (how.tables_in_registers) return x86_register_table_lookup(builder, module, is_float, table, index);
  llvm::Type* element = is_float ? builder.getFloatTy() : builder.getInt32Ty();
  return memory_lookup(builder, how.memory, element, table, index, width);
}

// A noise table's entries at index and index + 1 (mod 256), which
// nodes/noise_tables.h keeps adjacent (entry 0 again after the last). From
// memory, one 64-bit lookup per lane split into its two halves: half the
// loads of two 32-bit gathers. As bytes, both index vectors in one byte
// permute. From sixteen registers, two lookups.
std::pair<llvm::Value*, llvm::Value*> pair_lookup(llvm::IRBuilder<>& builder, llvm::Module& module,
                                                  const Lookups256& how, bool is_float, llvm::Value* table,
                                                  llvm::Value* index, int width) {
  if (!is_float && how.ints_as_bytes) return x86_byte_table_pair_lookup(builder, module, table, index);
  if (how.tables_in_registers) {
    llvm::Value* next_index = builder.CreateAnd(
        builder.CreateAdd(index, builder.CreateVectorSplat(width, builder.getInt32(1))),
        builder.CreateVectorSplat(width, builder.getInt32(noise_table_size - 1)));
    return {lookup256(builder, module, how, is_float, table, index, width),
            lookup256(builder, module, how, is_float, table, next_index, width)};
  }
  llvm::Type* element = is_float ? builder.getFloatTy() : builder.getInt32Ty();
  llvm::Value* pairs =
      builder.CreateBitCast(memory_lookup(builder, how.memory, builder.getInt64Ty(), element, table, index, width),
                            llvm::FixedVectorType::get(element, static_cast<unsigned>(2 * width)));
  // The entry at index is the pair's first half in memory: its low half on
  // a little-endian target.
  const int first_half = module.getDataLayout().isLittleEndian() ? 0 : 1;
  std::vector<int> firsts, seconds;
  for (int lane = 0; lane < width; ++lane) {
    firsts.push_back(2 * lane + first_half);
    seconds.push_back(2 * lane + 1 - first_half);
  }
  return {builder.CreateShuffleVector(pairs, firsts), builder.CreateShuffleVector(pairs, seconds)};
}

// st_gather256_pair_<type>_w<width>(at, next, table, index).
void define_pair_lookup(llvm::Module& module, const Lookups256& how, int width, bool is_float) {
  llvm::Function* function =
      module.getFunction(std::string("st_gather256_pair_") + (is_float ? "f32" : "i32") + "_w" + std::to_string(width));
  if (!function || !function->isDeclaration()) return;
  llvm::IRBuilder<> builder(llvm::BasicBlock::Create(module.getContext(), "entry", function));
  auto args = function->arg_begin();
  llvm::Value* at_out = &*args++;
  llvm::Value* next_out = &*args++;
  llvm::Value* table = &*args++;
  llvm::Value* index =
      builder.CreateLoad(llvm::FixedVectorType::get(builder.getInt32Ty(), static_cast<unsigned>(width)), &*args);
  const auto [at, next] = pair_lookup(builder, module, how, is_float, table, index, width);
  builder.CreateStore(at, at_out);
  builder.CreateStore(next, next_out);
  builder.CreateRetVoid();
}

// The mask of a shuffle that does the same within each group of four lanes
// (each 128-bit lane of an x86 register): `pattern` names four elements of
// the group as operand * 4 + element, operand 0 or 1.
std::vector<int> within_each_quad(int width, std::array<int, 4> pattern) {
  std::vector<int> mask;
  for (int group = 0; group < width / 4; ++group)
    for (int p : pattern) mask.push_back((p / 4) * width + 4 * group + p % 4);
  return mask;
}

// A lane's (x, y, z, w) entries of the interleaved gradient table from
// `slot` on (an i64), one 16-byte load per knot: [knot].
std::vector<llvm::Value*> interleaved_entries(llvm::IRBuilder<>& builder, llvm::Value* interleaved, llvm::Value* slot,
                                              int knots) {
  auto* quad = llvm::FixedVectorType::get(builder.getFloatTy(), 4);
  llvm::Value* at = builder.CreateInBoundsGEP(quad, interleaved, slot);
  std::vector<llvm::Value*> entries;
  for (int knot = 0; knot < knots; ++knot)
    entries.push_back(
        builder.CreateAlignedLoad(quad, builder.CreateConstInBoundsGEP1_32(quad, at, knot), llvm::Align(16)));
  return entries;
}

// `first` and `second` side by side, one vector twice as long.
llvm::Value* concatenated(llvm::IRBuilder<>& builder, llvm::Value* first, llvm::Value* second) {
  const int count = 2 * static_cast<int>(llvm::cast<llvm::FixedVectorType>(first->getType())->getNumElements());
  std::vector<int> all(static_cast<std::size_t>(count));
  for (int e = 0; e < count; ++e) all[static_cast<std::size_t>(e)] = e;
  return builder.CreateShuffleVector(first, second, all);
}

// Four registers of (x, y, z, w) quarters transposed within each quarter,
// as the four-by-four transpose of SSE code does: x, y, z, and with
// `components` 4 w (else null), each quarter holding that component of the
// four registers' same quarter.
std::array<llvm::Value*, 4> transposed_quarters(llvm::IRBuilder<>& builder, const std::array<llvm::Value*, 4>& rows,
                                                int width, int components) {
  llvm::Value* xy01 = builder.CreateShuffleVector(rows[0], rows[1], within_each_quad(width, {0, 4, 1, 5}));
  llvm::Value* xy23 = builder.CreateShuffleVector(rows[2], rows[3], within_each_quad(width, {0, 4, 1, 5}));
  llvm::Value* zw01 = builder.CreateShuffleVector(rows[0], rows[1], within_each_quad(width, {2, 6, 3, 7}));
  llvm::Value* zw23 = builder.CreateShuffleVector(rows[2], rows[3], within_each_quad(width, {2, 6, 3, 7}));
  std::array<llvm::Value*, 4> axes{builder.CreateShuffleVector(xy01, xy23, within_each_quad(width, {0, 1, 4, 5})),
                                   builder.CreateShuffleVector(xy01, xy23, within_each_quad(width, {2, 3, 6, 7})),
                                   builder.CreateShuffleVector(zw01, zw23, within_each_quad(width, {0, 1, 4, 5})),
                                   nullptr};
  if (components == 4) axes[3] = builder.CreateShuffleVector(zw01, zw23, within_each_quad(width, {2, 3, 6, 7}));
  return axes;
}

// The gradient components of `entries` ([knot][lane]: a lane's (x, y, z,
// w), as interleaved_entries reads them): lanes l, l + 4, l + 8, ... are
// put side by side (one register, a 128-bit quarter each) and four such
// registers transposed within each quarter. Returns x at each knot, then
// y, then z, then (with `components` 4, for 4D noise) w.
std::vector<llvm::Value*> transposed_gradients(llvm::IRBuilder<>& builder,
                                               const std::vector<std::vector<llvm::Value*>>& entries, int width,
                                               int components) {
  const int knots = static_cast<int>(entries.size());
  auto concatenate = [&](std::vector<llvm::Value*> parts) {
    while (parts.size() > 1) {
      std::vector<llvm::Value*> joined;
      for (std::size_t i = 0; i < parts.size(); i += 2) joined.push_back(concatenated(builder, parts[i], parts[i + 1]));
      parts = std::move(joined);
    }
    return parts[0];
  };
  std::vector<llvm::Value*> gradients(static_cast<std::size_t>(components * knots));
  for (int knot = 0; knot < knots; ++knot) {
    std::array<llvm::Value*, 4> rows;  // rows[k]: lanes k, k + 4, ... side by side
    for (int k = 0; k < 4; ++k) {
      std::vector<llvm::Value*> parts;
      for (int lane = k; lane < width; lane += 4)
        parts.push_back(entries[static_cast<std::size_t>(knot)][static_cast<std::size_t>(lane)]);
      rows[static_cast<std::size_t>(k)] = concatenate(parts);
    }
    const std::array<llvm::Value*, 4> axes = transposed_quarters(builder, rows, width, components);
    for (int axis = 0; axis < components; ++axis)
      gradients[static_cast<std::size_t>(axis * knots + knot)] = axes[static_cast<std::size_t>(axis)];
  }
  return gradients;
}

// The gradient components of `pairs` ([lane]: a lane's two adjacent
// knots, (x, y, z, w) twice, as one 32-byte load reads them), at 8 or 16
// lanes: lanes j and j + 8 are put side by side (at 8 lanes, lane j
// alone), so that each 128-bit quarter holds one knot of one lane; four
// such registers are transposed within each quarter, and each knot's
// lanes are then taken from the quarters of the two transposes. A knot
// per 16-byte load and lane took twice the loads and a third more
// shuffles. Returns x at both knots, then y, then z, then (with
// `components` 4) w.
std::vector<llvm::Value*> transposed_knot_pairs(llvm::IRBuilder<>& builder, const std::vector<llvm::Value*>& pairs,
                                                int width, int components) {
  std::array<llvm::Value*, 8> registers;  // lane j, and lane j + 8 beside it at 16 lanes
  for (std::size_t j = 0; j < registers.size(); ++j)
    registers[j] = width == 16 ? concatenated(builder, pairs[j], pairs[j + 8]) : pairs[j];
  const auto transposed = [&](std::size_t first) {
    return transposed_quarters(
        builder, {registers[first], registers[first + 1], registers[first + 2], registers[first + 3]}, width,
        components);
  };
  const std::array<llvm::Value*, 4> low = transposed(0), high = transposed(4);  // lanes 0-3 (8-11), 4-7 (12-15)
  std::vector<llvm::Value*> gradients;
  for (int axis = 0; axis < components; ++axis)
    for (int knot = 0; knot < 2; ++knot) {
      // Lanes 4 q to 4 q + 3 are quarter 2 (q / 2) + knot of the low
      // transpose (q even) or of the high one (q odd).
      std::vector<int> mask;
      for (int q = 0; q < width / 4; ++q)
        for (int e = 0; e < 4; ++e) mask.push_back((q % 2) * width + ((q / 2) * 2 + knot) * 4 + e);
      gradients.push_back(builder.CreateShuffleVector(low[static_cast<std::size_t>(axis)],
                                                      high[static_cast<std::size_t>(axis)], mask));
    }
  return gradients;
}

// Whether gradients are read from the interleaved table: where memory is
// read lane by lane, one load a lane gives a knot's three components.
bool reads_interleaved(const Lookups256& how) {
  return !how.tables_in_registers && how.memory == GatherStrategy::per_lane;
}

llvm::Value* noise_table(llvm::IRBuilder<>& builder, llvm::Value* tables, std::size_t offset) {
  return builder.CreateConstInBoundsGEP1_64(builder.getInt8Ty(), tables, offset);
}

// Stores `vectors` one after the other from `out` and returns.
void store_vectors(llvm::IRBuilder<>& builder, const std::vector<llvm::Value*>& vectors, llvm::Value* out) {
  for (std::size_t v = 0; v < vectors.size(); ++v)
    builder.CreateStore(vectors[v], builder.CreateConstInBoundsGEP1_64(vectors[v]->getType(), out, v));
  builder.CreateRetVoid();
}

// The gradients of the knots at each lane's slot (and with `knots` 2 at
// the slot + 1) from the interleaved table, one lane at a time:
// slot_of_lane(l) is lane l's slot, an i32. x at each knot, then y, then
// z, then with `components` 4 the 4D w.
template <class SlotOfLane>
std::vector<llvm::Value*> interleaved_gradients(llvm::IRBuilder<>& builder, llvm::Value* tables, int width, int knots,
                                                int components, SlotOfLane slot_of_lane) {
  llvm::Value* interleaved = noise_table(builder, tables, offsetof(NoiseTables, hashed_gradient_xyzw));
  if (knots == 2 && width >= 8) {
    auto* quad = llvm::FixedVectorType::get(builder.getFloatTy(), 4);
    auto* two_quads = llvm::FixedVectorType::get(builder.getFloatTy(), 8);
    std::vector<llvm::Value*> pairs;  // [lane]
    for (int lane = 0; lane < width; ++lane) {
      llvm::Value* slot = builder.CreateZExt(slot_of_lane(lane), builder.getInt64Ty());
      pairs.push_back(builder.CreateAlignedLoad(two_quads, builder.CreateInBoundsGEP(quad, interleaved, slot),
                                                llvm::Align(16)));
    }
    return transposed_knot_pairs(builder, pairs, width, components);
  }
  std::vector<std::vector<llvm::Value*>> entries(static_cast<std::size_t>(knots));  // [knot][lane]
  for (int lane = 0; lane < width; ++lane) {
    llvm::Value* slot = builder.CreateZExt(slot_of_lane(lane), builder.getInt64Ty());
    const std::vector<llvm::Value*> loaded = interleaved_entries(builder, interleaved, slot, knots);
    for (int knot = 0; knot < knots; ++knot) entries[static_cast<std::size_t>(knot)].push_back(loaded[knot]);
  }
  return transposed_gradients(builder, entries, width, components);
}

// The hashed gradients of the knots at slot `index` (and with `knots` 2
// at index + 1) by lookups of each component's table: x at each knot,
// then y, then z, then with `components` 4 the 4D w (gradient_x at the
// slot).
std::vector<llvm::Value*> knot_gradients(llvm::IRBuilder<>& builder, llvm::Module& module, const Lookups256& how,
                                         llvm::Value* tables, llvm::Value* index, int width, int knots,
                                         int components) {
  const std::array<std::size_t, 4> offsets{offsetof(NoiseTables, hashed_gradient_x),
                                           offsetof(NoiseTables, hashed_gradient_y),
                                           offsetof(NoiseTables, hashed_gradient_z), offsetof(NoiseTables, gradient_x)};
  std::vector<llvm::Value*> gradients;
  for (int axis = 0; axis < components; ++axis) {
    const std::size_t offset = offsets[static_cast<std::size_t>(axis)];
    if (knots == 2) {
      const auto [at, next] =
          pair_lookup(builder, module, how, true, noise_table(builder, tables, offset), index, width);
      gradients.insert(gradients.end(), {at, next});
    } else {
      gradients.push_back(lookup256(builder, module, how, true, noise_table(builder, tables, offset), index, width));
    }
  }
  return gradients;
}

// (index + hash) mod n, the slot a hash reaches from an index: vectors of
// `width` lanes or single lanes.
llvm::Value* slot_of(llvm::IRBuilder<>& builder, llvm::Value* index, llvm::Value* hash, int width) {
  llvm::Value* sum = builder.CreateAdd(index, hash);
  llvm::Value* last = builder.getInt32(noise_table_size - 1);
  return builder.CreateAnd(sum, sum->getType()->isVectorTy() ? builder.CreateVectorSplat(width, last) : last);
}

// Which knot-rows lookup: over 3 or 4 axes, with each axis's second cell
// hashed as its index + 1 (`adjacent`: the lattice, cell[axis] holding
// the index) or by an index of its own (an axis that wraps, cell[2 axis +
// d] holding cell d's).
struct KnotRowsShape {
  int dimensions;
  bool adjacent;
  int rows() const { return 1 << (dimensions - 1); }
  // Where cell d's index of `axis` is in the caller's block.
  int cell_group(int axis, int d) const { return adjacent ? axis : 2 * axis + d; }
};

// The gradients of a row's two knots read apart, each as x, y, z (and w),
// as x at both knots, then y, then z (then w): a row read in one go.
std::vector<llvm::Value*> side_by_side(const std::vector<llvm::Value*>& first,
                                       const std::vector<llvm::Value*>& second) {
  std::vector<llvm::Value*> row;
  for (std::size_t axis = 0; axis < first.size(); ++axis) row.insert(row.end(), {first[axis], second[axis]});
  return row;
}

// The rows of knots of the st_gather256_knot_rows lookups hashed a lane at
// a time in general registers: hashed in vector registers, every level's
// slots were moved out lane by lane and the pairs read there put back,
// seven moves out a lane in 3D, and such moves were an octave's bound on
// Zen 3 (docs/architecture.md). A loop over the lanes loads each lane's
// indices from `cell_at`, where the caller stored them, hashes them and
// keeps its rows' slots on the stack; then each row's entries are read
// lane by lane, each slot loaded back (a load, not a move out of a vector
// register), and transposed. Written out for every lane instead, the hash
// ran plain noise faster still (about 1.5x) but compiled the noise graphs
// 10-20% slower (turbulence, marble, wool); reading the entries inside
// the loop meant storing and loading them again for the transposes,
// which lost more than the loop saved.
std::vector<llvm::Value*> lane_hashed_knot_rows(llvm::IRBuilder<>& builder, llvm::Module& module,
                                                llvm::Value* tables, llvm::Value* cell_at, int width,
                                                const KnotRowsShape& shape) {
  llvm::Type* int32 = builder.getInt32Ty();
  const int slots_per_row = shape.adjacent ? 1 : 2;  // a row's second knot is its first + 1 where adjacent
  llvm::Value* permutation = noise_table(builder, tables, offsetof(NoiseTables, permutation));
  llvm::Value* slots = builder.CreateAlloca(
      llvm::ArrayType::get(int32, static_cast<std::uint64_t>(shape.rows() * slots_per_row * width)));
  // Element `lane` of group `group` of a [group][lane] block of i32s.
  const auto in_group = [&](int group, auto lane) {
    return builder.CreateAdd(builder.getInt64(static_cast<std::uint64_t>(group * width)), lane);
  };
  const auto entry_at = [&](llvm::Value* slot) {
    return builder.CreateInBoundsGEP(int32, permutation, builder.CreateZExt(slot, builder.getInt64Ty()));
  };
  // The permutation's entries at both cells of `axis` from `hash`: where
  // they are adjacent, the entry at a slot is its pair's first half in
  // memory.
  const bool little_endian = module.getDataLayout().isLittleEndian();
  std::vector<std::array<llvm::Value*, 2>> index;  // [axis][cell]
  const auto cells = [&](int axis, llvm::Value* hash) {
    const auto& at = index[static_cast<std::size_t>(axis)];
    const auto entry = [&](int d) -> llvm::Value* {
      return builder.CreateAlignedLoad(int32, entry_at(slot_of(builder, at[static_cast<std::size_t>(d)], hash, width)),
                                       llvm::Align(4));
    };
    if (!shape.adjacent) return std::array{entry(0), entry(1)};
    llvm::Value* both =
        builder.CreateAlignedLoad(builder.getInt64Ty(), entry_at(slot_of(builder, at[0], hash, width)), llvm::Align(4));
    llvm::Value* low = builder.CreateTrunc(both, int32);
    llvm::Value* high = builder.CreateTrunc(builder.CreateLShr(both, 32), int32);
    return little_endian ? std::array{low, high} : std::array{high, low};
  };
  llvm::Function* function = builder.GetInsertBlock()->getParent();
  llvm::BasicBlock* before = builder.GetInsertBlock();
  auto* lanes = llvm::BasicBlock::Create(module.getContext(), "hash_lanes", function);
  auto* hashed = llvm::BasicBlock::Create(module.getContext(), "lanes_hashed", function);
  builder.CreateBr(lanes);
  builder.SetInsertPoint(lanes);
  llvm::PHINode* lane = builder.CreatePHI(builder.getInt64Ty(), 2);
  lane->addIncoming(builder.getInt64(0), before);
  for (int axis = 0; axis < shape.dimensions; ++axis) {
    std::array<llvm::Value*, 2> at{};
    for (int d = 0; d < slots_per_row; ++d)
      at[static_cast<std::size_t>(d)] = builder.CreateAlignedLoad(
          int32, builder.CreateInBoundsGEP(int32, cell_at, in_group(shape.cell_group(axis, d), lane)), llvm::Align(4));
    index.push_back(at);
  }
  // From the outermost axis in, depth first: a hash reaches a pair of the
  // next axis's cells, and the rows come out in the order 4 dl + 2 dk + dj.
  const auto hash_rows = [&](const auto& self, int axis, llvm::Value* hash, int row) -> void {
    if (axis == 0) {
      for (int d = 0; d < slots_per_row; ++d)
        builder.CreateAlignedStore(slot_of(builder, index[0][static_cast<std::size_t>(d)], hash, width),
                                   builder.CreateInBoundsGEP(int32, slots, in_group(slots_per_row * row + d, lane)),
                                   llvm::Align(4));
      return;
    }
    const auto pair = cells(axis, hash);
    for (int d = 0; d < 2; ++d) self(self, axis - 1, pair[static_cast<std::size_t>(d)], 2 * row + d);
  };
  hash_rows(hash_rows, shape.dimensions - 1, builder.getInt32(0), 0);
  llvm::Value* next = builder.CreateAdd(lane, builder.getInt64(1));
  lane->addIncoming(next, lanes);
  builder.CreateCondBr(builder.CreateICmpULT(next, builder.getInt64(static_cast<std::uint64_t>(width))), lanes, hashed);
  builder.SetInsertPoint(hashed);
  // The gradients of `knots` knots on from the slots of group `group`.
  const auto read = [&](int group, int knots) {
    return interleaved_gradients(builder, tables, width, knots, shape.dimensions, [&](int lane) {
      llvm::Value* at = builder.CreateInBoundsGEP(int32, slots, in_group(group, builder.getInt64(lane)));
      return builder.CreateAlignedLoad(int32, at, llvm::Align(4));
    });
  };
  std::vector<llvm::Value*> gradients;
  for (int row = 0; row < shape.rows(); ++row) {
    const std::vector<llvm::Value*> row_gradients =
        shape.adjacent ? read(row, 2) : side_by_side(read(2 * row, 1), read(2 * row + 1, 1));
    gradients.insert(gradients.end(), row_gradients.begin(), row_gradients.end());
  }
  return gradients;
}

// The same rows hashed in vector registers, by the strategy's lookups.
// With the permutation as bytes in registers and the gradients read lane
// by lane (bytes and per-lane at 16 lanes), the rows of the lattice are
// hashed here, a few byte permutes a level for all lanes at once where the
// lane loop spent about 25 instructions a lane, and read lane by lane as
// that loop's rows are: on Zen 5, noise 182-187 -> 231-250, turbulence
// 26.3 -> 30.8 and marble 20 -> 23 M samples/s at one thread
// (docs/architecture.md). The periodic (apart) rows stay with the loop:
// hashed here they compiled 5-10 ms slower (looping_turbulence,
// tileable_stones), past the 50 ms that a gallery graph's compile is held to.
std::vector<llvm::Value*> vector_hashed_knot_rows(llvm::IRBuilder<>& builder, llvm::Module& module,
                                                  const Lookups256& how, llvm::Value* tables, llvm::Value* cell_at,
                                                  int width, const KnotRowsShape& shape) {
  auto* index_type = llvm::FixedVectorType::get(builder.getInt32Ty(), static_cast<unsigned>(width));
  const auto index = [&](int axis, int d) {
    return builder.CreateLoad(index_type,
                              builder.CreateConstInBoundsGEP1_32(index_type, cell_at, shape.cell_group(axis, d)));
  };
  llvm::Value* permutation = noise_table(builder, tables, offsetof(NoiseTables, permutation));
  std::vector<llvm::Value*> hashes{llvm::Constant::getNullValue(index_type)};
  for (int axis = shape.dimensions - 1; axis >= 1; --axis) {
    llvm::Value* first = index(axis, 0);
    llvm::Value* second = shape.adjacent ? nullptr : index(axis, 1);
    std::vector<llvm::Value*> inner;
    for (llvm::Value* hash : hashes) {
      if (shape.adjacent) {
        const auto [at, next] =
            pair_lookup(builder, module, how, false, permutation, slot_of(builder, first, hash, width), width);
        inner.insert(inner.end(), {at, next});
      } else {
        for (llvm::Value* cell : {first, second})
          inner.push_back(
              lookup256(builder, module, how, false, permutation, slot_of(builder, cell, hash, width), width));
      }
    }
    hashes = std::move(inner);
  }
  llvm::Value* i = index(0, 0);
  llvm::Value* next_i = shape.adjacent ? nullptr : index(0, 1);
  // Where memory is read lane by lane, each row's slots are stored and
  // loaded back a lane at a time. Moved out of the vector register instead
  // (extracts), the kernels ran up to a tenth faster but compiled about
  // 10 ms slower (stf_multi, ocean, wool, tribble); the store is volatile
  // so that no pass turns the loads back into such moves.
  llvm::Value* stored_slots = reads_interleaved(how) ? builder.CreateAlloca(index_type) : nullptr;
  const auto knots = [&](llvm::Value* cell, llvm::Value* hash, int count) {
    llvm::Value* slots = slot_of(builder, cell, hash, width);
    if (!stored_slots) return knot_gradients(builder, module, how, tables, slots, width, count, shape.dimensions);
    builder.CreateStore(slots, stored_slots, /*isVolatile=*/true);
    return interleaved_gradients(builder, tables, width, count, shape.dimensions, [&](int lane) {
      return builder.CreateAlignedLoad(builder.getInt32Ty(),
                                       builder.CreateConstInBoundsGEP1_32(builder.getInt32Ty(), stored_slots, lane),
                                       llvm::Align(4));
    });
  };
  std::vector<llvm::Value*> gradients;
  for (llvm::Value* hash : hashes) {
    const std::vector<llvm::Value*> row =
        shape.adjacent ? knots(i, hash, 2) : side_by_side(knots(i, hash, 1), knots(next_i, hash, 1));
    gradients.insert(gradients.end(), row.begin(), row.end());
  }
  return gradients;
}

// st_gather256_knot_rows_w<width>(out, tables, cell): the gradients of
// the four rows of knots around lattice cell (i, j, k) = cell[0..2], as
// nodes/semantics/noise.h's for_each_noise_row hashes them: row 2 dk + dj
// at slot (i + phi(j + phi(k)[dk])[dj]) mod n, its two knots' x, y and z.
// st_gather256_knot_rows4_w<width>, the eight rows around (i, j, k, l) as
// nodes/semantics/noise4.h hashes them, row 4 dl + 2 dk + dj, its two
// knots' x, y, z and w. The _apart forms hash each axis's two cells by
// their own indices (cell[2 axis + d]). Lane by lane where memory is read
// lane by lane.
void define_knot_rows_lookup(llvm::Module& module, const Lookups256& how, int width, const KnotRowsShape& shape) {
  llvm::Function* function = module.getFunction(std::string("st_gather256_knot_rows") +
                                                (shape.dimensions == 4 ? "4" : "") + (shape.adjacent ? "" : "_apart") +
                                                "_w" + std::to_string(width));
  if (!function || !function->isDeclaration()) return;
  llvm::IRBuilder<> builder(llvm::BasicBlock::Create(module.getContext(), "entry", function));
  auto args = function->arg_begin();
  llvm::Value* out = &*args++;
  llvm::Value* tables = &*args++;
  llvm::Value* cell_at = &*args;
  store_vectors(builder,
                reads_interleaved(how) && !(how.ints_as_bytes && shape.adjacent)
                    ? lane_hashed_knot_rows(builder, module, tables, cell_at, width, shape)
                    : vector_hashed_knot_rows(builder, module, how, tables, cell_at, width, shape),
                out);
}

// A table of at most `width` entries `stride` floats apart as one vector
// (entries past `count` repeat the last, so nothing beyond the table is
// read), each lane picking its entry by index. Written as generic IR, a
// build of elements extracted at variable lanes, which the x86 back end
// turns into one variable permute (vpermps or vpermd at 8 lanes, their
// 512-bit forms at 16) where the target has one: no load per lane. A
// kernel's spline knots are constant data, so the vector folds to a
// constant.
llvm::Value* vector_table_lookup(llvm::IRBuilder<>& builder, llvm::Value* table, llvm::Value* count,
                                 llvm::Value* stride, llvm::Value* index, int width) {
  auto* vector = llvm::FixedVectorType::get(builder.getFloatTy(), static_cast<unsigned>(width));
  llvm::Value* last = builder.CreateSub(count, builder.getInt32(1));
  llvm::Value* entries = llvm::PoisonValue::get(vector);
  for (int lane = 0; lane < width; ++lane) {
    llvm::Value* entry = builder.CreateBinaryIntrinsic(llvm::Intrinsic::smin, builder.getInt32(lane), last);
    llvm::Value* address = builder.CreateInBoundsGEP(builder.getFloatTy(), table, builder.CreateMul(entry, stride));
    llvm::Value* knot = builder.CreateAlignedLoad(builder.getFloatTy(), address, llvm::Align(4));
    entries = builder.CreateInsertElement(entries, knot, lane);
  }
  llvm::Value* lanes = builder.CreateAnd(index, builder.CreateVectorSplat(width, builder.getInt32(width - 1)));
  llvm::Value* result = llvm::PoisonValue::get(vector);
  for (int lane = 0; lane < width; ++lane)
    result = builder.CreateInsertElement(
        result, builder.CreateExtractElement(entries, builder.CreateExtractElement(lanes, lane)), lane);
  return result;
}

// st_gather_small_f32_w<width>(out, table, count, stride, index): entry
// index of `count` floats `stride` apart (one component of a spline's
// knots). In one vector where they fit; else, in the AVX-512 strategies
// that hold tables in registers, from two registers where their span does
// (x86_small_table_entries); else as any gather. The branches on count
// and stride fold away when inlined into a kernel.
void define_small_table_lookup(llvm::Module& module, GatherStrategy strategy, int width, bool in_register) {
  llvm::Function* function = module.getFunction("st_gather_small_f32_w" + std::to_string(width));
  if (!function || !function->isDeclaration()) return;
  llvm::LLVMContext& context = module.getContext();
  llvm::IRBuilder<> builder(llvm::BasicBlock::Create(context, "entry", function));
  auto args = function->arg_begin();
  llvm::Value* out = &*args++;
  llvm::Value* table = &*args++;
  llvm::Value* count = &*args++;
  llvm::Value* stride = &*args++;
  llvm::Value* index =
      builder.CreateLoad(llvm::FixedVectorType::get(builder.getInt32Ty(), static_cast<unsigned>(width)), &*args);
  auto* one_vector = llvm::BasicBlock::Create(context, "one_vector", function);
  auto* larger = llvm::BasicBlock::Create(context, "larger", function);
  builder.CreateCondBr(builder.CreateICmpSLE(count, builder.getInt32(width)), one_vector, larger);
  builder.SetInsertPoint(one_vector);
  builder.CreateStore(vector_table_lookup(builder, table, count, stride, index, width), out);
  builder.CreateRetVoid();
  builder.SetInsertPoint(larger);
  llvm::Value* entries = builder.CreateMul(index, builder.CreateVectorSplat(width, stride));
  if (!in_register) {
    builder.CreateStore(memory_lookup(builder, strategy, builder.getFloatTy(), table, entries, width), out);
    builder.CreateRetVoid();
    return;
  }
  llvm::Value* span = builder.CreateAdd(builder.CreateMul(builder.CreateSub(count, builder.getInt32(1)), stride),
                                        builder.getInt32(1));
  auto* registers = llvm::BasicBlock::Create(context, "registers", function);
  auto* memory = llvm::BasicBlock::Create(context, "memory", function);
  builder.CreateCondBr(builder.CreateICmpSLE(span, builder.getInt32(x86_small_table_entries)), registers, memory);
  builder.SetInsertPoint(registers);
  builder.CreateStore(x86_small_table_lookup(builder, module, table, span, entries), out);
  builder.CreateRetVoid();
  builder.SetInsertPoint(memory);
  builder.CreateStore(memory_lookup(builder, GatherStrategy::hardware, builder.getFloatTy(), table, entries, width),
                      out);
  builder.CreateRetVoid();
}

// How a strategy reads the tables it does not hold in registers.
GatherStrategy memory_strategy(GatherStrategy strategy) {
  switch (strategy) {
    case GatherStrategy::per_lane:
    case GatherStrategy::byte_permutes_and_per_lane:
      return GatherStrategy::per_lane;
    default:
      return GatherStrategy::hardware;
  }
}

}  // namespace

void define_table_lookups(llvm::Module& module, GatherStrategy strategy) {
  const bool byte_permutes = strategy == GatherStrategy::in_register_byte_permutes ||
                             strategy == GatherStrategy::byte_permutes_and_gathers ||
                             strategy == GatherStrategy::byte_permutes_and_per_lane;
  const bool float_tables_in_registers =
      strategy == GatherStrategy::in_register || strategy == GatherStrategy::in_register_byte_permutes;
  const bool register_strategy = float_tables_in_registers || byte_permutes;
  llvm::LLVMContext& context = module.getContext();
  for (int width : {4, 8, 16}) {
    const bool in_register = register_strategy && width == 16;
    const Lookups256 how{memory_strategy(strategy), in_register && float_tables_in_registers,
                         in_register && byte_permutes};
    // Tables of any size (a mesh's distance grid, an image) by one gather
    // an instruction where per-lane reads only pay for noise rows.
    const GatherStrategy large_tables =
        strategy == GatherStrategy::byte_permutes_and_per_lane ? GatherStrategy::hardware : how.memory;
    define_small_table_lookup(module, memory_strategy(strategy), width, in_register);
    for (int dimensions : {3, 4})
      for (bool adjacent : {true, false}) define_knot_rows_lookup(module, how, width, {dimensions, adjacent});
    for (bool is_float : {true, false}) {
      define_pair_lookup(module, how, width, is_float);
      for (bool table256 : {false, true}) {
        const std::string name = std::string(table256 ? "st_gather256_" : "st_gather_") + (is_float ? "f32" : "i32") +
                                 "_w" + std::to_string(width);
        llvm::Function* function = module.getFunction(name);
        if (!function || !function->isDeclaration()) continue;
        llvm::IRBuilder<> builder(llvm::BasicBlock::Create(context, "entry", function));
        auto* index_type = llvm::FixedVectorType::get(builder.getInt32Ty(), static_cast<unsigned>(width));
        auto args = function->arg_begin();
        llvm::Value* out = &*args++;
        llvm::Value* table = &*args++;
        llvm::Value* index = builder.CreateLoad(index_type, &*args);
        llvm::Type* element = is_float ? builder.getFloatTy() : builder.getInt32Ty();
        builder.CreateStore(table256 ? lookup256(builder, module, how, is_float, table, index, width)
                                     : memory_lookup(builder, large_tables, element, table, index, width),
                            out);
        builder.CreateRetVoid();
      }
    }
  }
}

}  // namespace shadetree

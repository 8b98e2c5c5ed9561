// Compile-time attributes of a node (spline knots, a noise seed, table
// values) and their layout: each op that takes attributes lays them out
// itself, beside its semantics in nodes/ops/, as the constant data and the
// two immediates its instruction carries (nodes/op_frame.h: OpConstants).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "nodes/distance_grid.h"
#include "nodes/image.h"
#include "nodes/type.h"

namespace shadetree {

struct OpDef;

// An attribute as written: a number, a string, or a list whose items are
// numbers or number arrays.
struct AttributeValue {
  enum class Kind { number, text, list } kind = Kind::number;
  double number = 0;
  std::string text;
  std::vector<std::vector<float>> items;
  bool items_are_arrays = false;
};

// What an op's attributes become.
struct AttributeLayout {
  std::vector<float> data;
  std::int32_t immediate[2] = {0, 0};
  std::optional<Type> generic;  // T, for ops whose T comes from their knots
};

// A node's attributes as a layout function reads them. The checker
// implements lookup and failure, so that every fault is reported on the
// node with one line; the readers below validate the shapes ops share.
class Attributes {
 public:
  virtual ~Attributes() = default;

  // The attribute `name`, or null if the node leaves it out (a required
  // attribute left out is reported by the checker before layout).
  virtual const AttributeValue* find(const std::string& name) const = 0;
  [[noreturn]] virtual void fail(const std::string& message) const = 0;
  // The image file the attribute `name` names, read once per compile (at
  // most max_image_pixels).
  virtual const Image& image_file(const std::string& name) const = 0;
  // The mesh file the attribute `name` names as a signed distance grid,
  // `resolution` voxels along its longest side, read once per compile.
  virtual const DistanceGrid& mesh_distance_grid(const std::string& name, int resolution) const = 0;

  // A list of `minimum` to max_table_entries numbers or equally long number
  // arrays (1 to 3 components), appended to `data`; returns the components.
  int value_list(const std::string& name, int minimum, std::vector<float>& data) const;
  // The index of the attribute's text in `choices` (0, the default, if absent).
  int choice(const std::string& name, const std::vector<std::string>& choices) const;
  // [lo, hi] with lo != hi, or `fallback` if absent.
  std::pair<float, float> number_pair(const std::string& name, std::pair<float, float> fallback) const;
  // Rows of equally many numbers, appended row after row to `data`; returns
  // (rows, columns).
  std::pair<int, int> number_grid(const std::string& name, std::vector<float>& data) const;
  // An integer in [0, 2^32).
  std::uint32_t unsigned_integer(const std::string& name, std::uint32_t fallback) const;
};

// The type of knots of 1, 2 or 3 components: float, vec2, color.
Type type_of_knots(int components);

// Lays out `op`'s attributes: the noise seed for ops that read the noise
// tables, then the op's own layout, if it has one.
AttributeLayout lay_out_attributes(const OpDef& op, const Attributes& attributes);

}  // namespace shadetree

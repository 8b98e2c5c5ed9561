#include "nodes/attributes.h"

#include <cmath>

#include "nodes/limits.h"
#include "nodes/noise_tables.h"
#include "nodes/registry.h"

namespace shadetree {

int Attributes::value_list(const std::string& name, int minimum, std::vector<float>& data) const {
  const AttributeValue* value = find(name);
  if (!value || value->kind != AttributeValue::Kind::list)
    fail("attribute \"" + name + "\" must be a list of numbers or of [r, g, b] arrays");
  if (static_cast<int>(value->items.size()) < minimum || value->items.size() > static_cast<std::size_t>(max_table_entries))
    fail("attribute \"" + name + "\" needs " + std::to_string(minimum) + " to " + std::to_string(max_table_entries) +
         " values, got " + std::to_string(value->items.size()));
  const std::size_t components = value->items[0].size();
  if (components < 1 || components > 3)
    fail("attribute \"" + name + "\" values must be numbers or arrays of 2 or 3 numbers");
  for (const auto& item : value->items) {
    if (item.size() != components)
      fail("attribute \"" + name + "\" values must all have the same number of components");
    data.insert(data.end(), item.begin(), item.end());
  }
  return static_cast<int>(components);
}

int Attributes::choice(const std::string& name, const std::vector<std::string>& choices) const {
  const AttributeValue* value = find(name);
  if (!value) return 0;
  for (std::size_t i = 0; i < choices.size(); ++i)
    if (value->kind == AttributeValue::Kind::text && value->text == choices[i]) return static_cast<int>(i);
  std::string names;
  for (const std::string& choice : choices) names += (names.empty() ? "" : ", ") + choice;
  fail("attribute \"" + name + "\" must be one of: " + names);
}

std::pair<float, float> Attributes::number_pair(const std::string& name, std::pair<float, float> fallback) const {
  const AttributeValue* value = find(name);
  if (!value) return fallback;
  if (value->kind != AttributeValue::Kind::list || value->items.size() != 2 || value->items_are_arrays ||
      value->items[0][0] == value->items[1][0])
    fail("attribute \"" + name + "\" must be [lo, hi] with lo != hi");
  return {value->items[0][0], value->items[1][0]};
}

std::pair<int, int> Attributes::number_grid(const std::string& name, std::vector<float>& data) const {
  const AttributeValue* value = find(name);
  if (!value || value->kind != AttributeValue::Kind::list || value->items.empty() || !value->items_are_arrays)
    fail("attribute \"" + name + "\" must be a list of rows, each a list of numbers");
  const std::size_t columns = value->items[0].size();
  if (columns == 0 || value->items.size() * columns > static_cast<std::size_t>(max_table_entries))
    fail("attribute \"" + name + "\" must have 1 to " + std::to_string(max_table_entries) + " entries");
  for (const auto& row : value->items) {
    if (row.size() != columns) fail("attribute \"" + name + "\": all rows must have the same length");
    data.insert(data.end(), row.begin(), row.end());
  }
  return {static_cast<int>(value->items.size()), static_cast<int>(columns)};
}

std::uint32_t Attributes::unsigned_integer(const std::string& name, std::uint32_t fallback) const {
  const AttributeValue* value = find(name);
  if (!value) return fallback;
  if (value->kind != AttributeValue::Kind::number || value->number != std::floor(value->number) || value->number < 0 ||
      value->number > 4294967295.0)
    fail("attribute \"" + name + "\" must be an integer in [0, 4294967295]");
  return static_cast<std::uint32_t>(value->number);
}

Type type_of_knots(int components) {
  return components == 1 ? Type::float_ : components == 2 ? Type::vec2 : Type::color;
}

AttributeLayout lay_out_attributes(const OpDef& op, const Attributes& attributes) {
  AttributeLayout layout;
  if (op.tables == OpTables::noise)
    layout.immediate[0] = static_cast<std::int32_t>(attributes.unsigned_integer("seed", default_noise_seed));
  if (op.lay_out) op.lay_out(attributes, layout);
  return layout;
}

}  // namespace shadetree

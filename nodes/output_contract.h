// What each kind of graph outputs: one contract per kind, with a fixed
// plane layout, so that every driver, both backends, eval and bench agree
// on where each output lives without searching by name.
//
// A graph provides its kind's required outputs and any of the optional
// ones; a value of a convertible type (a float for a colour, say) is
// converted to the contract's type. Output planes are laid out in contract
// order, each output taking its type's components, whether or not the
// graph provides it: a driver reads an optional output only if the program
// says it is provided (see OutputLayout in ir/kernel.h).
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "nodes/graph_kind.h"
#include "nodes/type.h"

namespace shadetree {

// Every output name of every contract.
enum class OutputId : std::uint8_t { color, alpha, normal, specular, roughness, opacity, emission, density, ior, height };
inline constexpr int output_id_count = 10;

std::string_view output_id_name(OutputId id);

struct OutputSpec {
  OutputId id;
  std::string_view name;
  Type type;
  bool required;
  std::string_view doc;
};

// The outputs of graphs of `kind`, in layout order.
std::span<const OutputSpec> output_contract(GraphKind kind);

// The spec of output `name` in `kind`'s contract, or null.
const OutputSpec* find_output_spec(GraphKind kind, std::string_view name);

// Float planes of `kind`'s layout, and the first plane of each output
// (-1 where the contract has no such output).
int output_plane_count(GraphKind kind);
int output_first_plane(GraphKind kind, OutputId id);

}  // namespace shadetree

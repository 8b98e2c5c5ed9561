// The kinds of graph, each run by its own driver: a texture over an image
// grid, a surface shader at visible points of objects, a volume density at
// the samples of a ray march.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace shadetree {

enum class GraphKind : std::uint8_t { texture, surface, volume };

inline constexpr GraphKind all_graph_kinds[] = {GraphKind::texture, GraphKind::surface, GraphKind::volume};

constexpr std::string_view graph_kind_name(GraphKind kind) {
  return kind == GraphKind::texture ? "texture" : kind == GraphKind::surface ? "surface" : "volume";
}

constexpr std::optional<GraphKind> parse_graph_kind(std::string_view name) {
  for (GraphKind kind : all_graph_kinds)
    if (graph_kind_name(kind) == name) return kind;
  return std::nullopt;
}

// A set of graph kinds, as bits.
struct KindSet {
  std::uint8_t bits = 0;

  constexpr bool contains(GraphKind kind) const { return (bits >> static_cast<int>(kind)) & 1; }
  constexpr bool all() const { return bits == 7; }
};

constexpr KindSet kinds_of(GraphKind kind) { return {static_cast<std::uint8_t>(1 << static_cast<int>(kind))}; }
constexpr KindSet operator|(KindSet a, KindSet b) { return {static_cast<std::uint8_t>(a.bits | b.bits)}; }

// "surface or volume": the kinds of a set, for messages and docs.
inline std::string kind_set_names(KindSet kinds) {
  std::string names;
  for (GraphKind kind : all_graph_kinds)
    if (kinds.contains(kind)) names += (names.empty() ? "" : " or ") + std::string(graph_kind_name(kind));
  return names;
}

inline constexpr KindSet every_kind{7};
inline constexpr KindSet texture_kind = kinds_of(GraphKind::texture);
inline constexpr KindSet surface_kind = kinds_of(GraphKind::surface);
inline constexpr KindSet volume_kind = kinds_of(GraphKind::volume);

}  // namespace shadetree

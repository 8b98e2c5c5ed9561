// The kinds of graph, in one table as the ops are: what a kind is for and
// which parts of a graph file's "render" section it takes. Each kind also
// has a row in the output contracts (nodes/output_contract.cpp), provides
// some of the globals (nodes/globals.h), and is run by its driver
// (render/graph_kinds.h), which is all that a new kind adds.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace shadetree {

// The parts of a "render" section (graph/format_fields.cpp has their fields).
enum RenderSection : std::uint8_t {
  section_size = 1,     // "size": the image's width and height
  section_frame = 2,    // "frame": the frame rendered by default
  section_domain = 4,   // "domain" and "z": the rectangle of P an image spans
  section_scene = 8,    // "scene": camera, objects, lights, background
  section_volume = 16,  // "volume": the bounds and steps of a ray march
};

// Each part's field in the render section.
inline constexpr std::pair<RenderSection, std::string_view> render_section_fields[] = {
    {section_size, "size"}, {section_frame, "frame"}, {section_domain, "domain"}, {section_scene, "scene"},
    {section_volume, "volume"}};

// X(name, render sections it takes, render sections it needs, doc)
#define SHADETREE_GRAPH_KINDS(X)                                                                                  \
  X(texture, section_size | section_frame | section_domain, 0,                                                       \
    "a colour over a rectangle of P.xy, rendered as an image of it (Perlin 1985)")                                \
  X(surface, section_size | section_frame | section_scene, 0,                                                         \
    "a surface shader run at the visible points of a scene's objects (Perlin 1985, Rhoades et al. 1992)")          \
  X(volume, section_size | section_frame | section_scene | section_volume, section_volume,                             \
    "a density marched through a bounded volume (Perlin & Hoffert 1989)")                                         \
  X(environment, section_size | section_frame, 0,                                                                  \
    "a colour for every view direction I, rendered as a latitude-longitude panorama; a surface or volume "         \
    "scene names one as its background")

enum class GraphKind : std::uint8_t {
#define SHADETREE_GRAPH_KIND_ENUMERATOR(name, takes, needs, doc) name,
  SHADETREE_GRAPH_KINDS(SHADETREE_GRAPH_KIND_ENUMERATOR)
#undef SHADETREE_GRAPH_KIND_ENUMERATOR
};

struct GraphKindDef {
  GraphKind kind;
  std::string_view name;
  std::uint8_t render_sections;  // RenderSection bits it may have
  std::uint8_t needed_sections;  // and those it must have to be rendered
  std::string_view doc;
};

inline constexpr std::array graph_kind_defs = {
#define SHADETREE_GRAPH_KIND_DEF(name, takes, needs, doc) \
  GraphKindDef{GraphKind::name, #name, static_cast<std::uint8_t>(takes), static_cast<std::uint8_t>(needs), doc},
    SHADETREE_GRAPH_KINDS(SHADETREE_GRAPH_KIND_DEF)
#undef SHADETREE_GRAPH_KIND_DEF
};
inline constexpr int graph_kind_count = static_cast<int>(graph_kind_defs.size());

inline constexpr auto all_graph_kinds = [] {
  std::array<GraphKind, graph_kind_defs.size()> kinds{};
  for (std::size_t i = 0; i < kinds.size(); ++i) kinds[i] = graph_kind_defs[i].kind;
  return kinds;
}();

constexpr const GraphKindDef& graph_kind_def(GraphKind kind) { return graph_kind_defs[static_cast<int>(kind)]; }
constexpr std::string_view graph_kind_name(GraphKind kind) { return graph_kind_def(kind).name; }

constexpr std::optional<GraphKind> parse_graph_kind(std::string_view name) {
  for (GraphKind kind : all_graph_kinds)
    if (graph_kind_name(kind) == name) return kind;
  return std::nullopt;
}

// A set of graph kinds, as bits.
struct KindSet {
  std::uint8_t bits = 0;

  constexpr bool contains(GraphKind kind) const { return (bits >> static_cast<int>(kind)) & 1; }
  constexpr bool all() const { return bits == (1 << graph_kind_count) - 1; }
};
static_assert(graph_kind_count <= 8, "KindSet holds eight kinds");

constexpr KindSet kinds_of(GraphKind kind) { return {static_cast<std::uint8_t>(1 << static_cast<int>(kind))}; }
constexpr KindSet operator|(KindSet a, KindSet b) { return {static_cast<std::uint8_t>(a.bits | b.bits)}; }

// The kinds whose render section takes (or, with `needed`, must have) `section`.
constexpr KindSet kinds_taking(RenderSection section, bool needed = false) {
  KindSet kinds;
  for (const GraphKindDef& def : graph_kind_defs)
    if ((needed ? def.needed_sections : def.render_sections) & section) kinds = kinds | kinds_of(def.kind);
  return kinds;
}

// "surface or volume": the kinds of a set, for messages and docs.
inline std::string kind_set_names(KindSet kinds) {
  std::string names;
  for (GraphKind kind : all_graph_kinds)
    if (kinds.contains(kind)) names += (names.empty() ? "" : " or ") + std::string(graph_kind_name(kind));
  return names;
}

// "a texture graph", "an environment graph": a graph of `kind` in a sentence.
inline std::string a_graph_of(GraphKind kind) {
  const std::string_view name = graph_kind_name(kind);
  return std::string(name.find_first_of("aeiou") == 0 ? "an " : "a ") + std::string(name) + " graph";
}

inline constexpr KindSet every_kind{static_cast<std::uint8_t>((1 << graph_kind_count) - 1)};
inline constexpr KindSet texture_kind = kinds_of(GraphKind::texture);
inline constexpr KindSet surface_kind = kinds_of(GraphKind::surface);
inline constexpr KindSet volume_kind = kinds_of(GraphKind::volume);
inline constexpr KindSet environment_kind = kinds_of(GraphKind::environment);

}  // namespace shadetree

// The globals: every input a kernel can read, in one table. From it come
// the input ops of the node library (one op per global, same name), the
// plane layout of a kernel's sample inputs, the uniform block, the options
// of `shadetree eval` and the analysis of what a program reads, so that a
// driver fills only those planes. Open Shading Language's ShaderGlobals is
// the model.
//
// A varying global differs per sample and is passed as one plane of floats
// per component; a uniform one is the same for every sample of a call and
// is passed once, in the uniform block.
#pragma once

#include <array>
#include <bitset>
#include <cstdint>
#include <string_view>

#include "nodes/graph_kind.h"
#include "nodes/type.h"

namespace shadetree {

enum class Variability : std::uint8_t { uniform, varying };

// X(name, type, variability, kinds that provide it, doc)
#define SHADETREE_GLOBALS(X)                                                                                      \
  X(P, vec3, varying, every_kind, "sample position (object or texture space)")                                    \
  X(N, vec3, varying, every_kind, "surface normal at the sample (+z for textures)")                                \
  X(uv, vec2, varying, every_kind, "texture coordinates in [0,1]^2")                                               \
  X(I, vec3, varying, surface_kind | volume_kind | environment_kind,                                              \
    "unit direction from the eye to the sample (the ray direction)")                                              \
  X(surface, int_, varying, surface_kind, "id of the object the sample lies on")                                   \
  X(filter_width, float_, varying, every_kind,                                                                     \
    "sample footprint: pixel size in the units of P, for frequency clamping")                                      \
  X(density, float_, varying, volume_kind, "incoming density of a volume sample")                                   \
  X(L, vec3, varying, surface_kind, "unit direction from the sample toward the key light")                        \
  X(time, float_, uniform, every_kind, "time in seconds (frame / 24)")                                             \
  X(frame, float_, uniform, every_kind, "animation frame number")                                                  \
  X(step_size, float_, uniform, volume_kind, "the ray march step, in the units of P")                              \
  X(light_color, color, uniform, surface_kind, "colour of the key light")

enum class GlobalId : std::uint8_t {
#define SHADETREE_GLOBAL_ENUMERATOR(name, type, variability, kinds, doc) name,
  SHADETREE_GLOBALS(SHADETREE_GLOBAL_ENUMERATOR)
#undef SHADETREE_GLOBAL_ENUMERATOR
};

struct GlobalDef {
  GlobalId id;
  std::string_view name;
  Type type;
  Variability variability;
  KindSet kinds;
  std::string_view doc;
  int components;
  int first;  // first plane (varying) or first slot of the uniform block (uniform)
};

namespace detail {
constexpr auto make_globals() {
  std::array globals = {
#define SHADETREE_GLOBAL_DEF(name, type, variability, kinds, doc) \
  GlobalDef{GlobalId::name, #name, Type::type, Variability::variability, kinds, doc, component_count(Type::type), 0},
      SHADETREE_GLOBALS(SHADETREE_GLOBAL_DEF)
#undef SHADETREE_GLOBAL_DEF
  };
  int planes = 0, slots = 0;
  for (GlobalDef& global : globals) {
    int& next = global.variability == Variability::varying ? planes : slots;
    global.first = next;
    next += global.components;
  }
  return globals;
}
}  // namespace detail

inline constexpr auto globals = detail::make_globals();
inline constexpr int global_count = static_cast<int>(globals.size());

constexpr const GlobalDef& global_def(GlobalId id) { return globals[static_cast<std::size_t>(id)]; }

constexpr int count_floats(Variability variability) {
  int count = 0;
  for (const GlobalDef& global : globals)
    if (global.variability == variability) count += global.components;
  return count;
}

// Floats per sample (varying planes) and per call (the uniform block).
inline constexpr int varying_plane_count = count_floats(Variability::varying);
inline constexpr int uniform_value_count = count_floats(Variability::uniform);

// The global "time" is frame / frames_per_second.
inline constexpr float frames_per_second = 24.0f;

// Which globals a program reads.
using GlobalSet = std::bitset<globals.size()>;

}  // namespace shadetree

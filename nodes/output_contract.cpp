#include "nodes/output_contract.h"

namespace shadetree {
namespace {

constexpr OutputSpec texture_outputs[] = {
    {OutputId::color, "color", Type::color, true, "the texture colour (a float is shown as grey)"},
    {OutputId::alpha, "alpha", Type::float_, false, "coverage in [0,1]; the image gets an alpha channel"},
    {OutputId::height, "height", Type::float_, false,
     "height above the texture plane, in the units of P (bake: a height map, and the normal map's source)"},
    {OutputId::normal, "normal", Type::vec3, false,
     "tangent-space normal, +z out of the texture (bake: the normal map; default: from the height)"},
    {OutputId::roughness, "roughness", Type::float_, false, "roughness in [0,1] (bake: a roughness map)"},
};

constexpr OutputSpec surface_outputs[] = {
    {OutputId::color, "color", Type::color, true, "diffuse colour (or the final colour with lighting \"none\")"},
    {OutputId::normal, "normal", Type::vec3, false, "the shading normal, e.g. N perturbed by dnoise (Perlin 1985)"},
    {OutputId::specular, "specular", Type::float_, false, "weight of the specular lobe"},
    {OutputId::roughness, "roughness", Type::float_, false, "width of the specular lobe in [0,1]"},
    {OutputId::opacity, "opacity", Type::float_, false, "coverage in [0,1]"},
    {OutputId::emission, "emission", Type::color, false, "light emitted, added after lighting"},
};

constexpr OutputSpec volume_outputs[] = {
    {OutputId::density, "density", Type::float_, true, "density in [0,1] (Perlin & Hoffert 1989)"},
    {OutputId::color, "color", Type::color, false, "colour of the sample (a transfer function of density)"},
    {OutputId::opacity, "opacity", Type::float_, false, "opacity per reference step (default: the density)"},
    {OutputId::ior, "ior", Type::float_, false, "refractive index, for refraction where it changes"},
    {OutputId::normal, "normal", Type::vec3, false,
     "the lighting normal where the density is soft (default: the density's, -grad d / |grad d|)"},
};

constexpr OutputSpec environment_outputs[] = {
    {OutputId::color, "color", Type::color, true, "the colour seen in direction I"},
};

}  // namespace

std::string_view output_id_name(OutputId id) {
  constexpr std::string_view names[] = {"color",    "alpha",    "normal", "specular", "roughness",
                                        "opacity",  "emission", "density", "ior",      "height"};
  static_assert(std::size(names) == output_id_count);
  return names[static_cast<int>(id)];
}

// In the order of the kinds (nodes/graph_kind.h).
constexpr std::span<const OutputSpec> contracts[] = {texture_outputs, surface_outputs, volume_outputs,
                                                     environment_outputs};
static_assert(std::size(contracts) == graph_kind_count, "an output contract for every kind");

std::span<const OutputSpec> output_contract(GraphKind kind) { return contracts[static_cast<int>(kind)]; }

const OutputSpec* find_output_spec(GraphKind kind, std::string_view name) {
  for (const OutputSpec& spec : output_contract(kind))
    if (spec.name == name) return &spec;
  return nullptr;
}

int output_plane_count(GraphKind kind) {
  int planes = 0;
  for (const OutputSpec& spec : output_contract(kind)) planes += component_count(spec.type);
  return planes;
}

int output_first_plane(GraphKind kind, OutputId id) {
  int plane = 0;
  for (const OutputSpec& spec : output_contract(kind)) {
    if (spec.id == id) return plane;
    plane += component_count(spec.type);
  }
  return -1;
}

}  // namespace shadetree

// Baked texture sets (shadetree bake): a texture graph's outputs rendered
// at one size, one image each, as engines take them: colour, alpha,
// height, roughness, and a tangent-space normal map, which where the graph
// gives a height and no normal comes from the exact gradient of the
// height (graph/derived_normals.h), not from differences of the baked
// pixels.
#pragma once

#include <string>
#include <vector>

#include "nodes/output_contract.h"
#include "render/texture_driver.h"

namespace shadetree {

// The texture outputs a set can hold, in the order bake writes them.
inline constexpr OutputId bakeable_outputs[] = {OutputId::color, OutputId::alpha, OutputId::height, OutputId::normal,
                                                OutputId::roughness};

struct BakedMap {
  OutputId output;
  Image image;  // as the graph computes it (normals in [-1, 1])
};

struct BakedSet {
  std::vector<BakedMap> maps;
  // Whether the set repeats: the column past the right edge and the row
  // past the bottom, sampled as the image's own pixels are, equal the
  // first column and the top row in every map, bit for bit.
  bool tileable = false;
};

// The maps of `outputs` (each provided by the kernel's graph).
Result<BakedSet> bake_texture_set(const Kernel& kernel, const std::vector<float>& params, const TextureView& view,
                                  const std::vector<OutputId>& outputs, const TextureRenderOptions& options);

enum class NormalConvention { opengl, directx };

// A normal map's pixels as files hold them, 0.5 n + 0.5; the green channel
// points up the texture (OpenGL) or down it (DirectX).
Image encoded_normal_map(const Image& normals, NormalConvention convention);

}  // namespace shadetree

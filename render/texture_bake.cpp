#include "render/texture_bake.h"

#include <utility>

namespace shadetree {
namespace {

// The output planes of `output` in the kernel's layout.
std::vector<int> planes_of(const OutputLayout& layout, OutputId output) {
  std::vector<int> planes;
  for (const OutputSpec& spec : output_contract(GraphKind::texture))
    if (spec.id == output)
      for (int c = 0; c < component_count(spec.type); ++c) planes.push_back(layout.plane(output, c));
  return planes;
}

// The samples just past the right edge (column width, every row) and the
// bottom (row height, every column), beside those of the opposite edges.
bool wraps_around(const Kernel& kernel, const std::vector<float>& params, const TextureView& view,
                  const std::vector<std::vector<int>>& planes) {
  const std::size_t count = static_cast<std::size_t>(view.width + view.height);
  SampleBuffers past(count, kernel.reads()), first(count, kernel.reads());
  for (int row = 0; row < view.height; ++row) {
    store_texture_sample(past, static_cast<std::size_t>(row), texture_sample_at_pixel(view, view.width, row));
    store_texture_sample(first, static_cast<std::size_t>(row), texture_sample_at_pixel(view, 0, row));
  }
  for (int column = 0; column < view.width; ++column) {
    const std::size_t i = static_cast<std::size_t>(view.height + column);
    store_texture_sample(past, i, texture_sample_at_pixel(view, column, view.height));
    store_texture_sample(first, i, texture_sample_at_pixel(view, column, 0));
  }
  auto binding = kernel.bind(params.data(), texture_uniforms(view));
  OutputBuffers past_outputs(count, kernel.outputs()), first_outputs(count, kernel.outputs());
  binding->run(past.inputs(), past_outputs.planes(), count);
  binding->run(first.inputs(), first_outputs.planes(), count);
  for (const std::vector<int>& image : planes)
    for (int plane : image)
      for (std::size_t i = 0; i < count; ++i)
        if (past_outputs.plane(plane)[i] != first_outputs.plane(plane)[i]) return false;
  return true;
}

}  // namespace

Result<BakedSet> bake_texture_set(const Kernel& kernel, const std::vector<float>& params, const TextureView& view,
                                  const std::vector<OutputId>& outputs, const TextureRenderOptions& options) {
  const OutputLayout& layout = kernel.outputs();
  std::vector<std::vector<int>> planes;
  for (OutputId output : outputs) {
    if (!layout.provides(output))
      return invalid_input("the graph has no output \"" + std::string(output_id_name(output)) + "\" to bake");
    planes.push_back(planes_of(layout, output));
  }
  Result<std::vector<Image>> images = render_texture_outputs(kernel, params, view, planes, options);
  if (!images) return images.error();
  BakedSet set;
  for (std::size_t k = 0; k < outputs.size(); ++k) set.maps.push_back({outputs[k], std::move((*images)[k])});
  set.tileable = wraps_around(kernel, params, view, planes);
  return set;
}

Image encoded_normal_map(const Image& normals, NormalConvention convention) {
  Image encoded = normals;
  const float green = convention == NormalConvention::opengl ? 0.5f : -0.5f;
  for (std::size_t i = 0; i + 2 < encoded.pixels.size(); i += 3) {
    encoded.pixels[i] = 0.5f * normals.pixels[i] + 0.5f;
    encoded.pixels[i + 1] = green * normals.pixels[i + 1] + 0.5f;
    encoded.pixels[i + 2] = 0.5f * normals.pixels[i + 2] + 0.5f;
  }
  return encoded;
}

}  // namespace shadetree

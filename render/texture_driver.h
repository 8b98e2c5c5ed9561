// The 2D texture driver: evaluates a texture graph over an image grid, in
// parallel over tiles, through the Kernel interface.
#pragma once

#include <atomic>
#include <vector>

#include "graph/diagnostic.h"
#include "graph/graph.h"
#include "ir/kernel.h"
#include "nodes/image.h"
#include "render/graph_kinds.h"
#include "schedule/image_tiles.h"
#include "schedule/progress.h"

namespace shadetree {

struct TextureView {
  int width = 512;
  int height = 512;
  float domain_min[2] = {0.0f, 0.0f};  // P.xy at the lower-left image corner
  float domain_max[2] = {1.0f, 1.0f};  // P.xy at the upper-right image corner
  float z = 0.0f;
  float frame = 0.0f;

  static TextureView from_settings(const RenderSettings& settings);
};

// What the texture driver feeds a kernel for one point of the view.
struct TextureSample {
  float P[3];
  float uv[2];
  float filter_width;
};

// Writes a sample's inputs into sample i of `buffers` (those it stores):
// P, uv, filter_width, and N = +z.
void store_texture_sample(SampleBuffers& buffers, std::size_t i, const TextureSample& sample);

// The uniform globals of a view: time = frame / 24, frame.
UniformInputs texture_uniforms(const TextureView& view);

// Pixel (column, row), row 0 at the top, sampled at its centre.
TextureSample texture_sample_at_pixel(const TextureView& view, int column, int row);
// Any point: uv from its place in the domain, filter_width from pixel size.
TextureSample texture_sample_at_point(const TextureView& view, const float P[3]);

struct TextureRenderOptions {
  int threads = 0;  // 0: all cores
  ProgressCallback progress;  // may be empty
  const std::atomic<bool>* cancel = nullptr;  // see for_each_tile
  TileClaims* claims = nullptr;  // this process's tiles of the frame (for_each_tile); null: all
};

// Images of a texture graph's output planes (OutputLayout::plane): image k
// has a channel per plane of images[k], in that order. bake renders each
// output of a texture set this way, in one pass over the samples.
Result<std::vector<Image>> render_texture_outputs(const Kernel& kernel, const std::vector<float>& params,
                                                  const TextureView& view, const std::vector<std::vector<int>>& images,
                                                  const TextureRenderOptions& options);

// A texture graph's "color" and optional "alpha" (nodes/output_contract.h).
Result<Image> render_texture(const Kernel& kernel, const std::vector<float>& params, const TextureView& view,
                             const TextureRenderOptions& options);

// The kinds table's sample_at_point for textures: texture_sample_at_point
// in the view of the graph's render section at `size`.
PointSample texture_sample_at(const Graph& graph, std::pair<int, int> size, const float at[3], SampleBuffers& buffers);

// The texture row of the kinds table (render/graph_kinds.h): the view of
// the graph's render section at the requested size.
Result<std::unique_ptr<FrameRenderer>> prepare_texture(const Graph& graph, const RenderRequest& request);

}  // namespace shadetree

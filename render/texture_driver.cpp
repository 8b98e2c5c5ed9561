// The texture driver. P comes from the pixel centre through the view's
// domain transform, uv from the pixel's place in the image, and
// filter_width is the pixel's size in the units of P (the "pixelsize" of
// Perlin 1985's turbulence loop). Tiles are independent kernel calls, so
// the image is the same whatever the thread count.
#include "render/texture_driver.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "schedule/image_tiles.h"
#include "schedule/thread_bindings.h"

namespace shadetree {
namespace {

constexpr int tile_size = 64;

class TextureFrames : public FrameRenderer {
 public:
  TextureFrames(const TextureView& view, const RenderRequest& request) : view_(view) {
    options_.threads = request.threads;
    options_.cancel = request.cancel;
  }

  Result<Image> render_frame(const Kernel& kernel, const std::vector<float>& params, float frame,
                             const ProgressCallback& progress, TileClaims* claims,
                             FrameReport& report) const override {
    TextureView view = view_;
    view.frame = frame;
    TextureRenderOptions options = options_;
    options.progress = progress;
    options.claims = claims;
    report.kernel_samples = static_cast<long>(view.width) * view.height;
    report.what = std::to_string(view.width) + "x" + std::to_string(view.height) + ", " +
                  std::to_string(report.kernel_samples) + " samples";
    return render_texture(kernel, params, view, options);
  }

 private:
  TextureView view_;
  TextureRenderOptions options_;
};

}  // namespace

TextureView TextureView::from_settings(const RenderSettings& settings) {
  TextureView view;
  view.width = settings.width;
  view.height = settings.height;
  std::copy(settings.domain_min, settings.domain_min + 2, view.domain_min);
  std::copy(settings.domain_max, settings.domain_max + 2, view.domain_max);
  view.z = settings.z;
  view.frame = settings.frame;
  return view;
}

TextureSample texture_sample_at_point(const TextureView& view, const float P[3]) {
  const float span_x = view.domain_max[0] - view.domain_min[0];
  const float span_y = view.domain_max[1] - view.domain_min[1];
  TextureSample sample;
  std::copy(P, P + 3, sample.P);
  sample.uv[0] = (P[0] - view.domain_min[0]) / span_x;
  sample.uv[1] = (P[1] - view.domain_min[1]) / span_y;
  sample.filter_width = std::max(std::fabs(span_x) / view.width, std::fabs(span_y) / view.height);
  return sample;
}

void store_texture_sample(SampleBuffers& buffers, std::size_t i, const TextureSample& sample) {
  if (buffers.has(GlobalId::P))
    for (int c = 0; c < 3; ++c) buffers.plane(GlobalId::P, c)[i] = sample.P[c];
  if (buffers.has(GlobalId::N)) buffers.plane(GlobalId::N, 2)[i] = 1.0f;  // N = +z, facing the viewer
  if (buffers.has(GlobalId::uv))
    for (int c = 0; c < 2; ++c) buffers.plane(GlobalId::uv, c)[i] = sample.uv[c];
  if (buffers.has(GlobalId::filter_width)) buffers.plane(GlobalId::filter_width)[i] = sample.filter_width;
}

UniformInputs texture_uniforms(const TextureView& view) {
  UniformInputs uniforms;
  uniforms.set(GlobalId::time, view.frame / frames_per_second);
  uniforms.set(GlobalId::frame, view.frame);
  return uniforms;
}

TextureSample texture_sample_at_pixel(const TextureView& view, int column, int row) {
  const float u = (static_cast<float>(column) + 0.5f) / static_cast<float>(view.width);
  const float v = 1.0f - (static_cast<float>(row) + 0.5f) / static_cast<float>(view.height);
  const float P[3] = {view.domain_min[0] + u * (view.domain_max[0] - view.domain_min[0]),
                      view.domain_min[1] + v * (view.domain_max[1] - view.domain_min[1]), view.z};
  TextureSample sample = texture_sample_at_point(view, P);
  sample.uv[0] = u;
  sample.uv[1] = v;
  return sample;
}

Result<std::vector<Image>> render_texture_outputs(const Kernel& kernel, const std::vector<float>& params,
                                                  const TextureView& view, const std::vector<std::vector<int>>& images,
                                                  const TextureRenderOptions& options) {
  const OutputLayout& layout = kernel.outputs();
  if (layout.kind != GraphKind::texture) return invalid_input("the texture driver needs a texture graph");
  std::vector<Image> result(images.size());
  for (std::size_t k = 0; k < images.size(); ++k) {
    result[k].width = view.width;
    result[k].height = view.height;
    result[k].channels = static_cast<int>(images[k].size());
    result[k].pixels.assign(static_cast<std::size_t>(view.width) * view.height * images[k].size(), 0.0f);
  }

  ThreadBindings bindings(kernel, params.data(), texture_uniforms(view));

  auto render_tile = [&](const Tile& tile) -> long {
    const int x0 = tile.x0, y0 = tile.y0, w = tile.width, h = tile.height;
    const std::size_t count = static_cast<std::size_t>(w) * h;
    SampleBuffers input(count, kernel.reads());
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        store_texture_sample(input, static_cast<std::size_t>(y) * w + x, texture_sample_at_pixel(view, x0 + x, y0 + y));
    OutputBuffers outputs(count, layout);
    bindings.local().run(input.inputs(), outputs.planes(), count);

    for (std::size_t k = 0; k < images.size(); ++k) {
      Image& image = result[k];
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          const std::size_t i = static_cast<std::size_t>(y) * w + x;
          float* pixel = image.pixels.data() +
                         (static_cast<std::size_t>(y0 + y) * view.width + (x0 + x)) * image.channels;
          for (int c = 0; c < image.channels; ++c) pixel[c] = outputs.plane(images[k][static_cast<std::size_t>(c)])[i];
        }
    }
    return static_cast<long>(count);
  };
  if (Status done = for_each_tile(view.width, view.height, tile_size, options.threads, render_tile, options.progress,
                                  options.cancel, options.claims);
      !done)
    return done.error();
  return result;
}

Result<Image> render_texture(const Kernel& kernel, const std::vector<float>& params, const TextureView& view,
                             const TextureRenderOptions& options) {
  const OutputLayout& layout = kernel.outputs();
  if (layout.kind != GraphKind::texture || !layout.provides(OutputId::color))
    return invalid_input("the texture driver needs a texture graph with an output \"color\"");
  std::vector<int> planes = {layout.plane(OutputId::color, 0), layout.plane(OutputId::color, 1),
                             layout.plane(OutputId::color, 2)};
  if (layout.provides(OutputId::alpha)) planes.push_back(layout.plane(OutputId::alpha));
  Result<std::vector<Image>> images = render_texture_outputs(kernel, params, view, {planes}, options);
  if (!images) return images.error();
  return std::move(images->front());
}

Result<std::unique_ptr<FrameRenderer>> prepare_texture(const Graph& graph, const RenderRequest& request) {
  TextureView view = TextureView::from_settings(graph.render);
  if (request.size) std::tie(view.width, view.height) = *request.size;
  return std::unique_ptr<FrameRenderer>(std::make_unique<TextureFrames>(view, request));
}

PointSample texture_sample_at(const Graph& graph, std::pair<int, int> size, const float at[3], SampleBuffers& buffers) {
  TextureView view = TextureView::from_settings(graph.render);
  std::tie(view.width, view.height) = size;
  const TextureSample sample = texture_sample_at_point(view, at);
  store_texture_sample(buffers, 0, sample);
  return {{sample.P[0], sample.P[1], sample.P[2]}, {sample.uv[0], sample.uv[1]}, sample.filter_width};
}

}  // namespace shadetree

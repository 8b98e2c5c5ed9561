#include "render/graph_kinds.h"

#include <chrono>
#include <cstdio>

#include "render/environment_driver.h"
#include "render/surface_driver.h"
#include "render/texture_driver.h"
#include "render/volume_driver.h"

namespace shadetree {
namespace {

constexpr GraphKindDriver drivers[] = {
    // Surface and volume samples at a point are the texture's: P, uv over
    // the render domain and the pixel's filter width, N = +z.
    {GraphKind::texture, 0, "rendering", "samples", false, prepare_texture, nullptr, texture_sample_at, texture_glsl},
    {GraphKind::surface, option_samples_per_pixel | option_object | option_shadows, "rendering", "samples", true,
     prepare_surface, nullptr, texture_sample_at, surface_glsl},
    {GraphKind::volume, option_shadows | option_step | option_jitter | option_normals, "marching", "rays", true, prepare_volume,
     volume_thumbnail, texture_sample_at, volume_glsl},
    {GraphKind::environment, 0, "rendering", "directions", false, prepare_environment, nullptr,
     environment_sample_at, environment_glsl},
};
static_assert(std::size(drivers) == graph_kind_count, "a driver for every kind of nodes/graph_kind.h");
static_assert([] {
  for (int i = 0; i < graph_kind_count; ++i)
    if (static_cast<int>(drivers[i].kind) != i) return false;
  return true;
}(), "drivers in the order of the kinds");

constexpr std::pair<RenderOption, const char*> option_names[] = {{option_samples_per_pixel, "--spp"},
                                                                 {option_object, "--object"},
                                                                 {option_shadows, "--shadows"},
                                                                 {option_step, "--step"},
                                                                 {option_jitter, "--jitter"},
                                                                 {option_normals, "--normals"}};

// "surface or volume": the kinds whose drivers take `option`.
std::string kinds_with_option(RenderOption option) {
  KindSet kinds;
  for (const GraphKindDriver& driver : drivers)
    if (driver.options & option) kinds = kinds | kinds_of(driver.kind);
  return kind_set_names(kinds);
}

}  // namespace

unsigned RenderRequest::options() const {
  const auto bit = [](bool set, RenderOption option) { return set ? static_cast<unsigned>(option) : 0u; };
  return bit(samples_per_pixel != 1, option_samples_per_pixel) | bit(!object.empty(), option_object) |
         bit(shadows != ShadowMode::cached, option_shadows) | bit(step.has_value(), option_step) |
         bit(jitter, option_jitter) | bit(exact_normals, option_normals);
}

std::string FrameReport::summary() const {
  char text[64];
  std::snprintf(text, sizeof text, " in %.3f s (", seconds);
  if (!details.empty()) return what + text + details;
  char rate[32];
  std::snprintf(rate, sizeof rate, "%.2f M samples/s", seconds > 0 ? kernel_samples / seconds / 1e6 : 0.0);
  return what + text + rate;
}

Result<Image> FrameRenderer::render(const Kernel& kernel, const std::vector<float>& params, float frame,
                                    const ProgressCallback& progress, FrameReport* report, TileClaims* claims) const {
  FrameReport counts;
  const auto start = std::chrono::steady_clock::now();
  Result<Image> image = render_frame(kernel, params, frame, progress, claims, counts);
  counts.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (report) *report = std::move(counts);
  return image;
}

const GraphKindDriver& graph_kind_driver(GraphKind kind) { return drivers[static_cast<int>(kind)]; }

Result<std::unique_ptr<FrameRenderer>> prepare_render(const Graph& graph, const RenderRequest& request) {
  const GraphKindDriver& driver = graph_kind_driver(graph.kind);
  for (const auto& [option, name] : option_names)
    if ((request.options() & option) && !(driver.options & option))
      return Diagnostic{ExitStatus::invalid_input, graph.file, {}, {},
                        std::string(name) + " is for " + kinds_with_option(option) + " graphs; this is " + a_graph_of(graph.kind)};
  Result<std::unique_ptr<FrameRenderer>> prepared = driver.prepare(graph, request);
  if (!prepared && prepared.error().file.empty()) {
    Diagnostic named = prepared.error();
    named.file = graph.file;
    return named;
  }
  return prepared;
}

}  // namespace shadetree

// shadetree render FILE -o OUT.png|OUT.exr: render a texture graph over its
// domain, a surface graph on its scene (or a preview object), or a volume
// graph through the ray marcher; one frame, or a numbered sequence with
// --frames, from one compiled kernel.
#include <chrono>
#include <cstdio>
#include <filesystem>

#include <CLI/CLI.hpp>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "graph/parse_volume.h"
#include "pipeline/compile_graph.h"
#include "render/graph_files.h"
#include "pipeline/tiered_kernel.h"
#include "render/image_output.h"
#include "render/preview_scene.h"
#include "render/progress.h"
#include "render/surface_driver.h"
#include "render/texture_driver.h"
#include "render/volume_driver.h"

namespace shadetree {

namespace {
struct RenderArguments {
  std::string file;
  std::string output;
  std::string size;
  std::vector<std::string> assignments;
  std::optional<float> frame;
  std::string frames;
  int threads = 0;
  std::string backend = "tiered";
  int width = 0;
  int samples_per_pixel = 1;
  bool no_shadows = false;
  std::string object;
  std::vector<std::string> search_paths;
  std::optional<float> step;
  bool jitter = false;
};

std::string milliseconds_text(double milliseconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f ms", milliseconds);
  return text;
}

// One frame of the graph's driver into an image, and what to say of it.
using FrameRenderer = std::function<Result<Image>(float frame, std::string* summary)>;

// A surface graph's scene: --object's preview object, else the graph's
// scene, else the preview sphere.
Result<Scene> surface_scene(const Graph& graph, const RenderArguments& arguments) {
  std::vector<std::string> search_paths = arguments.search_paths;
  Result<SceneDesc> desc = surface_scene_desc(graph);
  if (!arguments.object.empty()) {
    desc = preview_scene(arguments.object);
    // A mesh named on the command line is the user's own choice of file.
    if (desc && desc->objects[0].type == ObjectType::mesh)
      search_paths.push_back(std::filesystem::path(desc->objects[0].mesh_file).parent_path().string());
  }
  if (!desc) return desc.error();
  return Scene::build(*desc, graph.file, search_paths);
}

// A volume graph's frames, through the ray marcher, on the graph's scene
// (camera, lights, background) or the default one.
Result<FrameRenderer> volume_frame_renderer(const LoadedGraph& loaded, const Kernel& kernel,
                                            const RenderArguments& arguments) {
  const Graph& graph = *loaded.graph;
  if (!arguments.object.empty() || arguments.samples_per_pixel != 1)
    return Diagnostic{ExitStatus::invalid_input, arguments.file, {}, {},
                      "--object and --spp are for surface graphs; this is a volume graph"};
  if (!graph.render.volume)
    return Diagnostic{ExitStatus::invalid_input, arguments.file, {}, {},
                      "a volume graph needs render.volume with \"bounds\" to be rendered (a volume must be bounded)"};
  const VolumeDesc volume = *graph.render.volume;
  if (arguments.step)
    if (std::string problem = step_problem(volume, *arguments.step, "--step"); !problem.empty())
      return Diagnostic{ExitStatus::invalid_input, arguments.file, {}, {}, problem};
  const SceneDesc desc = volume_scene(graph.render.scene);
  auto scene = std::make_shared<Result<Scene>>(Scene::build(desc, graph.file, arguments.search_paths));
  if (!*scene) return (*scene).error();
  Result<std::pair<int, int>> size = image_size(graph, arguments.size);
  if (!size) return size.error();
  VolumeView view;
  std::tie(view.width, view.height) = *size;
  auto camera = std::make_shared<Camera>(desc.camera, view.width, view.height);
  return FrameRenderer([&, scene, camera, view, volume](float frame, std::string* summary) {
    VolumeView frame_view = view;
    frame_view.frame = frame;
    ProgressReporter progress("marching " + arguments.file, "tiles", "rays");
    VolumeRenderOptions options;
    options.threads = arguments.threads;
    options.step = arguments.step.value_or(0.0f);
    options.shadows = !arguments.no_shadows;
    if (arguments.jitter) options.jitter = true;
    options.lane_width = arguments.width > 0 ? arguments.width : host_vector_width();
    options.progress = progress.callback();
    VolumeRenderStats stats;
    const auto start = std::chrono::steady_clock::now();
    Result<Image> image = render_volume(kernel, loaded.params, **scene, volume, *camera, frame_view, options, &stats);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    char text[320];
    std::snprintf(text, sizeof text,
                  "%dx%d, %ld rays, %ld density samples (%ld for gradients, %ld for shadows) in %.3f s (thread time: "
                  "kernel %.3f s = %.2f M samples/s, %.1f%% of %d-wide lanes in use, march %.3f s",
                  view.width, view.height, stats.rays, stats.density_samples, stats.gradient_samples,
                  stats.shadow_samples, seconds,
                  stats.kernel_seconds,
                  stats.kernel_seconds > 0 ? static_cast<double>(stats.density_samples) / stats.kernel_seconds / 1e6
                                           : 0.0,
                  100.0 * stats.lane_utilisation(), options.lane_width, stats.march_seconds);
    *summary = text;
    return image;
  });
}

Result<FrameRenderer> frame_renderer(const LoadedGraph& loaded, const Kernel& kernel,
                                     const RenderArguments& arguments) {
  const Graph& graph = *loaded.graph;
  if (graph.kind != GraphKind::volume && (arguments.step || arguments.jitter))
    return Diagnostic{ExitStatus::invalid_input, arguments.file, {}, {}, "--step and --jitter are for volume graphs"};
  if (graph.kind == GraphKind::texture) {
    if (!arguments.object.empty() || arguments.samples_per_pixel != 1 || arguments.no_shadows)
      return Diagnostic{ExitStatus::invalid_input, arguments.file, {}, {},
                        "--object, --spp and --no-shadows are for surface graphs; this is a texture graph"};
    Result<TextureView> view = texture_view(graph, arguments.size, arguments.frame);
    if (!view) return view.error();
    return FrameRenderer([&, view = *view](float frame, std::string* summary) {
      TextureView frame_view = view;
      frame_view.frame = frame;
      ProgressReporter progress("rendering " + arguments.file, "tiles", "samples");
      TextureRenderOptions options;
      options.threads = arguments.threads;
      options.progress = progress.callback();
      const auto start = std::chrono::steady_clock::now();
      Result<Image> image = render_texture(kernel, loaded.params, frame_view, options);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const double samples = static_cast<double>(view.width) * view.height;
      char text[160];
      std::snprintf(text, sizeof text, "%dx%d, %.0f samples in %.3f s (%.2f M samples/s", view.width, view.height,
                    samples, seconds, samples / seconds / 1e6);
      *summary = text;
      return image;
    });
  }
  if (graph.kind == GraphKind::volume) return volume_frame_renderer(loaded, kernel, arguments);
  auto scene = std::make_shared<Result<Scene>>(surface_scene(graph, arguments));
  if (!*scene) return (*scene).error();
  if (!arguments.object.empty() && graph.render.scene)
    std::fprintf(stderr, "%s: --object %s replaces the graph's scene\n", printable(arguments.file).c_str(),
                 printable(arguments.object).c_str());
  Result<std::pair<int, int>> size = image_size(graph, arguments.size);
  if (!size) return size.error();
  SurfaceView view;
  std::tie(view.width, view.height) = *size;
  view.samples_per_pixel = arguments.samples_per_pixel;
  auto camera = std::make_shared<Camera>((**scene).desc().camera, view.width, view.height);
  return FrameRenderer([&, scene, camera, view](float frame, std::string* summary) {
    SurfaceView frame_view = view;
    frame_view.frame = frame;
    ProgressReporter progress("rendering " + arguments.file, "tiles", "samples");
    SurfaceRenderOptions options;
    options.threads = arguments.threads;
    options.shadows = !arguments.no_shadows;
    options.progress = progress.callback();
    SurfaceRenderStats stats;
    const auto start = std::chrono::steady_clock::now();
    Result<Image> image = render_surface(kernel, loaded.params, **scene, *camera, frame_view, options, &stats);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    char text[256];
    std::snprintf(text, sizeof text,
                  "%dx%d x %d spp, %ld visible samples in %.3f s (thread time: visibility %.3f s, shading %.3f s "
                  "= %.2f M samples/s, lighting %.3f s",
                  view.width, view.height, view.samples_per_pixel, stats.visible_samples, seconds,
                  stats.visibility_seconds, stats.shading_seconds,
                  stats.shading_seconds > 0 ? static_cast<double>(stats.visible_samples) / stats.shading_seconds / 1e6
                                            : 0.0,
                  stats.lighting_seconds);
    *summary = text;
    return image;
  });
}

// "A..B" (inclusive, A <= B, at most max_frames frames).
constexpr int max_frames = 100000;
Result<std::pair<int, int>> parse_frame_range(const std::string& text) {
  int first = 0, last = 0;
  char dot1 = 0, dot2 = 0, trailing = 0;
  std::istringstream stream(text);
  if (!(stream >> first >> dot1 >> dot2 >> last) || dot1 != '.' || dot2 != '.' || (stream >> trailing) ||
      first > last || first < 0 || last - first >= max_frames)
    return invalid_input("--frames expects FIRST..LAST with 0 <= FIRST <= LAST and at most " +
                         std::to_string(max_frames) + " frames, got \"" + text + "\"");
  return std::pair{first, last};
}

// out.png -> out.0012.png; out.##.png -> out.12.png (the run of '#' is the
// field width).
std::string frame_path(const std::string& pattern, int frame) {
  const auto hashes = pattern.find('#');
  char number[32];
  if (hashes == std::string::npos) {
    std::snprintf(number, sizeof number, ".%04d", frame);
    const auto dot = pattern.rfind('.');
    return pattern.substr(0, dot) + number + pattern.substr(dot);
  }
  const auto end = pattern.find_first_not_of('#', hashes);
  const int digits = static_cast<int>((end == std::string::npos ? pattern.size() : end) - hashes);
  std::snprintf(number, sizeof number, "%0*d", digits, frame);
  return pattern.substr(0, hashes) + number + (end == std::string::npos ? "" : pattern.substr(end));
}

ExitStatus render(const RenderArguments& arguments) {
  Result<LoadedGraph> loaded = load_and_compile(arguments.file, arguments.assignments, {}, graph_files(arguments.search_paths));
  if (!loaded) return report(loaded.error());
  std::vector<std::pair<float, std::string>> frames;  // frame number, output path
  if (arguments.frames.empty()) {
    frames.emplace_back(arguments.frame.value_or(loaded->graph->render.frame), arguments.output);
  } else {
    Result<std::pair<int, int>> range = parse_frame_range(arguments.frames);
    if (!range) return report(range.error());
    for (int frame = range->first; frame <= range->second; ++frame)
      frames.emplace_back(static_cast<float>(frame), frame_path(arguments.output, frame));
  }
  // Refuse an output we cannot write before spending time on the render.
  Status writable = check_image_path(frames.front().second);
  if (!writable) return report(writable.error());

  const auto start = std::chrono::steady_clock::now();
  std::unique_ptr<TieredKernel> tiered;
  Result<std::unique_ptr<Kernel>> kernel = std::unique_ptr<Kernel>();
  if (arguments.backend == "tiered") {
    tiered = make_tiered_kernel(loaded->ir, arguments.width);
  } else {
    kernel = make_kernel(arguments.backend, loaded->ir, arguments.width);
    if (!kernel) return report(kernel.error());
  }
  const Kernel& chosen = tiered ? *tiered : **kernel;
  Result<FrameRenderer> render_frame = frame_renderer(*loaded, chosen, arguments);
  if (!render_frame) return report(render_frame.error());
  const double setup_milliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

  for (std::size_t index = 0; index < frames.size(); ++index) {
    const auto& [frame, path] = frames[index];
    std::string summary;
    Result<Image> image = (*render_frame)(frame, &summary);
    if (!image) return report(image.error());
    Status written = write_image(*image, path);
    if (!written) return report(written.error());
    std::string backend = arguments.backend + ", kernel ready in " + milliseconds_text(setup_milliseconds);
    if (tiered) {
      const TieredReport tiers = tiered->report();
      const long runs = tiers.interpreted_runs + tiers.compiled_runs;
      backend = tiers.jit_failed ? "tiered: the JIT failed, interpreter throughout"
                : !tiers.jit_ready || tiers.compiled_runs == 0
                    ? "tiered: interpreter throughout, the JIT still compiling"
                    : "tiered: JIT ready after " + milliseconds_text(tiers.jit_ready_milliseconds) + ", " +
                          std::to_string(tiers.compiled_runs) + " of " + std::to_string(runs) + " kernel runs on it";
    }
    const std::string counter =
        frames.size() > 1 ? "frame " + std::to_string(index + 1) + " of " + std::to_string(frames.size()) + ": " : "";
    std::fprintf(stderr, "%s: %s%s, %s) -> %s\n", arguments.file.c_str(), counter.c_str(), summary.c_str(),
                 backend.c_str(), path.c_str());
  }
  return ExitStatus::ok;
}
}  // namespace

void add_render_command(CLI::App& app, CommandRunner& run) {
  auto* command = app.add_subcommand("render", "render a texture, surface or volume graph to a PNG or EXR image");
  auto arguments = std::make_shared<RenderArguments>();
  command->add_option("file", arguments->file, "graph file")->required();
  command->add_option("-o,--output", arguments->output,
                      "output image (.png or .exr); with --frames a pattern: out.png -> out.0001.png, "
                      "out.##.png -> out.01.png")
      ->required();
  command->add_option("--size", arguments->size, "image size WIDTHxHEIGHT (default: the graph's render size)");
  command->add_option("--set", arguments->assignments, "set a param: NAME=VALUE (repeatable)");
  add_finite_option(*command, "--frame", arguments->frame, "animation frame (time = frame / 24)");
  command->add_option("--frames", arguments->frames, "render frames FIRST..LAST as a numbered sequence")
      ->excludes("--frame");
  command->add_option("--threads", arguments->threads, "worker threads (default: all cores)")
      ->check(CLI::Range(1, 1024));
  command->add_option("--backend", arguments->backend,
                      "backend: tiered (default: the interpreter while the JIT compiles, then the JIT), jit or interp")
      ->check(CLI::IsMember({"tiered", "jit", "interp"}));
  command->add_option("--width", arguments->width, "JIT vector width: 4, 8 or 16 (default: the host's widest)")
      ->check(CLI::IsMember({4, 8, 16}));
  command->add_option("--spp", arguments->samples_per_pixel,
                      "surface graphs: jittered samples per pixel (default 1: the pixel centre)")
      ->check(CLI::Range(1, 256));
  command->add_flag("--no-shadows", arguments->no_shadows, "surface and volume graphs: no shadow rays");
  command->add_option("--object", arguments->object,
                      "surface graphs: render on a preview object: sphere, torus, plane, box or a mesh file "
                      "(.obj, .ply) instead of the graph's scene");
  add_search_path_option(*command, arguments->search_paths);
  add_finite_option(*command, "--step", arguments->step,
                      "volume graphs: the march step in the units of P (default: render.volume.step, else the "
                      "bounds' diagonal / 256)");
  command->add_flag("--jitter", arguments->jitter,
                    "volume graphs: start each ray at a random fraction of a step (noise instead of banding)");
  command->callback([&run, arguments] { run = [arguments] { return render(*arguments); }; });
}

}  // namespace shadetree

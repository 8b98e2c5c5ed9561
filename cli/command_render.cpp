// shadetree render FILE -o OUT.png|OUT.exr: render a graph of any kind
// through its driver (render/graph_kinds.h); one frame, or a numbered
// sequence with --frames, from one compiled kernel.
#include <chrono>
#include <cstdio>
#include <filesystem>

#include <CLI/CLI.hpp>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "schedule/frame_list.h"
#include "graph/derived_normals.h"
#include "io/graph_files.h"
#include "io/image_output.h"
#include "pipeline/compile_graph.h"
#include "pipeline/tiered_kernel.h"
#include "render/graph_kinds.h"
#include "schedule/progress.h"

namespace shadetree {

namespace {
struct RenderArguments {
  std::string file;
  std::string output;
  std::string size;
  std::vector<std::string> assignments;
  std::optional<float> frame;
  std::string frames;
  std::string chunk;
  bool skip_existing = false;
  int threads = 0;
  std::string backend = "tiered";
  int width = 0;
  int samples_per_pixel = 1;
  std::string shadows = "cached";
  bool no_shadows = false;
  std::string object;
  std::vector<std::string> search_paths;
  std::optional<float> step;
  bool jitter = false;
  std::string normals = "probes";
};

std::string milliseconds_text(double milliseconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f ms", milliseconds);
  return text;
}

// The request of the command line's options; a graph's kind takes some
// of them (render/graph_kinds.h).
Result<RenderRequest> render_request(const RenderArguments& arguments) {
  RenderRequest request;
  if (!arguments.size.empty()) {
    Result<std::pair<int, int>> size = parse_size(arguments.size);
    if (!size) return size.error();
    request.size = *size;
  }
  request.threads = arguments.threads;
  request.samples_per_pixel = arguments.samples_per_pixel;
  request.object = arguments.object;
  request.shadows = arguments.no_shadows || arguments.shadows == "off" ? ShadowMode::off
                    : arguments.shadows == "exact"                     ? ShadowMode::exact
                                                                       : ShadowMode::cached;
  request.step = arguments.step;
  request.jitter = arguments.jitter;
  request.exact_normals = arguments.normals == "exact";
  request.lane_width = arguments.width > 0 ? arguments.width : host_vector_width();
  request.search_paths = arguments.search_paths;
  return request;
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
    Result<std::vector<int>> listed = parse_frame_list(arguments.frames);
    if (!listed) return report(listed.error());
    if (!arguments.chunk.empty()) listed = frame_chunk(*listed, arguments.chunk);
    if (!listed) return report(listed.error());
    for (int frame : *listed) frames.emplace_back(static_cast<float>(frame), frame_path(arguments.output, frame));
  }
  // A resumed sequence: the frames already written stay as they are.
  if (arguments.skip_existing) {
    std::error_code ignored;
    const std::size_t listed = frames.size();
    std::erase_if(frames, [&](const auto& frame) { return std::filesystem::exists(frame.second, ignored); });
    if (frames.empty()) {
      const std::string done = listed == 1 ? std::string("the output exists already")
                                           : "all " + std::to_string(listed) + " frames exist already";
      std::fprintf(stderr, "%s: %s\n", printable(arguments.file).c_str(), done.c_str());
      return ExitStatus::ok;
    }
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
  Result<RenderRequest> request = render_request(arguments);
  if (!request) return report(request.error());
  // --normals exact: a second kernel, the graph with its density's normal.
  std::unique_ptr<Kernel> normal_kernel;
  if (request->exact_normals && loaded->graph->kind == GraphKind::volume) {
    Result<LoadedGraph> with_normal = compile_graph(with_normal_from_density(*loaded->graph), arguments.assignments,
                                                    graph_files(arguments.search_paths));
    if (!with_normal) return report(with_normal.error());
    if (arguments.backend == "tiered") {
      normal_kernel = make_tiered_kernel(with_normal->ir, arguments.width);
    } else {
      Result<std::unique_ptr<Kernel>> made = make_kernel(arguments.backend, with_normal->ir, arguments.width);
      if (!made) return report(made.error());
      normal_kernel = std::move(*made);
    }
    request->normal_kernel = normal_kernel.get();
  }
  Result<std::unique_ptr<FrameRenderer>> renderer = prepare_render(*loaded->graph, *request);
  if (!renderer) return report(renderer.error());
  if (!arguments.object.empty() && loaded->graph->render.scene)
    std::fprintf(stderr, "%s: --object %s replaces the graph's scene\n", printable(arguments.file).c_str(),
                 printable(arguments.object).c_str());
  const GraphKindDriver& driver = graph_kind_driver(loaded->graph->kind);
  const double setup_milliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

  for (std::size_t index = 0; index < frames.size(); ++index) {
    const auto& [frame, path] = frames[index];
    ProgressReporter progress(std::string(driver.progress_verb) + " " + arguments.file, "tiles",
                              std::string(driver.progress_unit));
    FrameReport frame_report;
    Result<Image> image = (*renderer)->render(chosen, loaded->params, frame, progress.callback(), &frame_report);
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
    std::fprintf(stderr, "%s: %s%s, %s) -> %s\n", arguments.file.c_str(), counter.c_str(), frame_report.summary().c_str(),
                 backend.c_str(), path.c_str());
  }
  return ExitStatus::ok;
}
}  // namespace

void add_render_command(CLI::App& app, CommandRunner& run) {
  auto* command = app.add_subcommand("render", "render a graph of any kind (texture, surface, volume, environment) to a PNG or EXR image");
  auto arguments = std::make_shared<RenderArguments>();
  command->add_option("file", arguments->file, "graph file")->required();
  command->add_option("-o,--output", arguments->output,
                      "output image (.png or .exr); with --frames a pattern: out.png -> out.0001.png, "
                      "out.##.png -> out.01.png")
      ->required();
  command->add_option("--size", arguments->size, "image size WIDTHxHEIGHT (default: the graph's render size)");
  command->add_option("--set", arguments->assignments, "set a param: NAME=VALUE (repeatable)");
  add_finite_option(*command, "--frame", arguments->frame, "animation frame (time = frame / 24)");
  auto* frames = command->add_option("--frames", arguments->frames,
                                     "render a numbered sequence: frames and ranges FIRST..LAST or FIRST-LAST, each "
                                     "with an optional step xS, separated by commas (e.g. 1-240x4)")
                     ->excludes("--frame");
  command->add_option("--chunk", arguments->chunk,
                      "render only the frames of --frames from START to END (START..END or START-END; a farm task)")
      ->needs(frames);
  command->add_flag("--skip-existing", arguments->skip_existing,
                    "leave the frames whose output file exists (resume a sequence)");
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
  command
      ->add_option("--shadows", arguments->shadows,
                   "volume graphs: cached (default: each light's transmittance read from a grid marched once per "
                   "frame), exact (a shadow ray from every shaded sample, the reference) or off; surface graphs: "
                   "exact (their shadow rays always are) or off")
      ->check(CLI::IsMember({"cached", "exact", "off"}));
  command->add_flag("--no-shadows", arguments->no_shadows, "surface and volume graphs: --shadows off")
      ->excludes("--shadows");
  command->add_option("--object", arguments->object,
                      "surface graphs: render on a preview object: sphere, torus, plane, box or a mesh file "
                      "(.obj, .ply) instead of the graph's scene");
  add_search_path_option(*command, arguments->search_paths);
  add_finite_option(*command, "--step", arguments->step,
                      "volume graphs: the march step in the units of P (default: render.volume.step, else the "
                      "bounds' diagonal / 256)");
  command->add_flag("--jitter", arguments->jitter,
                    "volume graphs: start each ray at a random fraction of a step (noise instead of banding)");
  command->add_option("--normals", arguments->normals,
                      "volume graphs: light soft samples by the density's gradient from probes (two samples a "
                      "step off, Perlin & Hoffert 1989, the default) or exact (its derivative, one sample)")
      ->check(CLI::IsMember({"probes", "exact"}));
  command->callback([&run, arguments] { run = [arguments] { return render(*arguments); }; });
}

}  // namespace shadetree

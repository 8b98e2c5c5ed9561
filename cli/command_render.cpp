// shadetree render FILE -o OUT.png|OUT.exr: render a graph of any kind
// through its driver (render/graph_kinds.h); one frame, or a numbered
// sequence with --frames, from one compiled kernel. Started by mpirun, the
// ranks share the frames, or each frame's tiles (docs/farm.md).
#include <sched.h>

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
#include "schedule/mpi_job.h"
#include "schedule/progress.h"
#include "schedule/tile_packing.h"

namespace shadetree {

namespace {
struct RenderArguments {
  std::string file;
  std::string output;
  std::string size;
  std::vector<std::string> assignments;
  std::optional<float> frame;
  std::string frames;
  bool frames_given = false;  // --frames with no list: the graph's render.frames
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

// Everything a render needs before its first frame, the same on every
// rank of an MPI job.
struct PreparedRender {
  std::unique_ptr<LoadedGraph> loaded;
  std::vector<std::pair<float, std::string>> frames;  // frame number, output path
  std::unique_ptr<Kernel> kernel;
  const TieredKernel* tiered = nullptr;  // the kernel, when it is tiered: its report
  std::unique_ptr<Kernel> normal_kernel;
  std::unique_ptr<FrameRenderer> renderer;
  const GraphKindDriver* driver = nullptr;
  double setup_milliseconds = 0;
};

Result<std::unique_ptr<Kernel>> backend_kernel(const std::string& backend, const ShadeIR& ir, int width) {
  if (backend == "tiered") return std::unique_ptr<Kernel>(make_tiered_kernel(ir, width));
  return make_kernel(backend, ir, width);
}

Result<PreparedRender> prepare(const RenderArguments& arguments) {
  PreparedRender prepared;
  Result<LoadedGraph> loaded = load_and_compile(arguments.file, arguments.assignments, {}, graph_files(arguments.search_paths));
  if (!loaded) return loaded.error();
  prepared.loaded = std::make_unique<LoadedGraph>(std::move(*loaded));
  const LoadedGraph& graph = *prepared.loaded;
  if (!arguments.frames_given) {
    prepared.frames.emplace_back(arguments.frame.value_or(graph.graph->render.frame), arguments.output);
  } else {
    const std::optional<std::pair<int, int>>& range = graph.graph->render.frames;
    if (arguments.frames.empty() && !range)
      return invalid_input(arguments.file + ": --frames without a list needs the graph's render.frames [first, last]");
    Result<std::vector<int>> listed =
        arguments.frames.empty() ? parse_frame_list(std::to_string(range->first) + ".." + std::to_string(range->second))
                                 : parse_frame_list(arguments.frames);
    if (!listed) return listed.error();
    if (!arguments.chunk.empty()) listed = frame_chunk(*listed, arguments.chunk);
    if (!listed) return listed.error();
    for (int frame : *listed) prepared.frames.emplace_back(static_cast<float>(frame), frame_path(arguments.output, frame));
  }
  // Refuse an output we cannot write before spending time on the render.
  Status writable = check_image_path(prepared.frames.front().second);
  if (!writable) return writable.error();

  const auto start = std::chrono::steady_clock::now();
  Result<std::unique_ptr<Kernel>> kernel = backend_kernel(arguments.backend, graph.ir, arguments.width);
  if (!kernel) return kernel.error();
  prepared.kernel = std::move(*kernel);
  prepared.tiered = dynamic_cast<const TieredKernel*>(prepared.kernel.get());
  Result<RenderRequest> request = render_request(arguments);
  if (!request) return request.error();
  // --normals exact: a second kernel, the graph with its density's normal.
  if (request->exact_normals && graph.graph->kind == GraphKind::volume) {
    Result<LoadedGraph> with_normal = compile_graph(with_normal_from_density(*graph.graph), arguments.assignments,
                                                    graph_files(arguments.search_paths));
    if (!with_normal) return with_normal.error();
    Result<std::unique_ptr<Kernel>> made = backend_kernel(arguments.backend, with_normal->ir, arguments.width);
    if (!made) return made.error();
    prepared.normal_kernel = std::move(*made);
    request->normal_kernel = prepared.normal_kernel.get();
  }
  Result<std::unique_ptr<FrameRenderer>> renderer = prepare_render(*graph.graph, *request);
  if (!renderer) return renderer.error();
  prepared.renderer = std::move(*renderer);
  prepared.driver = &graph_kind_driver(graph.graph->kind);
  prepared.setup_milliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return prepared;
}

bool output_exists(const std::string& path) {
  std::error_code ignored;
  return std::filesystem::exists(path, ignored);
}

// The render line's closing part: which backend ran the frame.
std::string backend_text(const RenderArguments& arguments, const PreparedRender& prepared) {
  if (!prepared.tiered) return arguments.backend + ", kernel ready in " + milliseconds_text(prepared.setup_milliseconds);
  const TieredReport tiers = prepared.tiered->report();
  const long runs = tiers.interpreted_runs + tiers.compiled_runs;
  return tiers.jit_failed ? "tiered: the JIT failed (" + tiers.jit_error + "), interpreter throughout"
         : !tiers.jit_ready || tiers.compiled_runs == 0
             ? "tiered: interpreter throughout, the JIT still compiling"
             : "tiered: JIT ready after " + milliseconds_text(tiers.jit_ready_milliseconds) + ", " +
                   std::to_string(tiers.compiled_runs) + " of " + std::to_string(runs) + " kernel runs on it";
}

// Renders frame `index` (all of it, or with `claims` the tiles they hand
// this process).
Result<Image> render_frame(const RenderArguments& arguments, const PreparedRender& prepared, std::size_t index,
                           FrameReport& report, TileClaims* claims = nullptr) {
  ProgressReporter progress(std::string(prepared.driver->progress_verb) + " " + arguments.file, "tiles",
                            std::string(prepared.driver->progress_unit));
  return prepared.renderer->render(*prepared.kernel, prepared.loaded->params, prepared.frames[index].first,
                                   progress.callback(), &report, claims);
}

void print_render_line(const RenderArguments& arguments, const PreparedRender& prepared, std::size_t index,
                       const FrameReport& report, const std::string& where) {
  const std::size_t count = prepared.frames.size();
  const std::string counter =
      count > 1 ? "frame " + std::to_string(index + 1) + " of " + std::to_string(count) + ": " : "";
  std::fprintf(stderr, "%s: %s%s, %s%s) -> %s\n", arguments.file.c_str(), counter.c_str(), report.summary().c_str(),
               backend_text(arguments, prepared).c_str(), where.c_str(), prepared.frames[index].second.c_str());
}

ExitStatus render_and_write(const RenderArguments& arguments, const PreparedRender& prepared, std::size_t index,
                            const std::string& where = "") {
  FrameReport report;
  Result<Image> image = render_frame(arguments, prepared, index, report);
  if (!image) return shadetree::report(image.error());
  Status written = write_image(*image, prepared.frames[index].second);
  if (!written) return shadetree::report(written.error());
  print_render_line(arguments, prepared, index, report, where);
  return ExitStatus::ok;
}

void note_replaced_scene(const RenderArguments& arguments, const PreparedRender& prepared) {
  if (!arguments.object.empty() && prepared.loaded->graph->render.scene)
    std::fprintf(stderr, "%s: --object %s replaces the graph's scene\n", printable(arguments.file).c_str(),
                 printable(arguments.object).c_str());
}

ExitStatus render_here(const RenderArguments& arguments) {
  Result<PreparedRender> prepared = prepare(arguments);
  if (!prepared) return report(prepared.error());
  // A resumed sequence: the frames already written stay as they are.
  if (arguments.skip_existing) {
    const std::size_t listed = prepared->frames.size();
    std::erase_if(prepared->frames, [](const auto& frame) { return output_exists(frame.second); });
    if (prepared->frames.empty()) {
      const std::string done = listed == 1 ? std::string("the output exists already")
                                           : "all " + std::to_string(listed) + " frames exist already";
      std::fprintf(stderr, "%s: %s\n", printable(arguments.file).c_str(), done.c_str());
      return ExitStatus::ok;
    }
  }
  note_replaced_scene(arguments, *prepared);
  for (std::size_t index = 0; index < prepared->frames.size(); ++index)
    if (ExitStatus status = render_and_write(arguments, *prepared, index); status != ExitStatus::ok) return status;
  return ExitStatus::ok;
}

// A sequence of at least as many frames as ranks: each rank renders whole
// frames, claiming the next when done, and writes them.
ExitStatus render_frames_on_ranks(const RenderArguments& arguments, const PreparedRender& prepared, MpiJob& job) {
  ExitStatus status = ExitStatus::ok;
  MpiJob::Queue queue(job);
  const std::string where = ", rank " + std::to_string(job.rank()) + " of " + std::to_string(job.ranks());
  for (long index; (index = queue.claim(static_cast<long>(prepared.frames.size()))) >= 0;) {
    if (arguments.skip_existing && output_exists(prepared.frames[index].second)) continue;
    status = render_and_write(arguments, prepared, static_cast<std::size_t>(index), where);
    if (status != ExitStatus::ok) {
      queue.fail();
      break;
    }
  }
  queue.close();
  return static_cast<ExitStatus>(job.agree(static_cast<int>(status)).first);
}

// Fewer frames than ranks: each frame's tiles are shared by the ranks, each
// claiming its next tile when done, and gathered to rank 0, which writes
// the frame.
ExitStatus render_tiles_on_ranks(const RenderArguments& arguments, const PreparedRender& prepared, MpiJob& job) {
  for (std::size_t index = 0; index < prepared.frames.size(); ++index) {
    const std::string& path = prepared.frames[index].second;
    if (arguments.skip_existing && job.agree(output_exists(path) ? 1 : 0).second) continue;
    FrameReport report;
    ExitStatus status = ExitStatus::ok;
    MpiJob::Queue queue(job);
    Result<Image> image = render_frame(arguments, prepared, index, report, &queue);
    if (!image) {
      status = shadetree::report(image.error());
      queue.fail();
    }
    if (!queue.close()) return static_cast<ExitStatus>(job.agree(static_cast<int>(status)).first);
    const std::vector<Tile> tiles = queue.rendered_tiles();
    if (job.rank() != 0) {
      job.send_to_zero(pack_tiles(*image, tiles));
    } else {
      std::string counts = std::to_string(tiles.size());
      for (int rank = 1; rank < job.ranks() && status == ExitStatus::ok; ++rank) {
        Result<long> received = unpack_tiles(job.receive_from(rank), *image);
        if (!received) status = shadetree::report(received.error());
        else counts += " + " + std::to_string(*received);
      }
      if (status == ExitStatus::ok) {
        Status written = write_image(*image, path);
        if (!written) status = shadetree::report(written.error());
      }
      if (status == ExitStatus::ok)
        print_render_line(arguments, prepared, index, report,
                          ", " + std::to_string(job.ranks()) + (job.ranks() == 1 ? " rank" : " ranks") + ", tiles " + counts + ", figures of rank 0");
    }
    status = static_cast<ExitStatus>(job.agree(static_cast<int>(status)).first);
    if (status != ExitStatus::ok) return status;
  }
  return ExitStatus::ok;
}

// mpirun binds each rank to one core unless told otherwise: more threads
// than the cores a rank may run on share them (2.5 times slower, measured).
void note_bound_threads(const RenderArguments& arguments, const MpiJob& job) {
  cpu_set_t allowed;
  if (job.rank() != 0 || ::sched_getaffinity(0, sizeof allowed, &allowed) != 0) return;
  const int cores = CPU_COUNT(&allowed);
  if (arguments.threads > cores)
    std::fprintf(stderr,
                 "%s: --threads %d, but rank 0 may run on %d core%s: give mpirun --bind-to none, or as many "
                 "cores per rank (--map-by node:PE=%d)\n",
                 printable(arguments.file).c_str(), arguments.threads, cores, cores == 1 ? "" : "s",
                 arguments.threads);
}

// Under mpirun: every rank sets up the render; a failure there is
// reported once (by rank 0, or by a rank that failed where rank 0 did not).
ExitStatus render_on_ranks(const RenderArguments& arguments, MpiJob& job) {
  Result<PreparedRender> prepared = prepare(arguments);
  const ExitStatus mine = prepared ? ExitStatus::ok : prepared.error().status;
  const auto [worst, rank_zero] = job.agree(static_cast<int>(mine));
  if (worst != 0) {
    if (!prepared && (job.rank() == 0 || rank_zero == 0)) report(prepared.error());
    return static_cast<ExitStatus>(worst);
  }
  if (job.rank() == 0) note_replaced_scene(arguments, *prepared);
  note_bound_threads(arguments, job);
  return prepared->frames.size() >= static_cast<std::size_t>(job.ranks()) && prepared->frames.size() > 1
             ? render_frames_on_ranks(arguments, *prepared, job)
             : render_tiles_on_ranks(arguments, *prepared, job);
}

ExitStatus render(const RenderArguments& arguments) {
  if (!MpiJob::launched()) return render_here(arguments);
  Result<std::unique_ptr<MpiJob>> job = MpiJob::join();
  if (!job) return report(job.error());
  return render_on_ranks(arguments, **job);
}
}  // namespace

void add_render_command(CLI::App& app, CommandRunner& run) {
  auto* command = app.add_subcommand("render", "render a graph of any kind (texture, surface, volume, environment) to a PNG or EXR image; "
                                                     "started by mpirun, its ranks share the frames or tiles");
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
                                     "with an optional step xS, separated by commas (e.g. 1-240x4); with no list, "
                                     "the graph's render.frames")
                     ->expected(0, 1)
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
                   "frame, empty space skipped, rays ended once 1/64 of the light gets through, faint samples' "
                   "gradients not probed, specular lobes below 2^-16 left out and the rest read from a table), exact (a "
                   "shadow ray from every shaded sample, every ray to its end, every gradient probed, every lobe by "
                   "powf: the reference) or off; surface "
                   "graphs: "
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
  command->callback([&run, arguments, frames] {
    arguments->frames_given = frames->count() > 0;
    run = [arguments] { return render(*arguments); };
  });
}

}  // namespace shadetree

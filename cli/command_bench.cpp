// shadetree bench FILE...: per graph, nodes before and after optimization,
// JIT compile time (cold and cached), and interpreter and JIT throughput at
// one thread and at all threads, as medians of repeated runs after a
// warm-up. Samples are the texture driver's (a WxH grid over the graph's
// render domain), fed straight to the kernel so that every graph kind can
// be measured. Surface graphs are also rendered by the surface driver on
// their scene, with the time of each stage and the shading stage's
// throughput against the kernel's own on the texture samples; volume
// graphs by the ray marcher, with its density throughput and lane use.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <tuple>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "graph/parse_volume.h"
#include "pipeline/compile_graph.h"
#include "render/graph_files.h"
#include "interp/interpreter.h"
#include "jit/jit_kernel.h"
#include "render/preview_scene.h"
#include "render/surface_driver.h"
#include "render/texture_driver.h"
#include "render/thread_bindings.h"
#include "render/volume_driver.h"

namespace shadetree {

namespace {
struct BenchArguments {
  std::vector<std::string> files;
  std::string size = "256x256";
  int threads = 0;
  int repetitions = 7;
  bool json = false;
  std::string gathers;
  bool quick = false;
};

struct Samples {
  std::size_t count = 0;
  SampleBuffers input{0, {}};
};

Samples make_samples(const TextureView& view, const Kernel& kernel) {
  Samples samples;
  samples.count = static_cast<std::size_t>(view.width) * view.height;
  samples.input = SampleBuffers(samples.count, kernel.reads());
  for (int row = 0; row < view.height; ++row)
    for (int column = 0; column < view.width; ++column)
      store_texture_sample(samples.input, static_cast<std::size_t>(row) * view.width + column,
                           texture_sample_at_pixel(view, column, row));
  return samples;
}

// Median samples per second of `repetitions` runs after one warm-up run.
double measure(const Kernel& kernel, const std::vector<float>& params, const UniformInputs& uniforms,
               const Samples& samples, int threads, int repetitions) {
  constexpr std::size_t chunk = 4096;
  OutputBuffers output_buffers(samples.count, kernel.outputs());
  const std::vector<float*> outputs(output_buffers.planes(), output_buffers.planes() + kernel.outputs().plane_count);
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  ThreadBindings bindings(kernel, params.data(), uniforms);
  auto run_once = [&] {
    arena.execute([&] {
      tbb::parallel_for(std::size_t(0), (samples.count + chunk - 1) / chunk, [&](std::size_t c) {
        const std::size_t start = c * chunk, count = std::min(chunk, samples.count - start);
        SampleInputs inputs = samples.input.inputs();
        for (const float*& plane : inputs.planes)
          if (plane) plane += start;
        std::vector<float*> shifted;
        for (float* plane : outputs) shifted.push_back(plane + start);
        bindings.local().run(inputs, shifted.data(), count);
      });
    });
  };
  run_once();
  std::vector<double> seconds;
  for (int r = 0; r < repetitions; ++r) {
    const auto start = std::chrono::steady_clock::now();
    run_once();
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::nth_element(seconds.begin(), seconds.begin() + seconds.size() / 2, seconds.end());
  return static_cast<double>(samples.count) / seconds[seconds.size() / 2];
}

// A driver's render: its statistics (stage times in seconds of thread
// time) and its wall time, for the run with the median wall time of
// `repetitions` after one warm-up run.
template <class Stats>
struct Timing {
  Stats stats;
  double seconds = 0;
};

template <class Stats, class Render>
Timing<Stats> median_render(int repetitions, Render render) {
  std::vector<Timing<Stats>> runs;
  for (int r = 0; r <= repetitions; ++r) {
    Timing<Stats> timing;
    const auto start = std::chrono::steady_clock::now();
    render(timing.stats);
    timing.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (r > 0) runs.push_back(timing);
  }
  std::nth_element(runs.begin(), runs.begin() + runs.size() / 2, runs.end(),
                   [](const Timing<Stats>& a, const Timing<Stats>& b) { return a.seconds < b.seconds; });
  return runs[runs.size() / 2];
}

// The backends a driver is measured with, and each one's kernel rate on
// the texture samples (1 thread), which the driver's rate is compared to.
struct MeasuredBackend {
  const char* name;
  const Kernel* kernel;
  double kernel_sps;
};

// The surface driver on the graph's scene (or the preview sphere).
Status bench_surface(const LoadedGraph& loaded, const std::string& file, const TextureView& view,
                     const std::vector<MeasuredBackend>& backends, const BenchArguments& arguments,
                     nlohmann::ordered_json& results, std::vector<std::string>& rows) {
  Result<Scene> scene = Scene::build(
      loaded.graph->render.scene ? *loaded.graph->render.scene : SceneDesc(*preview_scene("sphere")), file, {});
  if (!scene) return scene.error();
  SurfaceView surface_view;
  surface_view.width = view.width;
  surface_view.height = view.height;
  const Camera camera(scene->desc().camera, view.width, view.height);
  for (const MeasuredBackend& backend : backends)
    for (int threads : {1, arguments.threads}) {
      SurfaceRenderOptions options;
      options.threads = threads;
      const auto timing = median_render<SurfaceRenderStats>(arguments.repetitions, [&](SurfaceRenderStats& stats) {
        render_surface(*backend.kernel, loaded.params, *scene, camera, surface_view, options, &stats);
      });
      const double shading_sps = static_cast<double>(timing.stats.visible_samples) / timing.stats.shading_seconds;
      results.push_back({{"backend", backend.name},
                         {"threads", threads},
                         {"visible_samples", timing.stats.visible_samples},
                         {"visibility_s", timing.stats.visibility_seconds},
                         {"shading_s", timing.stats.shading_seconds},
                         {"lighting_s", timing.stats.lighting_seconds},
                         {"total_s", timing.seconds},
                         {"shading_sps", shading_sps},
                         {"shading_vs_kernel", shading_sps / backend.kernel_sps}});
      char row[256];
      std::snprintf(row, sizeof row, "%-16s %-7s %7s %9ld %9.3f %9.3f %9.3f %9.3f %9.2fM %8.2fx",
                    loaded.graph->name.c_str(), backend.name, threads == 1 ? "1" : "all",
                    timing.stats.visible_samples, timing.stats.visibility_seconds, timing.stats.shading_seconds,
                    timing.stats.lighting_seconds, timing.seconds, shading_sps / 1e6, shading_sps / backend.kernel_sps);
      rows.push_back(row);
    }
  return success();
}

// The ray marcher on the graph's volume and scene.
Status bench_volume(const LoadedGraph& loaded, const std::string& file, const TextureView& view,
                    const std::vector<MeasuredBackend>& backends, const BenchArguments& arguments,
                    nlohmann::ordered_json& results, std::vector<std::string>& rows) {
  if (!loaded.graph->render.volume) return invalid_input(file + ": a volume graph needs render.volume to be marched");
  const SceneDesc desc = volume_scene(loaded.graph->render.scene);
  Result<Scene> scene = Scene::build(desc, file, {});
  if (!scene) return scene.error();
  VolumeView volume_view;
  volume_view.width = view.width;
  volume_view.height = view.height;
  const Camera camera(desc.camera, view.width, view.height);
  for (const MeasuredBackend& backend : backends)
    for (int threads : {1, arguments.threads}) {
      VolumeRenderOptions options;
      options.threads = threads;
      options.lane_width = host_vector_width();
      const auto timing = median_render<VolumeRenderStats>(arguments.repetitions, [&](VolumeRenderStats& stats) {
        render_volume(*backend.kernel, loaded.params, *scene, *loaded.graph->render.volume, camera, volume_view,
                      options, &stats);
      });
      const double density_sps = static_cast<double>(timing.stats.density_samples) / timing.stats.kernel_seconds;
      results.push_back({{"backend", backend.name},
                         {"threads", threads},
                         {"rays", timing.stats.rays},
                         {"density_samples", timing.stats.density_samples},
                         {"lane_utilisation", timing.stats.lane_utilisation()},
                         {"kernel_s", timing.stats.kernel_seconds},
                         {"march_s", timing.stats.march_seconds},
                         {"total_s", timing.seconds},
                         {"density_sps", density_sps},
                         {"density_vs_kernel", density_sps / backend.kernel_sps}});
      char row[256];
      std::snprintf(row, sizeof row, "%-16s %-7s %7s %11ld %7.1f%% %9.3f %9.3f %9.3f %9.2fM %8.2fx",
                    loaded.graph->name.c_str(), backend.name, threads == 1 ? "1" : "all",
                    timing.stats.density_samples, 100.0 * timing.stats.lane_utilisation(), timing.stats.kernel_seconds,
                    timing.stats.march_seconds, timing.seconds, density_sps / 1e6, density_sps / backend.kernel_sps);
      rows.push_back(row);
    }
  return success();
}

ExitStatus bench(const BenchArguments& arguments) {
  // Start the JIT first, so that no graph's cold compile includes that
  // one-time cost (it is measured separately: see docs/architecture.md).
  Result<LoadedGraph> warm_up = compile_graph_text(
      R"({"format": "shadetree-graph", "version": 1, "kind": "texture", "nodes": [{"id": "t", "op": "time"}],
          "outputs": {"color": "t"}})",
      "warm-up");
  if (!warm_up || !compile_kernel(warm_up->ir, 0, JitSettings{false, {}, true, std::nullopt}))
    return report(failure("cannot start the JIT for benchmarking"));
  nlohmann::ordered_json results = nlohmann::json::array();
  if (!arguments.json)
    std::printf("%-16s %8s %11s %9s %9s %11s %11s %11s %11s %9s\n", "graph", "samples", "nodes", "cold ms",
                "cached ms", "interp 1t", "interp mt", "jit 1t", "jit mt", "jit/int");
  std::vector<std::string> surface_rows, volume_rows;
  for (const std::string& file : arguments.files) {
    Result<LoadedGraph> loaded = load_and_compile(file, {}, {}, graph_files());
    if (!loaded) return report(loaded.error());
    auto view = texture_view(*loaded->graph, arguments.size, std::nullopt);
    if (!view) return report(view.error());
    JitSettings settings{false, {}, false, std::nullopt};
    if (arguments.gathers == "hardware") settings.gathers = GatherStrategy::hardware;
    if (arguments.gathers == "per-lane") settings.gathers = GatherStrategy::per_lane;
    if (arguments.gathers == "in-register") settings.gathers = GatherStrategy::in_register;
    if (arguments.gathers == "in-register-bytes") settings.gathers = GatherStrategy::in_register_byte_permutes;
    if (arguments.quick) settings.optimization = Optimization::quick;
    JitSettings cold_settings = settings;
    cold_settings.cold = true;
    Result<CompiledKernel> cold = compile_kernel(loaded->ir, 0, cold_settings);
    if (!cold) return report(cold.error());
    Result<std::unique_ptr<Kernel>> jit = make_jit_kernel(loaded->ir, 0, settings);
    if (!jit) return report(jit.error());
    std::optional<double> cached_milliseconds;  // quick kernels are never cached
    if (!arguments.quick) {
      Result<CompiledKernel> cached = compile_kernel(loaded->ir, 0, settings);
      if (!cached) return report(cached.error());
      cached_milliseconds = cached->compile_milliseconds;
    }
    auto interp = make_interpreted_kernel(loaded->ir);
    const Samples samples = make_samples(*view, *interp);

    // A volume's samples see its march step, so that ops clamped by it
    // do the same work here as in the marcher.
    UniformInputs uniforms = texture_uniforms(*view);
    if (loaded->graph->render.volume) uniforms.set(GlobalId::step_size, march_step(*loaded->graph->render.volume));
    const int all = arguments.threads;
    const double interp_1t = measure(*interp, loaded->params, uniforms, samples, 1, arguments.repetitions);
    const double interp_mt = measure(*interp, loaded->params, uniforms, samples, all, arguments.repetitions);
    const double jit_1t = measure(**jit, loaded->params, uniforms, samples, 1, arguments.repetitions);
    const double jit_mt = measure(**jit, loaded->params, uniforms, samples, all, arguments.repetitions);
    const std::string name = loaded->graph->name;
    nlohmann::ordered_json driver = nlohmann::json::array();
    const std::vector<MeasuredBackend> backends = {{"jit", jit->get(), jit_1t}, {"interp", interp.get(), interp_1t}};
    if (loaded->graph->kind == GraphKind::surface) {
      Status measured = bench_surface(*loaded, file, *view, backends, arguments, driver, surface_rows);
      if (!measured) return report(measured.error());
    }
    if (loaded->graph->kind == GraphKind::volume) {
      Status measured = bench_volume(*loaded, file, *view, backends, arguments, driver, volume_rows);
      if (!measured) return report(measured.error());
    }
    if (arguments.json) {
      results.push_back({{"graph", name},
                         {"samples", samples.count},
                         {"nodes_before", loaded->instructions_before_optimization},
                         {"nodes_after", loaded->ir.code.size()},
                         {"compile_ms_cold", cold->compile_milliseconds},
                         {"compile_ms_cached", cached_milliseconds ? nlohmann::json(*cached_milliseconds) : nlohmann::json()},
                         {"interp_sps_1t", interp_1t},
                         {"interp_sps_mt", interp_mt},
                         {"jit_sps_1t", jit_1t},
                         {"jit_sps_mt", jit_mt},
                         {loaded->graph->kind == GraphKind::volume ? "volume_driver" : "surface_driver", driver}});
    } else {
      char cached_text[32] = "-";
      if (cached_milliseconds) std::snprintf(cached_text, sizeof cached_text, "%.3f", *cached_milliseconds);
      std::printf("%-16s %8zu %5d->%-5zu %9.2f %9s %10.2fM %10.2fM %10.2fM %10.2fM %8.1fx\n", name.c_str(),
                  samples.count, loaded->instructions_before_optimization, loaded->ir.code.size(),
                  cold->compile_milliseconds, cached_text, interp_1t / 1e6, interp_mt / 1e6, jit_1t / 1e6,
                  jit_mt / 1e6, jit_1t / interp_1t);
    }
  }
  if (arguments.json) {
    std::printf("%s\n", results.dump(2).c_str());
  } else if (!surface_rows.empty()) {
    // Stage times are thread time summed over threads; total is wall time.
    std::printf("\nsurface driver (stage times: thread seconds; shading throughput vs the kernel's 1-thread rate)\n");
    std::printf("%-16s %-7s %7s %9s %9s %9s %9s %9s %10s %9s\n", "graph", "backend", "threads", "visible",
                "visib. s", "shading s", "light. s", "total s", "shading", "vs kernel");
    for (const std::string& row : surface_rows) std::printf("%s\n", row.c_str());
  }
  if (!arguments.json && !volume_rows.empty()) {
    std::printf("\nray marcher (kernel and march: thread seconds; density throughput vs the kernel's 1-thread rate on "
                "the texture samples)\n");
    std::printf("%-16s %-7s %7s %11s %8s %9s %9s %9s %10s %9s\n", "graph", "backend", "threads", "samples", "lanes",
                "kernel s", "march s", "total s", "density", "vs kernel");
    for (const std::string& row : volume_rows) std::printf("%s\n", row.c_str());
  }
  return ExitStatus::ok;
}
}  // namespace

void add_bench_command(CLI::App& app, CommandRunner& run) {
  auto* command = app.add_subcommand("bench", "measure compile time and interpreter / JIT throughput");
  auto arguments = std::make_shared<BenchArguments>();
  command->add_option("files", arguments->files, "graph files")->required();
  command->add_option("--size", arguments->size, "sample grid WIDTHxHEIGHT (default 256x256)");
  command->add_option("--threads", arguments->threads, "threads of the multi-threaded runs (default: all cores)")
      ->check(CLI::Range(1, 1024));
  command->add_option("--repetitions", arguments->repetitions, "timed runs per measurement (default 7)")
      ->check(CLI::Range(1, 1000));
  command->add_flag("--json", arguments->json, "print a JSON array, one object per graph");
  command->add_option("--gathers", arguments->gathers, "JIT table lookups: hardware, per-lane, in-register or in-register-bytes (default: the host's)")
      ->check(CLI::IsMember({"hardware", "per-lane", "in-register", "in-register-bytes"}));
  command->add_flag("--quick", arguments->quick,
                    "measure the JIT's quick kernels (the editor's first previews of an edit) instead of its full ones");
  command->callback([&run, arguments] { run = [arguments] { return bench(*arguments); }; });
}

}  // namespace shadetree

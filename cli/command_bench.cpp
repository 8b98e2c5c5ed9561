// shadetree bench FILE...: per graph, nodes before and after optimization,
// JIT compile time (cold, the median of --compiles, and cached), and
// interpreter and JIT throughput at one thread and at all threads, as
// medians of repeated runs after a warm-up. Samples are the texture driver's (a WxH grid over the graph's
// render domain), fed straight to the kernel so that every graph kind can
// be measured. Graphs of the kinds whose drivers do more than run the
// kernel (surface, volume) are also rendered by their driver, with the
// figures it reports and its kernel throughput against the kernel's own
// on the texture samples.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <tuple>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "graph/parse_volume.h"
#include "interp/interpreter.h"
#include "io/graph_files.h"
#include "jit/jit_kernel.h"
#include "pipeline/compile_graph.h"
#include "platform/cpu_model.h"
#include "render/graph_kinds.h"
#include "render/texture_driver.h"
#include "schedule/thread_arena.h"
#include "schedule/thread_bindings.h"

namespace shadetree {

namespace {

// The median of `values` (the upper middle one of an even count); there is
// at least one.
double median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

struct BenchArguments {
  std::vector<std::string> files;
  std::string size = "256x256";
  int threads = 0;
  int repetitions = 7;
  int compiles = 1;  // cold compiles per graph
  bool json = false;
  std::string gathers;
  int width = 0;  // 0: the host's widest
  bool quick = false;
};

// --gathers: the JIT's table lookup strategies by their names.
const std::map<std::string, GatherStrategy> gather_strategies = {
    {"hardware", GatherStrategy::hardware},
    {"per-lane", GatherStrategy::per_lane},
    {"in-register", GatherStrategy::in_register},
    {"in-register-bytes", GatherStrategy::in_register_byte_permutes},
    {"bytes-and-gathers", GatherStrategy::byte_permutes_and_gathers},
    {"bytes-and-per-lane", GatherStrategy::byte_permutes_and_per_lane}};

std::string gather_strategy_name(GatherStrategy strategy) {
  for (const auto& [name, named] : gather_strategies)
    if (named == strategy) return name;
  return "unnamed";
}

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
  tbb::task_arena arena(arena_concurrency(threads));
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
  return static_cast<double>(samples.count) / median(seconds);
}

// The backends a driver is measured with, and each one's kernel rate on
// the texture samples (1 thread), which the driver's rate is compared to.
struct MeasuredBackend {
  const char* name;
  const Kernel* kernel;
  double kernel_sps;
};

// A driver's measurements of one graph: a JSON object and a table row per
// backend and thread count.
struct DriverRows {
  std::vector<std::string> names;  // of the figures, for the table's heading
  std::vector<std::string> rows;
};

// The graph's driver (the kinds table) at the bench's size: its figures
// from the run with the median wall time of `repetitions` after one
// warm-up, and its kernel throughput against the kernel's own on the
// texture samples.
Status bench_driver(const LoadedGraph& loaded, const TextureView& view, const std::vector<MeasuredBackend>& backends,
                    const BenchArguments& arguments, nlohmann::ordered_json& results, DriverRows& table) {
  RenderRequest request;
  request.size = {view.width, view.height};
  request.lane_width = arguments.width > 0 ? arguments.width : host_vector_width();
  for (const MeasuredBackend& backend : backends)
    for (int threads : {1, arguments.threads}) {
      request.threads = threads;
      Result<std::unique_ptr<FrameRenderer>> renderer = prepare_render(*loaded.graph, request);
      if (!renderer) return renderer.error();
      std::vector<FrameReport> runs;
      for (int r = 0; r <= arguments.repetitions; ++r) {
        FrameReport report;
        Result<Image> image = (*renderer)->render(*backend.kernel, loaded.params, view.frame, {}, &report);
        if (!image) return image.error();
        if (r > 0) runs.push_back(std::move(report));
      }
      std::nth_element(runs.begin(), runs.begin() + runs.size() / 2, runs.end(),
                       [](const FrameReport& a, const FrameReport& b) { return a.seconds < b.seconds; });
      const FrameReport& report = runs[runs.size() / 2];
      const double seconds = report.seconds;
      const double kernel_sps = static_cast<double>(report.kernel_samples) / report.kernel_seconds;
      nlohmann::ordered_json result = {{"backend", backend.name}, {"threads", threads}};
      // A row as long as the driver has figures: a cell at a time.
      std::string row = loaded.graph->name;
      if (row.size() < 16) row.resize(16, ' ');
      char cell[64];
      std::snprintf(cell, sizeof cell, " %-7s %7s", backend.name, threads == 1 ? "1" : "all");
      row += cell;
      table.names.clear();
      for (const auto& [name, value] : report.figures) {
        result[name] = value;
        table.names.push_back(name);
        std::snprintf(cell, sizeof cell, " %16.6g", value);
        row += cell;
      }
      result["total_s"] = seconds;
      result["kernel_sps"] = kernel_sps;
      result["kernel_vs_texture_samples"] = kernel_sps / backend.kernel_sps;
      std::snprintf(cell, sizeof cell, " %9.3f %9.2fM %8.2fx", seconds, kernel_sps / 1e6,
                    kernel_sps / backend.kernel_sps);
      row += cell;
      results.push_back(result);
      table.rows.push_back(std::move(row));
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
  // What the figures were measured on and with: lookup strategies and
  // widths rank differently from one processor to the next. The lookups
  // are those asked for; a host without their instructions falls back
  // (jit/jit_compiler.cpp, effective_gathers).
  const std::string cpu = cpu_model_name(), jit_cpu = host_cpu_name();
  const int jit_width = arguments.width > 0 ? arguments.width : host_vector_width();
  const std::string jit_gathers = arguments.gathers.empty() ? gather_strategy_name(host_gather_strategy()) : arguments.gathers;
  if (!arguments.json) {
    std::printf("%s (LLVM: %s); JIT: %d lanes, %s lookups\n", cpu.c_str(), jit_cpu.c_str(), jit_width,
                jit_gathers.c_str());
    std::printf("%-16s %8s %11s %9s %17s %9s %11s %11s %11s %11s %9s\n", "graph", "samples", "nodes", "cold ms",
                "emit/opt/gen ms", "cached ms", "interp 1t", "interp mt", "jit 1t", "jit mt", "jit/int");
  }
  std::map<GraphKind, DriverRows> driver_rows;
  for (const std::string& file : arguments.files) {
    Result<LoadedGraph> loaded = load_and_compile(file, {}, {}, graph_files());
    if (!loaded) return report(loaded.error());
    auto view = texture_view(*loaded->graph, arguments.size, std::nullopt);
    if (!view) return report(view.error());
    JitSettings settings{false, {}, false, std::nullopt};
    if (!arguments.gathers.empty()) settings.gathers = gather_strategies.at(arguments.gathers);
    if (arguments.quick) settings.optimization = Optimization::quick;
    JitSettings cold_settings = settings;
    cold_settings.cold = true;
    std::vector<double> cold_milliseconds, emit_milliseconds, optimize_milliseconds, generate_milliseconds;
    int modules = 0;
    for (int c = 0; c < arguments.compiles; ++c) {
      Result<CompiledKernel> cold = compile_kernel(loaded->ir, arguments.width, cold_settings);
      if (!cold) return report(cold.error());
      cold_milliseconds.push_back(cold->compile_milliseconds);
      emit_milliseconds.push_back(cold->stages.emit_milliseconds);
      optimize_milliseconds.push_back(cold->stages.optimize_milliseconds);
      generate_milliseconds.push_back(cold->stages.generate_milliseconds);
      modules = cold->stages.modules;
    }
    const auto [fastest, slowest] = std::minmax_element(cold_milliseconds.begin(), cold_milliseconds.end());
    const double cold_median = median(cold_milliseconds);
    const double emit_median = median(emit_milliseconds), optimize_median = median(optimize_milliseconds),
                 generate_median = median(generate_milliseconds);
    Result<std::unique_ptr<Kernel>> jit = make_jit_kernel(loaded->ir, arguments.width, settings);
    if (!jit) return report(jit.error());
    std::optional<double> cached_milliseconds;  // quick kernels are never cached
    if (!arguments.quick) {
      Result<CompiledKernel> cached = compile_kernel(loaded->ir, arguments.width, settings);
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
    if (graph_kind_driver(loaded->graph->kind).bench_driver) {
      Status measured = bench_driver(*loaded, *view, backends, arguments, driver, driver_rows[loaded->graph->kind]);
      if (!measured) return report(measured.error());
    }
    if (arguments.json) {
      results.push_back({{"graph", name},
                         {"samples", samples.count},
                         {"nodes_before", loaded->instructions_before_optimization},
                         {"nodes_after", loaded->ir.code.size()},
                         {"compile_ms_cold", cold_median},
                         {"compile_ms_cold_fastest", *fastest},
                         {"compile_ms_cold_slowest", *slowest},
                         {"compile_stages_ms",
                          {{"emit", emit_median}, {"optimize", optimize_median}, {"generate", generate_median}}},
                         {"compile_modules", modules},
                         {"compile_ms_cached", cached_milliseconds ? nlohmann::json(*cached_milliseconds) : nlohmann::json()},
                         {"interp_sps_1t", interp_1t},
                         {"interp_sps_mt", interp_mt},
                         {"jit_sps_1t", jit_1t},
                         {"jit_sps_mt", jit_mt},
                         {"cpu", cpu},
                         {"jit_cpu", jit_cpu},
                         {"jit_width", jit_width},
                         {"jit_gathers", jit_gathers},
                         {"driver", driver}});
    } else {
      char cached_text[32] = "-";
      if (cached_milliseconds) std::snprintf(cached_text, sizeof cached_text, "%.3f", *cached_milliseconds);
      char stages_text[48];
      std::snprintf(stages_text, sizeof stages_text, "%.1f/%.1f/%.1f", emit_median, optimize_median, generate_median);
      std::printf("%-16s %8zu %5d->%-5zu %9.2f %17s %9s %10.2fM %10.2fM %10.2fM %10.2fM %8.1fx\n", name.c_str(),
                  samples.count, loaded->instructions_before_optimization, loaded->ir.code.size(), cold_median,
                  stages_text, cached_text, interp_1t / 1e6, interp_mt / 1e6, jit_1t / 1e6, jit_mt / 1e6,
                  jit_1t / interp_1t);
    }
  }
  if (arguments.json) {
    std::printf("%s\n", results.dump(2).c_str());
    return ExitStatus::ok;
  }
  // Figures in seconds are thread time summed over threads; total is wall time.
  for (const auto& [kind, table] : driver_rows) {
    std::printf("\n%s driver (seconds of thread time but total; kernel throughput vs the kernel's 1-thread rate on "
                "the texture samples)\n%-16s %-7s %7s",
                std::string(graph_kind_name(kind)).c_str(), "graph", "backend", "threads");
    for (const std::string& name : table.names) std::printf(" %16s", name.c_str());
    std::printf(" %9s %10s %9s\n", "total s", "kernel", "vs kernel");
    for (const std::string& row : table.rows) std::printf("%s\n", row.c_str());
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
  command->add_option("--compiles", arguments->compiles,
                      "cold compiles per graph, of which the median is reported (default 1)")
      ->check(CLI::Range(1, 100));
  command->add_flag("--json", arguments->json, "print a JSON array, one object per graph");
  command->add_option("--gathers", arguments->gathers, "JIT table lookups: hardware, per-lane, in-register, in-register-bytes, bytes-and-gathers or bytes-and-per-lane (default: the host's)")
      ->check(CLI::IsMember(gather_strategies));
  command->add_option("--width", arguments->width, "JIT vector width: 4, 8 or 16 (default: the host's widest)")
      ->check(CLI::IsMember({4, 8, 16}));
  command->add_flag("--quick", arguments->quick,
                    "measure the JIT's quick kernels (the editor's first previews of an edit) instead of its full ones");
  command->callback([&run, arguments] { run = [arguments] { return bench(*arguments); }; });
}

}  // namespace shadetree

// The editor's latency end to end: a real `shadetree serve` (in this
// process, on a free port of 127.0.0.1) driven over HTTP, as the editor
// page drives it. Three figures, each the time from sending a preview
// request to having its pixels:
//   editor_param_change/marble     a param changed on marble, 256x256:
//                                  params are bound at call time, so no compile
//   editor_volume_drag/fireball    the same on fireball at 128x128: frames per
//                                  second while a slider is dragged
//   editor_graph_edit_cold/G       graph G edited and recompiled cold (the
//                                  JIT's caches bypassed), as the page draws
//                                  it first: 256x256, volumes as a draft at a
//                                  coarser step and at the side the page
//                                  picks from the time opening took (128,
//                                  64, or down to 32 for the slowest; the
//                                  page refines it when the user pauses).
//                                  It renders on the interpreter
//                                  while the JIT compiles in the background,
//                                  then on a quick JIT kernel and on the
//                                  full one (server/preview_kernels.h);
//                                  kernel_ms is the part spent from the
//                                  graph's text to a kernel that runs,
//                                  opening_ms the opening's full preview
// Run
//   build/shadetree_bench --benchmark_filter=editor_ --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <httplib.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "server/editor_server.h"

namespace shadetree {
namespace {

namespace fs = std::filesystem;

const fs::path gallery = fs::path(SHADETREE_SOURCE_DIR) / "graphs";

struct Served {
  std::unique_ptr<EditorServer> server;
  std::unique_ptr<httplib::Client> client;
  httplib::Headers headers;
};

// cold: every request compiles its kernel anew.
Served& served(bool cold) {
  static Served warm_server, cold_server;
  Served& served = cold ? cold_server : warm_server;
  if (served.server) return served;
  ServeOptions options;
  options.folder = gallery.string();
  options.editor_folder = (fs::path(SHADETREE_SOURCE_DIR) / "editor").string();
  options.jit.cold = cold;
  Result<std::unique_ptr<EditorServer>> started = EditorServer::start(options);
  if (!started) {
    std::fprintf(stderr, "%s\n", started.error().to_string().c_str());
    std::exit(1);
  }
  served.server = std::move(*started);
  served.client = std::make_unique<httplib::Client>("127.0.0.1", served.server->port());
  served.client->set_read_timeout(120);  // a volume opened at full size takes seconds
  served.headers = {{"X-Shadetree-Token", served.server->token()}};
  return served;
}

nlohmann::json gallery_graph(const std::string& name) {
  std::ifstream file(gallery / (name + ".json"));
  return nlohmann::json::parse(file);
}

// Posts `body` as a preview of `name`; false (and the benchmark skipped
// with the server's error) unless it rendered from `expected_kernel`, if
// set. Adds the server's compile time to *compile_milliseconds.
bool preview(benchmark::State& state, Served& served, const std::string& name, const std::string& body, int side,
             const char* expected_kernel, double* compile_milliseconds = nullptr, bool draft = false) {
  const std::string url = "/api/preview?path=" + name + ".json&width=" + std::to_string(side) +
                          "&height=" + std::to_string(side) + "&slot=main" + (draft ? "&draft=1" : "");
  httplib::Result result = served.client->Post(url, served.headers, body, "application/json");
  if (!result || result->status != 200) {
    state.SkipWithError(result ? result->body.c_str() : "no response");
    return false;
  }
  if (expected_kernel && result->get_header_value("X-Kernel") != expected_kernel) {
    state.SkipWithError(("the kernel came from " + result->get_header_value("X-Kernel")).c_str());
    return false;
  }
  if (compile_milliseconds) *compile_milliseconds += std::stod(result->get_header_value("X-Compile-Milliseconds"));
  return true;
}

// Waits until the server compiles nothing in the background: each edit
// starts from an idle server.
void wait_for_background_compiles(Served& served) {
  for (int poll = 0; poll < 3000; ++poll) {
    httplib::Result stats = served.client->Get("/api/stats", served.headers);
    if (stats && nlohmann::json::parse(stats->body)["compiling"] == 0) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

// A slider dragged: param `param` alternates between its default and a
// quarter more, which binds the cached kernel anew each time.
void drag_param(benchmark::State& state, const std::string& name, const std::string& param, int side) {
  Served& server = served(false);
  nlohmann::json graph = gallery_graph(name);
  std::string bodies[2];
  for (int b = 0; b < 2; ++b) {
    nlohmann::json& declared = graph["params"][param];
    if (b == 1) declared["default"] = 1.25 * declared["default"].get<double>();
    bodies[b] = graph.dump();
  }
  if (!preview(state, server, name, bodies[0], side, nullptr)) return;  // compiled (or found) once
  wait_for_background_compiles(server);
  int turn = 0;
  for (auto _ : state)
    if (!preview(state, server, name, bodies[++turn % 2], side, "memory")) return;
}

void editor_param_change(benchmark::State& state) { drag_param(state, "marble", "scale", 256); }
void editor_volume_drag(benchmark::State& state) { drag_param(state, "fireball", "scale", 128); }

// The side of a volume's first draft after an edit, as previewSide() in
// editor/editor.js picks it from the full preview's time: half the full
// side, a quarter when that took over 150 ms, and smaller (down to 32, in
// steps of 16) where the draft's budget, judged by that time over the
// drafts' saving per pixel, calls for it.
int first_draft_side(double full_preview_milliseconds) {
  constexpr int full_side = 256;
  constexpr double draft_budget_milliseconds = 30.0, draft_saving = 6.0;
  const int largest = full_preview_milliseconds > 150 ? full_side / 4 : full_side / 2;
  const double draft_ms_per_pixel = full_preview_milliseconds / (full_side * full_side) / draft_saving;
  return std::clamp(16 * static_cast<int>(std::sqrt(draft_budget_milliseconds / draft_ms_per_pixel) / 16), 32, largest);
}

void editor_graph_edit_cold(benchmark::State& state, const std::string& name) {
  const nlohmann::json graph = gallery_graph(name);
  const bool volume = graph.value("kind", "texture") == "volume";
  const std::string body = graph.dump();
  // Opening the graph draws it at 256x256 (a volume after a 64x64 draft)
  // and reads its images and meshes; an edit finds them read.
  if (volume && !preview(state, served(true), name, body, 64, "compiling", nullptr, true)) return;
  const auto opening = std::chrono::steady_clock::now();
  if (!preview(state, served(true), name, body, 256, "compiling")) return;
  const double opening_milliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - opening).count();
  const int side = volume ? first_draft_side(opening_milliseconds) : 256;
  state.counters["side"] = side;
  state.counters["opening_ms"] = opening_milliseconds;
  double compile_milliseconds = 0;
  for (auto _ : state) {
    state.PauseTiming();
    wait_for_background_compiles(served(true));
    state.ResumeTiming();
    if (!preview(state, served(true), name, body, side, "compiling", &compile_milliseconds, volume)) return;
  }
  state.counters["kernel_ms"] = benchmark::Counter(compile_milliseconds, benchmark::Counter::kAvgIterations);
}

BENCHMARK(editor_param_change)->Name("editor_param_change/marble")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(editor_volume_drag)->Name("editor_volume_drag/fireball")->Unit(benchmark::kMillisecond)->UseRealTime();

const bool graph_edits_registered = [] {
  std::vector<std::string> names;
  for (const fs::directory_entry& entry : fs::directory_iterator(gallery))
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  for (const std::string& name : names)
    benchmark::RegisterBenchmark(("editor_graph_edit_cold/" + name).c_str(),
                                 [name](benchmark::State& state) { editor_graph_edit_cold(state, name); })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  return true;
}();

}  // namespace
}  // namespace shadetree

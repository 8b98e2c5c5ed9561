// The drivers of the graph kinds (nodes/graph_kind.h), in one table: for
// each kind the render options it takes and how a graph of it is set up
// (render section checked, scene built, camera placed) and rendered, frame
// by frame. The command line, the server's previews, the C API and bench
// render every kind through prepare_render and nowhere else, so a new
// kind is a row of nodes/graph_kind.h and one here with its driver.
#pragma once

#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "graph/diagnostic.h"
#include "graph/graph.h"
#include "graph/json_reader.h"
#include "ir/kernel.h"
#include "nodes/image.h"
#include "render/glsl_drivers.h"
#include "schedule/image_tiles.h"
#include "schedule/progress.h"

namespace shadetree {

// The options of a render that only some kinds take.
enum RenderOption : unsigned {
  option_samples_per_pixel = 1,  // --spp
  option_object = 2,             // --object
  option_shadows = 4,            // --shadows exact or off (--no-shadows)
  option_step = 8,               // --step
  option_jitter = 16,            // --jitter
  option_normals = 32,           // --normals exact
};

// How shaded samples find what reaches them of each light. A surface's
// shadow rays are always exact: cached is exact there.
enum class ShadowMode {
  cached,  // volume: read from a grid marched once per light and frame (render/transmittance_grid.h)
  exact,   // a shadow ray from every shaded sample toward every light
  off,
};

// What a caller asks of a render, whatever the graph's kind.
struct RenderRequest {
  std::optional<std::pair<int, int>> size;  // default: the graph's render size
  int threads = 0;                          // 0: all cores
  int samples_per_pixel = 1;                // surface: jittered samples per pixel
  std::string object;                       // surface: a preview object instead of the graph's scene
  ShadowMode shadows = ShadowMode::cached;  // surface, volume: and the scene's "shadows"
  std::optional<float> step;                // volume: the march step (default: the volume's)
  bool jitter = false;                      // volume: jitter each ray's start (default: the volume's)
  bool draft = false;                       // volume: march coarser steps (editor previews while editing)
  int lane_width = 0;                       // the kernel's vector width, for the lane figures only
  std::vector<std::string> search_paths;    // folders besides the graph's own that its scene may read
  const std::atomic<bool>* cancel = nullptr;  // see for_each_tile (schedule/image_tiles.h)
  TileSink tile_done;  // volume: told of each tile as it is done (other kinds: not called)
  // volume: light soft samples by the density's exact gradient, from
  // normal_kernel (VolumeRenderOptions::normal_kernel), not two probes
  bool exact_normals = false;
  const Kernel* normal_kernel = nullptr;

  // The RenderOption bits this request sets.
  unsigned options() const;
};

// What a frame's render tells: a line for the command line, and the
// figures bench tabulates (seconds are of one core, summed over threads).
struct FrameReport {
  std::string what;     // "512x512, 262144 samples"
  std::string details;  // where the time went; empty: the samples' rate over the frame
  double seconds = 0;   // the frame's wall time
  long kernel_samples = 0;  // samples the graph was run on
  double kernel_seconds = 0;
  std::vector<std::pair<std::string, double>> figures;  // by name: "visible_samples", "march_s", ...

  // "<what> in <seconds> s (<details>": the caller closes the parenthesis.
  std::string summary() const;
};

// A graph's driver, set up for one request; renders any frame with any
// kernel of the graph.
class FrameRenderer {
 public:
  virtual ~FrameRenderer() = default;
  // The frame, and in `report` (if not null) what it took. With `claims`,
  // only the pixels of the tiles it hands out (for_each_tile).
  Result<Image> render(const Kernel& kernel, const std::vector<float>& params, float frame,
                       const ProgressCallback& progress, FrameReport* report, TileClaims* claims = nullptr) const;

 private:
  // The driver's part: the frame, and its counts in `report` but the time.
  virtual Result<Image> render_frame(const Kernel& kernel, const std::vector<float>& params, float frame,
                                     const ProgressCallback& progress, TileClaims* claims,
                                     FrameReport& report) const = 0;
};

// What `shadetree eval` shows of the sample a driver makes at a point.
struct PointSample {
  float P[3];
  float uv[2];
  float filter_width;
};

struct GraphKindDriver {
  GraphKind kind;
  unsigned options;  // the RenderOption bits it takes
  std::string_view progress_verb;  // "marching": what its progress line says it does
  std::string_view progress_unit;  // "rays": what its progress counts besides tiles
  bool bench_driver;  // bench measures the driver as well as the kernel
  Result<std::unique_ptr<FrameRenderer>> (*prepare)(const Graph& graph, const RenderRequest& request);
  // A node's thumbnail (server/node_probe.h) is a graph of this kind with
  // the node's value as its colour; where that is not how to see it, this
  // rewrites that graph's document. Null: it renders as it is.
  void (*thumbnail_document)(const Graph& graph, json& document);
  // The inputs its driver gives the sample at point `at` (a direction, for
  // an environment) in an image of `size`, stored as sample 0 of `buffers`.
  PointSample (*sample_at_point)(const Graph& graph, std::pair<int, int> size, const float at[3],
                                 SampleBuffers& buffers);
  // The driver as GLSL, around the graph's function (render/glsl_drivers.h).
  Result<GlslDriver> (*glsl_driver)(const Graph& graph, const GlslFunction& function);
};

const GraphKindDriver& graph_kind_driver(GraphKind kind);

// The driver of `graph`'s kind set up for `request`: refused, naming the
// graph's file, when the request sets an option the kind does not take,
// the size is out of range, or the scene cannot be built.
Result<std::unique_ptr<FrameRenderer>> prepare_render(const Graph& graph, const RenderRequest& request);

}  // namespace shadetree

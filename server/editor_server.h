// `shadetree serve`: a local HTTP server (cpp-httplib) for the browser
// editor. It keeps the JIT and its kernel caches warm across requests, so
// a param change re-renders without compiling, and serves the graph files
// of one folder and the editor's own files.
//
// Security of a local server: it binds to 127.0.0.1 unless told otherwise;
// every request must carry the session's random token (in the URL, as
// Jupyter does, or the X-Shadetree-Token header), so other users of the
// machine and other web pages cannot drive it. The page sets it as a
// SameSite cookie too, which suffices for GET requests only (the page, its
// files, reading graphs): other local pages' requests carry that cookie,
// and none may compile, render or write. Requests whose Host header is not
// the server's own are refused (DNS rebinding); only files inside the
// served folder are read or written, through one path policy
// (graph/file_path.h); bodies, graphs and previews are capped, and so are
// connections (server/bounded_http_server.h). Every refusal is a 4xx with
// a one-line JSON error, {"error": "..."}.
//
// Endpoints (JSON unless said):
//   GET  /                      the editor (sets the token cookie)
//   GET  /assets/PATH           the editor's files
//   GET  /api/nodes             the node library and the graph kinds' output contracts
//                               (server/node_library.h)
//   GET  /api/graphs            {"graphs": [relative paths of the .json files]}
//   GET  /api/graph?path=P      the file's text, with its ETag
//   PUT  /api/graph?path=P[&new=1]
//                               saves the body (JSON text) to P, through a temporary file;
//                               with new=1 (save as), 409 if P exists; with If-Match, 412 if P
//                               is not that ETag's text any more; the new text's ETag
//   POST /api/check?path=P      checks the body as graph P: {"ok": true} or {"ok": false, "parsed": B,
//                               "error": {...}}; parsed is false when the body is not a graph file at
//                               all (its JSON, fields and their types: graph/parse.h), true when it is
//                               one with a check error
//   POST /api/preview?path=P&width=W&height=H&frame=F[&node=ID][&slot=S]
//                               renders the body as graph P: W x H RGBA bytes, rows from the top;
//                               headers X-Width, X-Height, X-Kernel (memory | disk | compiled |
//                               compiling: server/preview_kernels.h),
//                               X-Milliseconds (X-Compile-Milliseconds of them from the
//                               graph's text to a kernel that runs). node=ID (or ID.output): that node's value
//                               instead of the outputs (server/node_probe.h), for thumbnails; with
//                               function=F, ID is a node of function F's body.
//                               slot=S: a newer request of the same slot cancels this one,
//                               which then answers 409 {"error": "superseded"}. draft=1: a
//                               volume marches at a coarser step (render/graph_preview.h).
//                               stream=1 (not with node=): the picture as records of tiles sent
//                               as they are done, then an end record with the error if any
//                               (server/preview_stream.h); no X-Milliseconds
//   POST /api/glsl?path=P       the body as graph P in GLSL for the page's own GPU
//                               (glslgen/emit_glsl.h): {"source": the fragment shader,
//                               "uniforms": [{"param", "name", "type", "slot", "components"}]};
//                               422 with the diagnostic for a graph that does not check, is not
//                               a texture or environment graph or holds too much data for a shader
//   POST /api/export?path=P&width=W&height=H&frame=F&format=png|exr
//                               the body rendered as an image file (up to max_export_side)
//   GET  /api/stats             {"compiles": kernels compiled since start, "compiling": in the
//                                background now, "previews": N,
//                                "rendering": previews in progress, "kernels": JIT kernels resident:
//                                the memory cache's (jit/jit_compiler.h, 64) and those compiles and
//                                renders under way hold besides}
#pragma once

#include <atomic>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "graph/check.h"
#include "graph/diagnostic.h"
#include "jit/jit_compiler.h"
#include "nodes/image.h"
#include "server/bounded_http_server.h"
#include "server/preview_kernels.h"
#include "server/served_folder.h"

namespace httplib {
class Server;
struct Request;
struct Response;
}

namespace shadetree {

struct ServeOptions {
  std::string folder = ".";      // the graphs served
  std::string editor_folder;     // the editor's files (index.html, editor.js, node_modules/)
  std::string host = "127.0.0.1";
  int port = 0;                  // 0: a free port
  std::string token;             // empty: a random one
  std::size_t max_body = std::size_t{4} << 20;
  int max_preview_side = 2048;
  int max_export_side = 4096;
  JitSettings jit;
  int background_compiles = 2;  // at once (server/preview_kernels.h)
  ConnectionLimits connections;  // against slow and idle clients (server/bounded_http_server.h)
};

class EditorServer {
 public:
  // Binds and starts serving on a thread of its own.
  static Result<std::unique_ptr<EditorServer>> start(const ServeOptions& options);
  ~EditorServer();

  int port() const { return port_; }
  const std::string& token() const { return options_.token; }
  std::string url() const;  // what to open, token included
  long compiles() const { return kernels_.compiles(); }

  void stop();  // and waits for the server's thread

 private:
  struct PreparedRender;  // a request's body loaded and compiled, ready to render (editor_server.cpp)

  EditorServer(const ServeOptions& options, ServedFolder graphs, ServedFolder editor);
  void add_routes();
  void add_request_guards();  // Host and token checks; every error as JSON
  void add_editor_file_routes();
  void add_node_library_and_stats_routes();
  void add_graph_file_routes();
  void add_check_route();
  void add_glsl_route();
  void add_render_routes();  // preview and export

  bool is_own_host(const std::string& host) const;
  // Why the request is refused, or nothing if it may go on.
  std::optional<std::string> access_refusal(const httplib::Request& request) const;
  void serve_editor_file(httplib::Response& response, const std::string& relative) const;
  // The graph file a request names, or (unless `named`) the served folder's untitled.json.
  Result<std::filesystem::path> graph_path(const httplib::Request& request, bool named) const;
  // The request's body (a graph, or a node of it with node=) to render at
  // width x height up to `max_side` in its slot, or sends the error and
  // returns nothing.
  std::optional<PreparedRender> prepare_body(const httplib::Request& request, httplib::Response& response, int max_side);
  Result<Image> render_prepared(PreparedRender& prepared);
  // A failed render's error: 409 where a newer request of the slot superseded it.
  void send_render_error(httplib::Response& response, const Diagnostic& error, bool cancelled) const;
  // Sends the render's tiles as they are done (server/preview_stream.h).
  void stream_render(std::shared_ptr<PreparedRender> prepared, httplib::Response& response);
  // The slot's flag, raised to cancel the render of its previous request.
  std::shared_ptr<std::atomic<bool>> claim_slot(const std::string& slot);
  void release_slot(const std::string& slot, const std::shared_ptr<std::atomic<bool>>& flag);

  ServeOptions options_;
  ServedFolder graphs_, editor_;
  GraphFiles files_;  // images and meshes the graphs name, kept while unchanged on disk
  PreviewKernels kernels_;
  std::unique_ptr<httplib::Server> server_;
  std::thread thread_;
  int port_ = 0;
  std::atomic<long> previews_{0}, rendering_{0};
  std::mutex slots_mutex_;
  std::map<std::string, std::shared_ptr<std::atomic<bool>>> slots_;  // slot -> its render in progress
};

}  // namespace shadetree

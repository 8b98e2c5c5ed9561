#include "server/editor_server.h"

#include <httplib.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <optional>
#include <random>
#include <sstream>

#include <nlohmann/json.hpp>

#include "render/glsl_shader.h"
#include "graph/parse.h"
#include "jit/jit_compiler.h"
#include "jit/jit_kernel.h"
#include "pipeline/compile_graph.h"
#include "io/graph_files.h"
#include "render/graph_preview.h"
#include "io/image_output.h"
#include "io/output_file.h"
#include "server/node_library.h"
#include "server/node_probe.h"
#include "server/preview_stream.h"

namespace shadetree {
namespace {

// Browsers keep cookies per host, not per port: a server's cookie is
// named after its port, so that two servers on one host do not log each
// other's pages out.
std::string token_cookie(int port) { return "shadetree_token_" + std::to_string(port); }

std::string random_token() {
  std::random_device device;
  std::ostringstream token;
  for (int i = 0; i < 4; ++i) {
    char part[9];
    std::snprintf(part, sizeof part, "%08x", static_cast<unsigned>(device()));
    token << part;
  }
  return token.str();
}

// glibc gives each thread that allocates an arena of its own, up to eight
// per core, and each keeps its high-water mark: a server whose 32 workers
// take turns serving edits grew by megabytes over a day's edits without
// holding anything. Two arenas a core keep its memory flat (measured with
// EditorServerTest.ResidentMemoryStaysFlatOverAThousandGraphEdits), at the
// cost of some contention between the few threads that allocate at once.
void keep_the_heap_flat() {
#ifdef __GLIBC__
  static const bool set = mallopt(M_ARENA_MAX, 2 * static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
  (void)set;
#endif
}

// Equal strings, in time that does not depend on where they differ.
bool same_secret(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return false;
  unsigned char difference = 0;
  for (std::size_t i = 0; i < a.size(); ++i) difference |= static_cast<unsigned char>(a[i] ^ b[i]);
  return difference == 0;
}

void send_error(httplib::Response& response, int status, const std::string& message) {
  response.status = status;
  response.set_content(nlohmann::json{{"error", message}}.dump(), "application/json");
}

void send_json(httplib::Response& response, const nlohmann::json& json) {
  response.set_content(json.dump(), "application/json");
}

// A diagnostic as the page is shown it: paths inside the served folder
// relative to it, as the page names files; where the folder is on the
// server's disk is none of the page's business.
Diagnostic relative_to(const ServedFolder& folder, Diagnostic diagnostic) {
  diagnostic.file = folder.relative_text(std::move(diagnostic.file));
  diagnostic.message = folder.relative_text(std::move(diagnostic.message));
  return diagnostic;
}

nlohmann::json diagnostic_json(const Diagnostic& diagnostic) {
  return {{"file", diagnostic.file},       {"node", diagnostic.node},         {"input", diagnostic.input},
          {"message", diagnostic.message}, {"text", diagnostic.to_string()}};
}

// 400 for what the user can fix, 500 for what they cannot.
int http_status(const Diagnostic& diagnostic) { return diagnostic.status == ExitStatus::invalid_input ? 400 : 500; }

std::string cookie_value(const httplib::Request& request, const std::string& name) {
  const std::string cookies = request.get_header_value("Cookie");
  std::istringstream stream(cookies);
  std::string part;
  while (std::getline(stream, part, ';')) {
    const std::size_t start = part.find_first_not_of(' ');
    if (start == std::string::npos) continue;
    part = part.substr(start);
    if (part.rfind(name + "=", 0) == 0) return part.substr(name.size() + 1);
  }
  return {};
}

std::string content_type(const std::filesystem::path& path) {
  const std::string extension = path.extension().string();
  if (extension == ".html") return "text/html; charset=utf-8";
  if (extension == ".js" || extension == ".mjs") return "text/javascript; charset=utf-8";
  if (extension == ".css") return "text/css; charset=utf-8";
  if (extension == ".json" || extension == ".map") return "application/json";
  if (extension == ".png") return "image/png";
  if (extension == ".svg") return "image/svg+xml";
  return "application/octet-stream";
}

std::string read_file(const std::filesystem::path& path, bool* ok) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  *ok = static_cast<bool>(file) || file.eof();
  return text.str();
}

// A query parameter as an integer within [low, high], or why not.
Result<int> integer_parameter(const httplib::Request& request, const char* name, int fallback, int low, int high) {
  if (!request.has_param(name)) return fallback;
  const std::string text = request.get_param_value(name);
  try {
    std::size_t used = 0;
    const long value = std::stol(text, &used);
    if (used == text.size() && value >= low && value <= high) return static_cast<int>(value);
  } catch (const std::exception&) {
  }
  return invalid_input(std::string(name) + " must be an integer from " + std::to_string(low) + " to " +
                       std::to_string(high) + ", got \"" + text + "\"");
}

// A node's thumbnail shows its values' shape whatever their range (a
// noise in [-1, 1], a product reaching 4): where they leave [0, 1], the
// range [min(0, lowest), max(1, highest)] of its colour channels is mapped
// onto [0, 1]. Values within [0, 1] stay as they are. The range mapped.
std::pair<float, float> show_thumbnail_range(Image& image) {
  float lowest = 0.0f, highest = 1.0f;
  const int colours = std::min(image.channels, 3);
  const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
  for (std::size_t i = 0; i < pixels; ++i)
    for (int c = 0; c < colours; ++c) {
      const float value = image.pixels[i * image.channels + c];
      if (!std::isfinite(value)) continue;
      lowest = std::min(lowest, value);
      highest = std::max(highest, value);
    }
  if (lowest < 0.0f || highest > 1.0f)
    for (std::size_t i = 0; i < pixels; ++i)
      for (int c = 0; c < colours; ++c) {
        float& value = image.pixels[i * image.channels + c];
        value = (value - lowest) / (highest - lowest);
      }
  return {lowest, highest};
}

// A graph file's HTTP entity tag: a digest of its text, enough to tell
// that another program changed the file (not a defence against anyone).
std::string entity_tag(const std::string& text) {
  char tag[32];
  std::snprintf(tag, sizeof tag, "\"%016zx\"", std::hash<std::string>{}(text));
  return tag;
}

double milliseconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// A body that does not load as a graph: 422, with the diagnostic's fields.
void send_unprocessable(httplib::Response& response, const ServedFolder& folder, const Diagnostic& error) {
  const Diagnostic diagnostic = relative_to(folder, error);
  response.status = 422;
  send_json(response, {{"error", diagnostic.to_string()}, {"diagnostic", diagnostic_json(diagnostic)}});
}

// The size, frame and draft a preview request asks for, its sides up to `max_side`.
Result<PreviewRequest> preview_request(const httplib::Request& request, int max_side) {
  PreviewRequest preview;
  for (auto [name, target] : {std::pair{"width", &preview.width}, std::pair{"height", &preview.height}}) {
    Result<int> side = integer_parameter(request, name, 256, 1, max_side);
    if (!side) return side.error();
    *target = *side;
  }
  Result<int> frame = integer_parameter(request, "frame", 0, 0, 1000000);
  if (!frame) return frame.error();
  preview.frame = static_cast<float>(*frame);
  preview.draft = request.get_param_value("draft") == "1";
  return preview;
}

// The request's body as graph `path`, or with node= the graph that shows
// that node's value instead (server/node_probe.h).
Result<LoadedGraph> load_body(const httplib::Request& request, const std::filesystem::path& path,
                              const GraphFiles& files) {
  if (!request.has_param("node")) return compile_graph_text(request.body, path.string(), {}, {}, files);
  Result<std::string> probe = node_probe_graph(request.body, path.string(), request.get_param_value("node"), files,
                                               request.get_param_value("function"));
  if (!probe) return probe.error();
  return compile_graph_text(*probe, path.string(), {}, {}, files);
}

// The image as the bytes of a png or exr file. OpenImageIO writes files:
// write one in the system's temporary folder, read it, and remove it.
Result<std::string> image_file_bytes(const Image& image, const std::string& format) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("shadetree-export-" + random_token() + "." + format);
  Status written = write_image(image, file.string());
  bool ok = false;
  const std::string bytes = written ? read_file(file, &ok) : std::string();
  std::error_code ignored;
  std::filesystem::remove(file, ignored);
  if (!written) return written.error();
  if (!ok) return failure("cannot read back the exported image");
  return bytes;
}

}  // namespace

EditorServer::EditorServer(const ServeOptions& options, ServedFolder graphs, ServedFolder editor)
    : options_(options),
      graphs_(std::move(graphs)),
      editor_(std::move(editor)),
      files_(graph_files()),
      kernels_(options.jit, options.background_compiles),
      server_(make_bounded_http_server(options.connections)) {}

EditorServer::~EditorServer() { stop(); }

Result<std::unique_ptr<EditorServer>> EditorServer::start(const ServeOptions& requested) {
  ServeOptions options = requested;
  if (options.token.empty()) options.token = random_token();
  Result<ServedFolder> graphs = ServedFolder::open(options.folder);
  if (!graphs) return graphs.error();
  Result<ServedFolder> editor = ServedFolder::open(options.editor_folder);
  if (!editor) {
    Diagnostic error = editor.error();
    error.message = "the editor's files are missing (run scripts/build.sh, which installs them with npm ci)";
    return error;
  }
  keep_the_heap_flat();
  std::unique_ptr<EditorServer> server(new EditorServer(options, std::move(*graphs), std::move(*editor)));
  server->add_routes();
  server->server_->set_payload_max_length(options.max_body);
  if (options.port == 0) {
    server->port_ = server->server_->bind_to_any_port(options.host);
  } else if (server->server_->bind_to_port(options.host, options.port)) {
    server->port_ = options.port;
  }
  if (server->port_ <= 0)
    return Diagnostic{ExitStatus::failure, {}, {}, {},
                      "cannot listen on " + options.host + ":" + std::to_string(options.port)};
  httplib::Server* http = server->server_.get();
  server->thread_ = std::thread([http] { http->listen_after_bind(); });
  // Until it runs: httplib's stop() does nothing before, and the thread
  // would listen on after a stop() that came too soon (starting its workers
  // takes a while).
  for (int wait = 0; wait < 10000 && !http->is_running(); ++wait)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  return server;
}

std::string EditorServer::url() const {
  const std::string host = options_.host.find(':') != std::string::npos ? "[" + options_.host + "]" : options_.host;
  return "http://" + host + ":" + std::to_string(port_) + "/?token=" + options_.token;
}

void EditorServer::stop() {
  if (server_) server_->stop();
  if (thread_.joinable()) thread_.join();
}

struct EditorServer::PreparedRender {
  LoadedGraph loaded;
  PreviewKernel kernel;
  PreviewRequest preview;
  double compile_milliseconds;  // graph text to a kernel that runs
  std::string slot;
  std::shared_ptr<std::atomic<bool>> cancel;  // raised by a newer request of the slot
};

void EditorServer::add_routes() {
  add_request_guards();
  add_editor_file_routes();
  add_node_library_and_stats_routes();
  add_graph_file_routes();
  add_check_route();
  add_glsl_route();
  add_render_routes();
}

void EditorServer::add_request_guards() {
  httplib::Server& http = *server_;
  http.set_pre_routing_handler([this](const httplib::Request& request, httplib::Response& response) {
    const std::optional<std::string> refusal = access_refusal(request);
    if (!refusal) return httplib::Server::HandlerResponse::Unhandled;
    send_error(response, 403, *refusal);
    return httplib::Server::HandlerResponse::Handled;
  });
  http.set_exception_handler([](const httplib::Request&, httplib::Response& response, std::exception_ptr) {
    send_error(response, 500, "internal error");
  });
  http.set_error_handler([](const httplib::Request& request, httplib::Response& response) {
    if (!response.body.empty()) return;
    // Debian's cpp-httplib is built to read a form's body (curl -d sends
    // one) up to 8 KB only, whatever the server's own limit.
    const bool form = request.get_header_value("Content-Type").starts_with("application/x-www-form-urlencoded");
    const std::string message = response.status == 413 && form
                                    ? "request body too large for a form (at most 8 KB): send the graph as "
                                      "application/json (curl --data-binary @g.json -H 'Content-Type: application/json')"
                                : response.status == 413 ? "request body too large"
                                : response.status == 404 ? "no such endpoint"
                                                         : "bad request";
    send_error(response, response.status, message);
  });
}

// Against DNS rebinding: a page whose site's name comes to resolve to this
// machine still sends that name as the Host.
bool EditorServer::is_own_host(const std::string& host) const {
  const std::string port = ":" + std::to_string(port_);
  for (const std::string& name : {options_.host, std::string("localhost"), std::string("127.0.0.1"),
                                  std::string("[::1]"), "[" + options_.host + "]"})
    if (host == name + port) return true;
  return false;
}

// Every request: the Host must be ours, and the token must come along.
std::optional<std::string> EditorServer::access_refusal(const httplib::Request& request) const {
  const std::string host = request.get_header_value("Host");
  if (!is_own_host(host)) return "the Host header \"" + host + "\" is not this server's";
  // The cookie rides on requests that other pages of this machine make
  // (a text/plain POST from another port is same-site and needs no
  // preflight), so it only lets the page and its files load and graphs be
  // read. Every other request compiles, renders or writes, and must name
  // the token itself, in the URL or in a header no other page can set.
  std::string token = request.get_param_value("token");
  if (token.empty()) token = request.get_header_value("X-Shadetree-Token");
  if (same_secret(token, options_.token)) return std::nullopt;
  const bool reads = request.method == "GET" || request.method == "HEAD";
  if (reads && same_secret(cookie_value(request, token_cookie(port_)), options_.token)) return std::nullopt;
  return reads ? "missing or wrong token: open the URL shadetree serve printed"
               : "this request needs the token in the URL or the X-Shadetree-Token header, not only the cookie";
}

void EditorServer::add_editor_file_routes() {
  httplib::Server& http = *server_;
  http.Get("/", [this](const httplib::Request&, httplib::Response& response) {
    serve_editor_file(response, "index.html");
    response.set_header("Set-Cookie", token_cookie(port_) + "=" + options_.token +
                                          "; Path=/; HttpOnly; SameSite=Strict");
    response.set_header("Cache-Control", "no-store");
  });
  http.Get(R"(/assets/(.+))", [this](const httplib::Request& request, httplib::Response& response) {
    serve_editor_file(response, request.matches[1]);
  });
}

void EditorServer::serve_editor_file(httplib::Response& response, const std::string& relative) const {
  Result<std::filesystem::path> path = editor_.resolve(relative);
  bool ok = false;
  const std::string content = path ? read_file(*path, &ok) : std::string();
  if (!path || !ok || !std::filesystem::is_regular_file(*path)) return send_error(response, 404, "no such file");
  response.set_content(content, content_type(*path).c_str());
}

void EditorServer::add_node_library_and_stats_routes() {
  httplib::Server& http = *server_;
  http.Get("/api/nodes", [](const httplib::Request&, httplib::Response& response) {
    send_json(response, node_library_json());
  });
  http.Get("/api/stats", [this](const httplib::Request&, httplib::Response& response) {
    send_json(response, {{"compiles", kernels_.compiles()},
                         {"compiling", kernels_.compiling()},
                         {"previews", previews_.load()},
                         {"rendering", rendering_.load()},
                         {"kernels", resident_kernel_count()}});
  });
}

void EditorServer::add_graph_file_routes() {
  httplib::Server& http = *server_;
  http.Get("/api/graphs", [this](const httplib::Request&, httplib::Response& response) {
    send_json(response, {{"graphs", graphs_.graph_files()}});
  });
  http.Get("/api/graph", [this](const httplib::Request& request, httplib::Response& response) {
    Result<std::filesystem::path> path = graph_path(request, true);
    if (!path) return send_error(response, 400, path.error().message);
    bool ok = false;
    const std::string text = read_file(*path, &ok);
    if (!ok || !std::filesystem::is_regular_file(*path)) return send_error(response, 404, "no such graph file");
    response.set_header("ETag", entity_tag(text));
    response.set_content(text, "application/json");
  });
  http.Put("/api/graph", [this](const httplib::Request& request, httplib::Response& response) {
    Result<std::filesystem::path> path = graph_path(request, true);
    if (!path) return send_error(response, 400, path.error().message);
    if (request.get_param_value("new") == "1" && std::filesystem::exists(*path))
      return send_error(response, 409, request.get_param_value("path") + " exists already");
    if (!nlohmann::json::accept(request.body)) return send_error(response, 400, "the body is not JSON");
    // If-Match: the file as the page last read or wrote it. A file another
    // program changed (or removed) since is not written over unasked.
    if (request.has_header("If-Match")) {
      bool ok = false;
      const std::string text = read_file(*path, &ok);
      if (!ok || entity_tag(text) != request.get_header_value("If-Match"))
        return send_error(response, 412,
                          request.get_param_value("path") + (ok ? " changed on disk" : " was removed") +
                              " since it was opened here");
    }
    Status written = write_then_rename(path->string(), [&](const std::string& temporary) -> std::string {
      std::ofstream file(temporary, std::ios::binary);
      file << request.body;
      file.close();
      return file ? "" : "cannot write " + temporary;
    });
    if (!written) return send_error(response, 500, relative_to(graphs_, written.error()).message);
    response.set_header("ETag", entity_tag(request.body));
    send_json(response, {{"saved", request.get_param_value("path")}});
  });
}

Result<std::filesystem::path> EditorServer::graph_path(const httplib::Request& request, bool named) const {
  if (!request.has_param("path")) {
    if (named) return invalid_input("the request needs ?path=FILE.json");
    return graphs_.path() / "untitled.json";
  }
  Result<std::filesystem::path> path = graphs_.resolve(request.get_param_value("path"));
  if (path && path->extension() != ".json") return invalid_input("graph files end in .json");
  return path;
}

void EditorServer::add_check_route() {
  server_->Post("/api/check", [this](const httplib::Request& request, httplib::Response& response) {
    Result<std::filesystem::path> path = graph_path(request, false);
    if (!path) return send_error(response, 400, path.error().message);
    // The editor opens a graph with a check error, to mend it, but not a
    // file that does not parse as one: the canvas could not show it.
    // "error" is the fault to mend first; "errors" all that were found.
    const auto refused = [&](bool parsed, const std::vector<Diagnostic>& faults) {
      nlohmann::json errors = nlohmann::json::array();
      for (const Diagnostic& fault : faults) errors.push_back(diagnostic_json(relative_to(graphs_, fault)));
      send_json(response, {{"ok", false}, {"parsed", parsed}, {"error", errors.front()}, {"errors", errors}});
    };
    Result<Graph> parsed = parse_graph(request.body, path->string());
    if (!parsed) return refused(false, {parsed.error()});
    Result<LoadedGraph> loaded = compile_graph(*parsed, {}, files_);
    if (!loaded) return refused(true, every_fault(parsed, loaded.error(), files_));
    send_json(response, {{"ok", true}});
  });
}

void EditorServer::add_glsl_route() {
  server_->Post("/api/glsl", [this](const httplib::Request& request, httplib::Response& response) {
    Result<std::filesystem::path> path = graph_path(request, false);
    if (!path) return send_error(response, 400, path.error().message);
    Result<Graph> parsed = parse_graph(request.body, path->string());
    if (!parsed) return send_unprocessable(response, graphs_, parsed.error());
    Result<LoadedGraph> loaded = compile_graph(std::move(*parsed), {}, files_);
    if (!loaded) return send_unprocessable(response, graphs_, loaded.error());
    Result<GlslShader> shader = glsl_shader(*loaded->graph, loaded->ir, loaded->params, {loaded->graph->name, false});
    if (!shader) return send_unprocessable(response, graphs_, shader.error());
    nlohmann::json uniforms = nlohmann::json::array();
    for (const GlslUniform& uniform : shader->uniforms)
      uniforms.push_back({{"param", uniform.param},
                          {"name", uniform.name},
                          {"type", uniform.type},
                          {"slot", uniform.slot},
                          {"components", uniform.components}});
    send_json(response, {{"source", shader->source}, {"uniforms", uniforms}});
  });
}

void EditorServer::add_render_routes() {
  httplib::Server& http = *server_;
  http.Post("/api/preview", [this](const httplib::Request& request, httplib::Response& response) {
    const auto start = std::chrono::steady_clock::now();
    const bool streamed = request.get_param_value("stream") == "1";
    if (streamed && request.has_param("node"))
      return send_error(response, 400, "a node's preview is not streamed: its range is mapped over the whole picture");
    std::optional<PreparedRender> prepared = prepare_body(request, response, options_.max_preview_side);
    if (!prepared) return;
    const auto set_headers = [&] {
      response.set_header("X-Width", std::to_string(prepared->preview.width));
      response.set_header("X-Height", std::to_string(prepared->preview.height));
      response.set_header("X-Kernel", source_name(prepared->kernel.source));
      response.set_header("X-Compile-Milliseconds", std::to_string(prepared->compile_milliseconds));
    };
    if (streamed) {
      set_headers();
      return stream_render(std::make_shared<PreparedRender>(std::move(*prepared)), response);
    }
    Result<Image> image = render_prepared(*prepared);
    if (!image) return send_render_error(response, image.error(), *prepared->cancel);
    ++previews_;
    if (request.has_param("node")) {
      const auto [lowest, highest] = show_thumbnail_range(*image);
      response.set_header("X-Range", std::to_string(lowest) + " " + std::to_string(highest));
    }
    response.set_content(rgba_bytes(*image), "application/octet-stream");
    set_headers();
    response.set_header("X-Milliseconds", std::to_string(milliseconds_since(start)));
  });
  http.Post("/api/export", [this](const httplib::Request& request, httplib::Response& response) {
    const std::string format = request.has_param("format") ? request.get_param_value("format") : "png";
    if (format != "png" && format != "exr") return send_error(response, 400, "format must be png or exr");
    std::optional<PreparedRender> prepared = prepare_body(request, response, options_.max_export_side);
    if (!prepared) return;
    Result<Image> image = render_prepared(*prepared);
    if (!image) return send_render_error(response, image.error(), *prepared->cancel);
    Result<std::string> bytes = image_file_bytes(*image, format);
    if (!bytes) return send_error(response, 500, bytes.error().message);
    const Result<std::filesystem::path> path = graph_path(request, false);
    const std::string stem = path ? path->stem().string() : "untitled";
    response.set_content(*bytes, format == "png" ? "image/png" : "image/x-exr");
    response.set_header("Content-Disposition", "attachment; filename=\"" + stem + "." + format + "\"");
  });
}

std::optional<EditorServer::PreparedRender> EditorServer::prepare_body(const httplib::Request& request,
                                                                      httplib::Response& response, int max_side) {
  Result<std::filesystem::path> path = graph_path(request, false);
  if (!path) return send_error(response, 400, path.error().message), std::nullopt;
  Result<PreviewRequest> preview = preview_request(request, max_side);
  if (!preview) return send_error(response, 400, preview.error().message), std::nullopt;
  const std::string slot = request.get_param_value("slot");
  if (slot.size() > 100) return send_error(response, 400, "slot names are at most 100 characters"), std::nullopt;
  const auto start = std::chrono::steady_clock::now();
  Result<LoadedGraph> loaded = load_body(request, *path, files_);
  if (!loaded) return send_unprocessable(response, graphs_, loaded.error()), std::nullopt;
  Result<PreviewKernel> kernel = kernels_.kernel_for(loaded->ir);
  if (!kernel) return send_error(response, 500, kernel.error().to_string()), std::nullopt;
  const double compile_milliseconds = milliseconds_since(start);
  std::shared_ptr<std::atomic<bool>> cancel = slot.empty() ? std::make_shared<std::atomic<bool>>(false) : claim_slot(slot);
  return PreparedRender{std::move(*loaded), std::move(*kernel), *preview, compile_milliseconds, slot, std::move(cancel)};
}

Result<Image> EditorServer::render_prepared(PreparedRender& prepared) {
  prepared.preview.cancel = prepared.cancel.get();
  ++rendering_;
  Result<Image> image = render_preview(prepared.loaded, *prepared.kernel.kernel, prepared.preview);
  --rendering_;
  if (!prepared.slot.empty()) release_slot(prepared.slot, prepared.cancel);
  return image;
}

void EditorServer::send_render_error(httplib::Response& response, const Diagnostic& error, bool cancelled) const {
  if (cancelled) return send_error(response, 409, "superseded");
  send_error(response, http_status(error), relative_to(graphs_, error).to_string());
}

// The render runs when the library asks for the body, after the headers
// went; tiles are written from the render's threads, one at a time. A
// client gone (a newer edit aborted it) cancels the render.
void EditorServer::stream_render(std::shared_ptr<PreparedRender> prepared, httplib::Response& response) {
  response.set_chunked_content_provider("application/octet-stream", [this, prepared](std::size_t, httplib::DataSink& sink) {
    std::mutex writing;
    bool open = true, streamed = false;
    const auto write = [&](const std::string& record) {
      open = open && sink.write(record.data(), record.size());
      return open;
    };
    prepared->preview.tile_done = [&](const Image& frame, const Tile& tile) {
      const std::string record = tile_record(frame, tile);
      std::lock_guard lock(writing);
      streamed = true;
      if (!write(record)) prepared->cancel->store(true);
    };
    Result<Image> image = render_prepared(*prepared);
    std::lock_guard lock(writing);
    prepared->preview.tile_done = nullptr;
    if (image) {
      ++previews_;
      // Kinds whose drivers do not tell of tiles send the frame whole.
      if (!streamed) write(tile_record(*image, {0, 0, image->width, image->height}));
    }
    write(end_record(image                   ? std::string()
                     : prepared->cancel->load() ? "superseded"
                                                : relative_to(graphs_, image.error()).to_string()));
    if (open) sink.done();
    return open;
  });
}

std::shared_ptr<std::atomic<bool>> EditorServer::claim_slot(const std::string& slot) {
  auto flag = std::make_shared<std::atomic<bool>>(false);
  std::lock_guard lock(slots_mutex_);
  std::shared_ptr<std::atomic<bool>>& current = slots_[slot];
  if (current) current->store(true);
  current = flag;
  return flag;
}

void EditorServer::release_slot(const std::string& slot, const std::shared_ptr<std::atomic<bool>>& flag) {
  std::lock_guard lock(slots_mutex_);
  if (auto found = slots_.find(slot); found != slots_.end() && found->second == flag) slots_.erase(found);
}

}  // namespace shadetree

// The editor's server over real HTTP on a free port of 127.0.0.1: every
// endpoint's success and error cases, the token, the Host check, paths
// that try to leave the served folder, caps, malformed requests, and
// param changes that re-render without compiling.
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <httplib.h>
#include <sys/socket.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include <nlohmann/json.hpp>

#include "nodes/registry.h"
#include "pipeline/compile_graph.h"
#include "server/editor_server.h"

namespace shadetree {
namespace {

namespace fs = std::filesystem;

const char* const sines_graph = R"({"format": "shadetree-graph", "version": 1, "name": "waves", "kind": "texture",
  "params": {"frequency": {"type": "float", "default": 3, "min": 0.1, "max": 50}},
  "nodes": [{"id": "p", "op": "P"}, {"id": "s", "op": "sines", "in": {"p": "p", "frequency": "$frequency"}},
            {"id": "c", "op": "to_color", "in": {"v": "s"}}],
  "outputs": {"color": "c"}})";

class EditorServerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / "shadetree-editor-server-test";
    fs::remove_all(root_);
    fs::create_directories(root_ / "graphs" / "more");
    fs::create_directories(root_ / "editor");
    std::ofstream(root_ / "graphs" / "waves.json") << sines_graph;
    std::ofstream(root_ / "graphs" / "more" / "two.json") << sines_graph;
    std::ofstream(root_ / "secret.json") << "{\"secret\": true}";
    fs::create_symlink(root_ / "secret.json", root_ / "graphs" / "link.json");
    std::ofstream(root_ / "editor" / "index.html") << "<!doctype html><title>editor</title>";
    ServeOptions options;
    options.folder = (root_ / "graphs").string();
    options.editor_folder = (root_ / "editor").string();
    options.max_body = 64 * 1024;
    Result<std::unique_ptr<EditorServer>> started = EditorServer::start(options);
    ASSERT_TRUE(started.ok()) << started.error().to_string();
    server_ = std::move(*started);
    client_ = std::make_unique<httplib::Client>("127.0.0.1", server_->port());
    headers_ = {{"X-Shadetree-Token", server_->token()}};
  }
  void TearDown() override {
    client_.reset();
    server_.reset();
    fs::remove_all(root_);
  }

  static std::string error_of(const httplib::Result& result) {
    if (!result) return "no response";
    const auto json = nlohmann::json::parse(result->body, nullptr, false);
    EXPECT_TRUE(json.is_object() && json.contains("error")) << result->body;
    if (!json.is_object() || !json.contains("error")) return {};
    const std::string error = json["error"];
    EXPECT_EQ(error.find('\n'), std::string::npos) << "one line";
    return error;
  }

  fs::path root_;
  std::unique_ptr<EditorServer> server_;
  std::unique_ptr<httplib::Client> client_;
  httplib::Headers headers_;
};

TEST_F(EditorServerTest, EveryRequestNeedsTheToken) {
  auto result = client_->Get("/api/graphs");
  ASSERT_TRUE(result);
  EXPECT_EQ(result->status, 403);
  EXPECT_NE(error_of(result).find("token"), std::string::npos);
  EXPECT_EQ(client_->Get("/api/graphs", {{"X-Shadetree-Token", "not-the-token"}})->status, 403);
  EXPECT_EQ(client_->Get("/?token=" + server_->token().substr(1))->status, 403);
  EXPECT_EQ(client_->Get("/api/graphs", headers_)->status, 200);
  // The page sets the token as a SameSite cookie, which then suffices.
  result = client_->Get("/?token=" + server_->token());
  ASSERT_EQ(result->status, 200);
  const std::string cookie = result->get_header_value("Set-Cookie");
  EXPECT_NE(cookie.find("SameSite=Strict"), std::string::npos) << cookie;
  EXPECT_NE(cookie.find("HttpOnly"), std::string::npos) << cookie;
  EXPECT_EQ(client_->Get("/api/graphs", {{"Cookie", cookie.substr(0, cookie.find(';'))}})->status, 200);
  EXPECT_NE(server_->url().find("http://127.0.0.1:" + std::to_string(server_->port()) + "/?token="),
            std::string::npos);
}

// DNS rebinding: a page of evil.example resolving to 127.0.0.1 still says
// Host: evil.example.
TEST_F(EditorServerTest, ForeignHostHeadersAreRefused) {
  httplib::Headers foreign = headers_;
  foreign.emplace("Host", "evil.example:" + std::to_string(server_->port()));
  auto result = client_->Get("/api/graphs", foreign);
  ASSERT_TRUE(result);
  EXPECT_EQ(result->status, 403);
  EXPECT_NE(error_of(result).find("Host"), std::string::npos);
  httplib::Headers local = headers_;
  local.emplace("Host", "localhost:" + std::to_string(server_->port()));
  EXPECT_EQ(client_->Get("/api/graphs", local)->status, 200);
}

TEST_F(EditorServerTest, ListsReadsAndServesTheNodeLibrary) {
  auto graphs = client_->Get("/api/graphs", headers_);
  ASSERT_EQ(graphs->status, 200);
  EXPECT_EQ(nlohmann::json::parse(graphs->body)["graphs"],  // not link.json, which leads out
            nlohmann::json::parse(R"(["more/two.json", "waves.json"])"));
  auto graph = client_->Get("/api/graph?path=more/two.json", headers_);
  ASSERT_EQ(graph->status, 200);
  EXPECT_EQ(graph->body, sines_graph);
  auto nodes = client_->Get("/api/nodes", headers_);
  ASSERT_EQ(nodes->status, 200);
  const auto library = nlohmann::json::parse(nodes->body)["ops"];
  EXPECT_EQ(library.size(), all_ops().size());
  bool found = false;
  for (const auto& op : library)
    if (op["name"] == "turbulence") {
      found = true;
      EXPECT_EQ(op["inputs"][0]["type"], "vec3");
      EXPECT_EQ(op["inputs"][1]["default"], 6.0);
      EXPECT_EQ(op["attributes"][0]["name"], "seed");
    }
  EXPECT_TRUE(found);
  EXPECT_EQ(client_->Get("/assets/index.html", headers_)->status, 200);
  EXPECT_EQ(client_->Get("/assets/missing.js", headers_)->status, 404);
  EXPECT_EQ(client_->Get("/api/nothing", headers_)->status, 404);
}

TEST_F(EditorServerTest, PathsMayNotLeaveTheServedFolder) {
  for (const char* path : {"../secret.json", "%2Fetc%2Fpasswd", "more/../../secret.json", "link.json", "", "waves.txt"}) {
    auto result = client_->Get(std::string("/api/graph?path=") + path, headers_);
    ASSERT_TRUE(result) << path;
    EXPECT_EQ(result->status, 400) << path << ": " << result->body;
    error_of(result);
  }
  EXPECT_EQ(client_->Get("/api/graph?path=absent.json", headers_)->status, 404);
  EXPECT_EQ(client_->Get("/assets/../graphs/waves.json", headers_)->status, 404);
  EXPECT_EQ(client_->Put("/api/graph?path=../escape.json", headers_, "{}", "application/json")->status, 400);
  EXPECT_FALSE(fs::exists(root_ / "escape.json"));
}

TEST_F(EditorServerTest, SavesThroughATemporaryFileWhatCheckAccepts) {
  const std::string edited = std::regex_replace(sines_graph, std::regex("\"default\": 3"), "\"default\": 7");
  auto saved = client_->Put("/api/graph?path=more/saved.json", headers_, edited, "application/json");
  ASSERT_EQ(saved->status, 200) << saved->body;
  std::ifstream file(root_ / "graphs" / "more" / "saved.json");
  const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, edited);
  EXPECT_TRUE(load_and_compile((root_ / "graphs" / "more" / "saved.json").string(), {}).ok());
  auto broken = client_->Put("/api/graph?path=broken.json", headers_, "{\"nodes\": [", "application/json");
  EXPECT_EQ(broken->status, 400);
  EXPECT_FALSE(fs::exists(root_ / "graphs" / "broken.json"));
  EXPECT_EQ(client_->Put("/api/graph?path=nowhere/x.json", headers_, "{}", "application/json")->status, 400);
}

TEST_F(EditorServerTest, ChecksGraphsWithTheCommandLinesDiagnostics) {
  auto good = client_->Post("/api/check?path=waves.json", headers_, sines_graph, "application/json");
  ASSERT_EQ(good->status, 200);
  EXPECT_EQ(nlohmann::json::parse(good->body)["ok"], true);
  const std::string wrong = std::regex_replace(sines_graph, std::regex("\"frequency\": \"\\$frequency\""),
                                               "\"frequency\": \"p\"");  // a vec3 into a float
  auto bad = client_->Post("/api/check?path=waves.json", headers_, wrong, "application/json");
  ASSERT_EQ(bad->status, 200);
  const auto json = nlohmann::json::parse(bad->body);
  EXPECT_EQ(json["ok"], false);
  EXPECT_EQ(json["error"]["node"], "s");
  EXPECT_EQ(json["error"]["input"], "frequency");
  const Result<LoadedGraph> cli = compile_graph_text(wrong, (root_ / "graphs" / "waves.json").string());
  ASSERT_FALSE(cli.ok());
  EXPECT_EQ(json["error"]["text"], cli.error().to_string()) << "the same text as the command line";
}

TEST_F(EditorServerTest, PreviewsRenderAndParamChangesDoNotRecompile) {
  auto first = client_->Post("/api/preview?path=waves.json&width=32&height=16", headers_, sines_graph,
                             "application/json");
  ASSERT_EQ(first->status, 200) << first->body;
  EXPECT_EQ(first->body.size(), 32u * 16u * 4u);
  EXPECT_EQ(first->get_header_value("X-Width"), "32");
  const long compiles = server_->compiles();
  const std::string changed = std::regex_replace(sines_graph, std::regex("\"default\": 3"), "\"default\": 11");
  auto second = client_->Post("/api/preview?path=waves.json&width=32&height=16", headers_, changed, "application/json");
  ASSERT_EQ(second->status, 200);
  EXPECT_EQ(second->get_header_value("X-Kernel"), "memory");
  EXPECT_EQ(server_->compiles(), compiles) << "a param change binds, never compiles";
  EXPECT_NE(second->body, first->body) << "and changes the picture";
  auto stats = client_->Get("/api/stats", headers_);
  EXPECT_EQ(nlohmann::json::parse(stats->body)["previews"], 2);

  EXPECT_EQ(client_->Post("/api/preview?width=99999", headers_, sines_graph, "application/json")->status, 400);
  EXPECT_EQ(client_->Post("/api/preview?width=abc", headers_, sines_graph, "application/json")->status, 400);
  auto invalid = client_->Post("/api/preview", headers_, "{\"format\": 3}", "application/json");
  EXPECT_EQ(invalid->status, 422);
  error_of(invalid);
}

TEST_F(EditorServerTest, OversizedAndMalformedRequestsGetErrorsAndTheServerLivesOn) {
  auto large = client_->Post("/api/check", headers_, std::string(100 * 1024, ' '), "application/json");
  ASSERT_TRUE(large);
  EXPECT_EQ(large->status, 413);
  // Garbage on a raw socket.
  const int socket = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(server_->port()));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::connect(socket, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  const std::string garbage = "\x01\x02 NOT HTTP \r\n\r\n\xff\xfe";
  ASSERT_GT(::write(socket, garbage.data(), garbage.size()), 0);
  char reply[512];
  const ssize_t read = ::read(socket, reply, sizeof reply);
  ::close(socket);
  EXPECT_GT(read, 0);
  EXPECT_EQ(std::string(reply, 12).substr(0, 9), "HTTP/1.1 ");
  EXPECT_EQ(client_->Get("/api/graphs", headers_)->status, 200) << "the server lives on";
}

}  // namespace
}  // namespace shadetree

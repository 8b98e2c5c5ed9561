// shadetree serve [DIR] [--port N] [--host H]: the browser editor for the
// graphs of DIR, until interrupted (server/editor_server.h).
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <thread>

#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "server/editor_server.h"

namespace shadetree {

namespace {

// Set by SIGINT and SIGTERM; the main thread then stops the server (which
// is not something a signal handler may do).
volatile std::sig_atomic_t stop_requested = 0;

extern "C" void request_stop(int) { stop_requested = 1; }

// Installed beside the executable (share/shadetree/editor), else the
// source tree's editor/ where the build put its packages.
std::string editor_folder() {
  std::error_code error;
  const auto executable = std::filesystem::read_symlink("/proc/self/exe", error).parent_path();
  const auto installed = executable.parent_path() / "share" / "shadetree" / "editor";
  if (!error && std::filesystem::exists(installed / "index.html", error)) return installed.string();
  return SHADETREE_EDITOR_DIR;
}

ExitStatus serve(ServeOptions options) {
  if (options.host != "127.0.0.1" && options.host != "localhost" && options.host != "::1")
    std::fprintf(stderr,
                 "warning: serving on %s, not the loopback address: anyone who can reach it and has the token can "
                 "read and write the graphs of %s\n",
                 options.host.c_str(), options.folder.c_str());
  options.editor_folder = editor_folder();
  Result<std::unique_ptr<EditorServer>> server = EditorServer::start(options);
  if (!server) return report(server.error());
  std::signal(SIGINT, request_stop);
  std::signal(SIGTERM, request_stop);
  std::printf("shadetree editor for %s: open %s\n", options.folder.c_str(), (*server)->url().c_str());
  std::fflush(stdout);
  while (!stop_requested) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  (*server)->stop();
  return ExitStatus::ok;
}

}  // namespace

void add_serve_command(CLI::App& app, CommandRunner& run) {
  auto* command = app.add_subcommand("serve", "serve the browser graph editor for the graphs of a folder");
  auto options = std::make_shared<ServeOptions>();
  command->add_option("folder", options->folder, "the folder of graph files (default: the current folder)");
  command->add_option("--port", options->port, "the port (default: a free one)")->check(CLI::Range(0, 65535));
  command->add_option("--host", options->host, "the address to listen on (default 127.0.0.1, this machine only)");
  command->callback([&run, options] { run = [options] { return serve(*options); }; });
}

}  // namespace shadetree

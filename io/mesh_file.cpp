// Mesh files: checked here against the limits from their text, then read
// by Assimp in a process of its own (io/mesh_reader.cpp); OBJ and PLY are
// what the tests cover, and any other format Assimp reads loads too.
// Every mesh of the file is flattened into one triangle list in the
// file's space.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

#include "graph/file_path.h"
#include "platform/loadable_module.h"
#include "io/mesh_file.h"
#include "io/mesh_record.h"

extern char** environ;

namespace shadetree {
namespace {

Diagnostic mesh_error(const std::string& path, ExitStatus status, std::string message) {
  for (char& c : message)
    if (c == '\n' || c == '\r') c = ' ';
  return Diagnostic{status, path, {}, {}, std::move(message)};
}

// Why Assimp must not be given an OBJ or PLY file, judged from its text:
// more triangles, vertices or OBJ parts than the limits (Assimp takes about
// 700 bytes a triangle while loading), a PLY element count larger than the file
// could hold (999999999 vertices in a 100-byte file took gigabytes), or a
// PLY header without its end (on which Assimp never returned). Empty if
// none; other formats only the file size bounds.
std::string mesh_text_problem(const std::string& path, std::uintmax_t bytes) {
  std::ifstream file(path, std::ios::binary);
  std::string line;
  const std::string too_many_triangles = "mesh has more than " + std::to_string(max_mesh_triangles) + " triangles";
  const std::string too_many_vertices = "mesh has more than " + std::to_string(max_mesh_vertices) + " vertices";
  if (std::getline(file, line) && line.rfind("ply", 0) == 0) {
    for (int lines = 0; lines < 10000 && std::getline(file, line); ++lines) {
      // Exactly that word: Assimp never returns on "end_header" followed by
      // anything but white space, as on no end_header at all.
      while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
      if (line == "end_header") return {};
      if (line.rfind("element ", 0) != 0) continue;
      std::istringstream words(line.substr(8));
      std::string element;
      unsigned long long count = 0;
      words >> element >> count;
      if (element == "face" && count > max_mesh_triangles) return too_many_triangles;
      if (element == "vertex" && count > max_mesh_vertices) return too_many_vertices;
      // Every element takes at least a byte of the file.
      if (count > bytes)
        return "PLY header declares " + std::to_string(count) + " \"" + element + "\" elements, more than a file of " +
               std::to_string(bytes) + " bytes holds";
    }
    return "PLY header has no end_header";
  }
  if (std::filesystem::path(path).extension() != ".obj") return {};
  std::size_t triangles = 0, vertices = 0;
  std::size_t parts = 0;
  do {
    if ((line.rfind("o ", 0) == 0 || line.rfind("usemtl", 0) == 0) && ++parts > max_obj_parts)
      return "OBJ file has more than " + std::to_string(max_obj_parts) + " objects and material switches";
    if (line.size() < 2 || (line[1] != ' ' && line[1] != '\t')) continue;
    if (line[0] == 'v' && ++vertices > max_mesh_vertices) return too_many_vertices;
    if (line[0] != 'f') continue;
    // "f a b c d": one triangle per corner past the second.
    std::size_t corners = 0;
    for (std::size_t i = 1; i < line.size(); ++i)
      if ((line[i - 1] == ' ' || line[i - 1] == '\t') && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++corners;
    if (corners > 2) triangles += corners - 2;
    if (triangles > max_mesh_triangles) return too_many_triangles;
  } while (std::getline(file, line));
  return {};
}

// A mesh reader that has not answered in this long is stopped: it has
// spent its minute of CPU time, or it is waiting on something.
constexpr auto mesh_reader_deadline = std::chrono::seconds(90);

// Runs the mesh reader on `path` and collects its record.
Result<TriangleMesh> read_in_mesh_reader(const std::string& path) {
  const std::string reader = support_file_path("shadetree_mesh_reader");
  int pipe_ends[2];
  if (::pipe2(pipe_ends, O_CLOEXEC) != 0) return mesh_error(path, ExitStatus::failure, "cannot start the mesh reader");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipe_ends[1], 3);  // dup2 clears close-on-exec on fd 3
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  char* const arguments[] = {const_cast<char*>(reader.c_str()), const_cast<char*>(path.c_str()), nullptr};
  pid_t child = 0;
  const int spawned = ::posix_spawn(&child, reader.c_str(), &actions, nullptr, arguments, environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(pipe_ends[1]);
  if (spawned != 0) {
    ::close(pipe_ends[0]);
    return mesh_error(path, ExitStatus::failure, "cannot run the mesh reader " + reader + ": " + std::strerror(spawned));
  }
  std::string record;
  bool timed_out = false, too_large = false;
  const auto deadline = std::chrono::steady_clock::now() + mesh_reader_deadline;
  char buffer[1 << 16];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    pollfd readable{pipe_ends[0], POLLIN, 0};
    if (left.count() <= 0 || ::poll(&readable, 1, static_cast<int>(left.count())) == 0) {
      timed_out = true;
      break;
    }
    const ssize_t n = ::read(pipe_ends[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    record.append(buffer, static_cast<std::size_t>(n));
    if (record.size() > max_mesh_record_bytes) {
      too_large = true;
      break;
    }
  }
  ::close(pipe_ends[0]);
  if (timed_out || too_large) ::kill(child, SIGKILL);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (timed_out) return mesh_error(path, ExitStatus::invalid_input, "reading the mesh file took too long");
  if (WIFSIGNALED(status))
    return mesh_error(path, ExitStatus::invalid_input,
                      std::string("the mesh reader failed on this file (") + ::strsignal(WTERMSIG(status)) + ")");
  if (record.empty())
    return mesh_error(path, ExitStatus::failure,
                      "the mesh reader " + reader + " stopped with status " + std::to_string(WEXITSTATUS(status)));
  return read_mesh_record(record, path);
}

}  // namespace

Result<TriangleMesh> load_mesh(const std::string& path) {
  if (Status text = check_path_text(path, "mesh file"); !text) return text.error();
  std::error_code error;
  if (!std::filesystem::exists(path, error)) return mesh_error(path, ExitStatus::invalid_input, "no such mesh file");
  if (std::filesystem::is_directory(path, error))
    return mesh_error(path, ExitStatus::invalid_input, "is a directory, not a mesh file");
  const std::uintmax_t bytes = std::filesystem::file_size(path, error);
  if (error) return mesh_error(path, ExitStatus::failure, "cannot read mesh file: " + error.message());
  if (bytes > max_mesh_file_bytes)
    return mesh_error(path, ExitStatus::invalid_input,
                      "mesh file is larger than " + std::to_string(max_mesh_file_bytes >> 20) + " MiB");
  if (std::string problem = mesh_text_problem(path, bytes); !problem.empty())
    return mesh_error(path, ExitStatus::invalid_input, problem);

  Result<TriangleMesh> read = read_in_mesh_reader(path);
  if (!read) return read.error();
  TriangleMesh& result = *read;
  for (const glm::vec3& p : result.positions)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      return mesh_error(path, ExitStatus::invalid_input, "mesh has a NaN or infinite vertex coordinate");
  for (glm::vec3& n : result.normals)
    if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z)) n = glm::vec3(0.0f);
  for (std::uint32_t index : result.indices)
    if (index >= result.positions.size())
      return mesh_error(path, ExitStatus::invalid_input, "mesh has a face index out of range");
  return result;
}

}  // namespace shadetree

// Mesh files through Assimp: OBJ and PLY are what the tests cover; any
// other format Assimp reads loads too. Every mesh of the file is
// flattened into one triangle list in the file's space.
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

#include <assimp/DefaultIOSystem.h>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "graph/file_path.h"
#include "io/mesh_file.h"

namespace shadetree {
namespace {

Diagnostic mesh_error(const std::string& path, ExitStatus status, std::string message) {
  for (char& c : message)
    if (c == '\n' || c == '\r') c = ' ';
  return Diagnostic{status, path, {}, {}, std::move(message)};
}

void append(const aiMesh& mesh, const aiMatrix4x4& transform, TriangleMesh& result, bool with_normals, bool with_uvs) {
  const auto base = static_cast<std::uint32_t>(result.positions.size());
  aiMatrix3x3 normal_transform(transform);
  normal_transform.Inverse().Transpose();
  for (unsigned i = 0; i < mesh.mNumVertices; ++i) {
    const aiVector3D p = transform * mesh.mVertices[i];
    result.positions.emplace_back(p.x, p.y, p.z);
    if (with_normals) {
      aiVector3D n = normal_transform * mesh.mNormals[i];
      n.Normalize();
      result.normals.emplace_back(n.x, n.y, n.z);
    }
    if (with_uvs) result.uvs.emplace_back(mesh.mTextureCoords[0][i].x, mesh.mTextureCoords[0][i].y);
  }
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
    const aiFace& face = mesh.mFaces[f];
    if (face.mNumIndices != 3) continue;  // points and lines left by triangulation
    for (int k = 0; k < 3; ++k) result.indices.push_back(base + face.mIndices[k]);
  }
}

// Assimp opens the files a mesh file names (an OBJ's mtllib, a glTF's
// buffers) through its IOSystem: this one opens the mesh file alone, so a
// file cannot make shadetree read /etc/shadow or anything else outside
// the path policy. Materials are not used; a missing one is not an error.
class MeshFileOnly : public Assimp::DefaultIOSystem {
 public:
  explicit MeshFileOnly(std::string path) : path_(std::move(path)) {}
  bool Exists(const char* file) const override { return path_ == file && DefaultIOSystem::Exists(file); }
  Assimp::IOStream* Open(const char* file, const char* mode) override {
    if (path_ != file || std::strchr(mode, 'w') || std::strchr(mode, 'a')) return nullptr;
    return DefaultIOSystem::Open(file, mode);
  }

 private:
  std::string path_;
};

// Why Assimp must not be given an OBJ or PLY file, judged from its text:
// more triangles or vertices than the limits (Assimp takes about 700 bytes
// a triangle while loading), a PLY element count larger than the file
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
  do {
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

  Assimp::Importer importer;
  importer.SetIOHandler(new MeshFileOnly(path));  // the importer owns it
  // Only triangles; no points or lines.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene = importer.ReadFile(path, aiProcess_ValidateDataStructure);
  if (!scene || !scene->mRootNode)
    return mesh_error(path, ExitStatus::invalid_input, std::string("cannot read mesh: ") + importer.GetErrorString());
  // A malformed file can leave faces without corners in a mesh marked as
  // holding polygons (a PLY with an unknown property type did), on which
  // Assimp's triangulation asserts and so aborts the process: they are
  // dropped, and the mesh's primitive types taken from the faces left.
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    aiMesh& mesh = *scene->mMeshes[m];
    unsigned kept = 0, types = 0;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const unsigned corners = mesh.mFaces[f].mNumIndices;
      if (corners == 0) continue;
      types |= corners == 1   ? aiPrimitiveType_POINT
               : corners == 2 ? aiPrimitiveType_LINE
               : corners == 3 ? aiPrimitiveType_TRIANGLE
                              : aiPrimitiveType_POLYGON;
      std::swap(mesh.mFaces[kept++], mesh.mFaces[f]);
    }
    mesh.mNumFaces = kept;
    mesh.mPrimitiveTypes = types;
  }
  scene = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_SortByPType | aiProcess_JoinIdenticalVertices);
  if (!scene || !scene->mRootNode)
    return mesh_error(path, ExitStatus::invalid_input, std::string("cannot read mesh: ") + importer.GetErrorString());

  // Normals and uvs only where every mesh of the file has them.
  bool with_normals = true, with_uvs = true;
  std::size_t triangles = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    with_normals = with_normals && scene->mMeshes[m]->HasNormals();
    with_uvs = with_uvs && scene->mMeshes[m]->HasTextureCoords(0);
    triangles += scene->mMeshes[m]->mNumFaces;
  }
  if (triangles > max_mesh_triangles)
    return mesh_error(path, ExitStatus::invalid_input,
                      "mesh has more than " + std::to_string(max_mesh_triangles) + " triangles");

  TriangleMesh result;
  // Walk the node tree without recursion (a hostile file may nest deeply).
  std::vector<std::pair<const aiNode*, aiMatrix4x4>> pending = {{scene->mRootNode, scene->mRootNode->mTransformation}};
  while (!pending.empty()) {
    auto [node, transform] = pending.back();
    pending.pop_back();
    for (unsigned i = 0; i < node->mNumMeshes; ++i) {
      if (node->mMeshes[i] >= scene->mNumMeshes) continue;
      append(*scene->mMeshes[node->mMeshes[i]], transform, result, with_normals, with_uvs);
      if (result.indices.size() / 3 > max_mesh_triangles)
        return mesh_error(path, ExitStatus::invalid_input,
                          "mesh has more than " + std::to_string(max_mesh_triangles) + " triangles");
    }
    for (unsigned i = 0; i < node->mNumChildren; ++i)
      pending.emplace_back(node->mChildren[i], transform * node->mChildren[i]->mTransformation);
  }
  if (result.indices.empty()) return mesh_error(path, ExitStatus::invalid_input, "mesh file holds no triangles");
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

// The mesh reader: a program of its own (shadetree_mesh_reader) that
// reads one mesh file with Assimp and writes it, or why it cannot, as a
// record (io/mesh_record.h) to file descriptor 3. load_mesh
// (io/mesh_file.cpp) runs it, so that Assimp's faults on a hostile file
// (aborts, endless loops, gigabytes of memory) end this process and not
// shadetree; its address space and CPU time are bounded here.
#include <sys/resource.h>
#include <unistd.h>

#include <cstring>
#include <utility>

#include <assimp/DefaultIOSystem.h>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "io/mesh_record.h"

namespace shadetree {
namespace {

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

Result<TriangleMesh> read_with_assimp(const std::string& path) {
  const auto mesh_error = [&](ExitStatus status, std::string message) {
    for (char& c : message)
      if (c == '\n' || c == '\r') c = ' ';
    return Diagnostic{status, path, {}, {}, std::move(message)};
  };
  Assimp::Importer importer;
  importer.SetIOHandler(new MeshFileOnly(path));  // the importer owns it
  // Only triangles; no points or lines.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene = importer.ReadFile(path, aiProcess_ValidateDataStructure);
  if (!scene || !scene->mRootNode)
    return mesh_error(ExitStatus::invalid_input, std::string("cannot read mesh: ") + importer.GetErrorString());
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
    return mesh_error(ExitStatus::invalid_input, std::string("cannot read mesh: ") + importer.GetErrorString());

  // Normals and uvs only where every mesh of the file has them.
  bool with_normals = true, with_uvs = true;
  std::size_t triangles = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    with_normals = with_normals && scene->mMeshes[m]->HasNormals();
    with_uvs = with_uvs && scene->mMeshes[m]->HasTextureCoords(0);
    triangles += scene->mMeshes[m]->mNumFaces;
  }
  if (triangles > max_mesh_triangles)
    return mesh_error(ExitStatus::invalid_input,
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
        return mesh_error(ExitStatus::invalid_input,
                          "mesh has more than " + std::to_string(max_mesh_triangles) + " triangles");
    }
    for (unsigned i = 0; i < node->mNumChildren; ++i)
      pending.emplace_back(node->mChildren[i], transform * node->mChildren[i]->mTransformation);
  }
  if (result.indices.empty()) return mesh_error(ExitStatus::invalid_input, "mesh file holds no triangles");
  return result;
}

// Assimp takes about 700 bytes a triangle while it loads a file, so the
// largest mesh allowed fits in 8 GiB; a minute of CPU is far more than
// any file within the size limit needs. (A sanitizer's shadow memory
// needs more address space than any limit would leave.)
#if defined(__SANITIZE_ADDRESS__)
constexpr bool address_sanitizer = true;
#elif defined(__has_feature)
constexpr bool address_sanitizer = __has_feature(address_sanitizer);
#else
constexpr bool address_sanitizer = false;
#endif

void bound_this_process() {
  if (!address_sanitizer) {
    const rlimit memory{8ull << 30, 8ull << 30};
    ::setrlimit(RLIMIT_AS, &memory);
  }
  const rlimit cpu{60, 60};
  ::setrlimit(RLIMIT_CPU, &cpu);
}

bool write_all(int fd, const std::string& bytes) {
  for (std::size_t written = 0; written < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n <= 0) return false;
    written += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace
}  // namespace shadetree

int main(int argc, char** argv) {
  using namespace shadetree;
  if (argc != 2) return 2;
  bound_this_process();
  Result<TriangleMesh> mesh = read_with_assimp(argv[1]);
  const std::string record =
      mesh ? mesh_record(*mesh) : mesh_failure_record(mesh.error().status, mesh.error().message);
  return write_all(3, record) ? 0 : 1;
}

// Mesh files through Assimp: OBJ and PLY are what the tests cover; any
// other format Assimp reads loads too. Every mesh of the file is
// flattened into one triangle list in the file's space.
#include <cmath>
#include <filesystem>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "render/mesh.h"

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

}  // namespace

Result<TriangleMesh> load_mesh(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::exists(path, error)) return mesh_error(path, ExitStatus::invalid_input, "no such mesh file");
  if (std::filesystem::is_directory(path, error))
    return mesh_error(path, ExitStatus::invalid_input, "is a directory, not a mesh file");
  const std::uintmax_t bytes = std::filesystem::file_size(path, error);
  if (error) return mesh_error(path, ExitStatus::failure, "cannot read mesh file: " + error.message());
  if (bytes > max_mesh_file_bytes) return mesh_error(path, ExitStatus::invalid_input, "mesh file is larger than 1 GiB");

  Assimp::Importer importer;
  // Only triangles; no points or lines.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_SortByPType |
                                                     aiProcess_JoinIdenticalVertices | aiProcess_ValidateDataStructure);
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

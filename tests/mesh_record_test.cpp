// The mesh reader's records (io/mesh_record.h): a mesh or a failure goes
// through unchanged, and whatever else the pipe delivers (a reader cut
// off, counts past the limits, arrays of the wrong size) is refused.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

#include "io/mesh_record.h"

namespace shadetree {
namespace {

TriangleMesh two_triangles(bool normals, bool uvs) {
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0.5f}};
  if (normals) mesh.normals.assign(4, glm::vec3(0, 0, 1));
  if (uvs) mesh.uvs = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
  mesh.indices = {0, 1, 2, 2, 1, 3};
  return mesh;
}

TEST(MeshRecord, MeshesGoThroughUnchanged) {
  for (bool normals : {false, true})
    for (bool uvs : {false, true}) {
      const TriangleMesh mesh = two_triangles(normals, uvs);
      Result<TriangleMesh> read = read_mesh_record(mesh_record(mesh), "m.obj");
      ASSERT_TRUE(read.ok()) << read.error().to_string();
      EXPECT_EQ(read->positions, mesh.positions);
      EXPECT_EQ(read->normals, mesh.normals);
      EXPECT_EQ(read->uvs, mesh.uvs);
      EXPECT_EQ(read->indices, mesh.indices);
    }
}

TEST(MeshRecord, FailuresKeepTheirStatusAndMessage) {
  Result<TriangleMesh> read =
      read_mesh_record(mesh_failure_record(ExitStatus::invalid_input, "cannot read mesh: no faces"), "m.ply");
  ASSERT_FALSE(read.ok());
  EXPECT_EQ(read.error().to_string(), "error: m.ply: cannot read mesh: no faces");
  EXPECT_EQ(read.error().status, ExitStatus::invalid_input);
}

TEST(MeshRecord, AnythingElseIsRefused) {
  const std::string good = mesh_record(two_triangles(true, true));
  auto with_count = [&](int which, std::uint64_t count) {
    std::string record = good;
    std::memcpy(record.data() + 4 + 8 * which, &count, 8);
    return record;
  };
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "nothing: the reader died before writing"},
      {good.substr(0, good.size() - 1), "cut off"},
      {good + "x", "trailing bytes"},
      {"mush" + good.substr(4), "unknown tag"},
      {with_count(0, max_mesh_vertices + 1), "too many vertices"},
      {with_count(0, std::uint64_t(1) << 62), "a count that would overflow the size"},
      {with_count(1, 3), "normals not one per vertex"},
      {with_count(2, 5), "uvs not one per vertex"},
      {with_count(3, 5), "indices not whole triangles"},
      {with_count(3, 3 * max_mesh_triangles + 3), "too many triangles"},
      {mesh_failure_record(ExitStatus::ok, "fine"), "a failure with status ok"}};
  for (const auto& [record, what] : cases) {
    Result<TriangleMesh> read = read_mesh_record(record, "m.obj");
    ASSERT_FALSE(read.ok()) << what;
    EXPECT_EQ(read.error().to_string(), "error: m.obj: the mesh reader sent a malformed record") << what;
  }
}

}  // namespace
}  // namespace shadetree

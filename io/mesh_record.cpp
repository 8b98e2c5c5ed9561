#include "io/mesh_record.h"

#include <cstdint>
#include <cstring>

namespace shadetree {
namespace {

template <class T>
void append_array(std::string& record, const std::vector<T>& values) {
  if (!values.empty()) record.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

class RecordReader {
 public:
  explicit RecordReader(const std::string& record) : record_(record) {}

  bool take(void* out, std::size_t bytes) {
    if (record_.size() - offset_ < bytes) return false;
    if (bytes == 0) return true;  // `out` may be an empty vector's null data
    std::memcpy(out, record_.data() + offset_, bytes);
    offset_ += bytes;
    return true;
  }
  // `count` is within the mesh limits: its bytes are checked before any
  // memory is taken for them.
  template <class T>
  bool take_array(std::vector<T>& values, std::uint64_t count) {
    if (record_.size() - offset_ < count * sizeof(T)) return false;
    values.resize(count);
    return take(values.data(), count * sizeof(T));
  }
  bool done() const { return offset_ == record_.size(); }
  std::string rest() const { return record_.substr(offset_); }

 private:
  const std::string& record_;
  std::size_t offset_ = 0;
};

}  // namespace

std::string mesh_record(const TriangleMesh& mesh) {
  std::string record = "mesh";
  for (std::uint64_t count : {mesh.positions.size(), mesh.normals.size(), mesh.uvs.size(), mesh.indices.size()})
    record.append(reinterpret_cast<const char*>(&count), sizeof count);
  append_array(record, mesh.positions);
  append_array(record, mesh.normals);
  append_array(record, mesh.uvs);
  append_array(record, mesh.indices);
  return record;
}

std::string mesh_failure_record(ExitStatus status, const std::string& message) {
  std::string record = "fail";
  const auto code = static_cast<std::int32_t>(status);
  record.append(reinterpret_cast<const char*>(&code), sizeof code);
  return record + message;
}

Result<TriangleMesh> read_mesh_record(const std::string& record, const std::string& path) {
  const Diagnostic malformed{ExitStatus::failure, path, {}, {}, "the mesh reader sent a malformed record"};
  RecordReader reader(record);
  char tag[4];
  if (!reader.take(tag, sizeof tag)) return malformed;
  if (std::memcmp(tag, "fail", 4) == 0) {
    std::int32_t code = 0;
    if (!reader.take(&code, sizeof code) ||
        (code != static_cast<int>(ExitStatus::invalid_input) && code != static_cast<int>(ExitStatus::failure)))
      return malformed;
    return Diagnostic{static_cast<ExitStatus>(code), path, {}, {}, reader.rest()};
  }
  std::uint64_t positions = 0, normals = 0, uvs = 0, indices = 0;
  if (std::memcmp(tag, "mesh", 4) != 0 || !reader.take(&positions, 8) || !reader.take(&normals, 8) ||
      !reader.take(&uvs, 8) || !reader.take(&indices, 8))
    return malformed;
  if (positions > max_mesh_vertices || indices > 3 * max_mesh_triangles || indices % 3 != 0 ||
      (normals != 0 && normals != positions) || (uvs != 0 && uvs != positions))
    return malformed;
  TriangleMesh mesh;
  if (!reader.take_array(mesh.positions, positions) || !reader.take_array(mesh.normals, normals) ||
      !reader.take_array(mesh.uvs, uvs) || !reader.take_array(mesh.indices, indices) || !reader.done())
    return malformed;
  return mesh;
}

}  // namespace shadetree

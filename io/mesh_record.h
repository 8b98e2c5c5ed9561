// What the mesh reader process (io/mesh_reader.cpp) sends back through its
// pipe: a mesh, or why the file was refused. Assimp runs in that process
// so that a file that crashes, hangs or exhausts it (Assimp has aborted,
// looped and taken gigabytes on hostile files) costs shadetree an error,
// not the process. The record is checked as any input is: counts within
// the mesh limits, arrays of the sizes the counts say.
#pragma once

#include <string>

#include "graph/diagnostic.h"
#include "io/mesh_file.h"

namespace shadetree {

// The bytes of a record: "mesh" and four counts then the arrays, or
// "fail", the exit status and the message.
std::string mesh_record(const TriangleMesh& mesh);
std::string mesh_failure_record(ExitStatus status, const std::string& message);

// The mesh a record holds, or its failure, or why the record is malformed;
// diagnostics name `path`.
Result<TriangleMesh> read_mesh_record(const std::string& record, const std::string& path);

// The largest record a mesh within the limits makes.
inline constexpr std::size_t max_mesh_record_bytes =
    64 + max_mesh_vertices * (3 + 3 + 2) * sizeof(float) + max_mesh_triangles * 3 * sizeof(std::uint32_t);

}  // namespace shadetree

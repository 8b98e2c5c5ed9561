// The op library as C++ source, for `emit --cpp`: the node headers
// (types, op definitions, semantics over lanes, nodes/lane_simd.h) in
// dependency order, generated at build time by embed_library_source.
#pragma once

#include <string_view>

namespace shadetree {

// The standard headers the library includes, one #include line each.
std::string_view library_includes();

// The library's declarations, all in namespace shadetree, with no
// #include lines.
std::string_view library_source();

}  // namespace shadetree

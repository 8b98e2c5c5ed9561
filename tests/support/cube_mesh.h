// A cube [-h, h]^3 as an OBJ file's text: 6 quads, counter-clockwise seen
// from outside, for the tests that read mesh files.
#pragma once

#include <string>

namespace shadetree::testing {

inline std::string cube_obj(float half) {
  const std::string h = std::to_string(half), m = std::to_string(-half);
  return "v " + m + " " + m + " " + m + "\nv " + h + " " + m + " " + m + "\nv " + h + " " + h + " " + m + "\nv " + m +
         " " + h + " " + m + "\nv " + m + " " + m + " " + h + "\nv " + h + " " + m + " " + h + "\nv " + h + " " + h +
         " " + h + "\nv " + m + " " + h + " " + h +
         "\nf 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n";
}

}  // namespace shadetree::testing

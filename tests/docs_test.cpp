// The docs name files of the source tree: every such name must exist, so
// that a rename or a removal that forgets the docs fails here.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

// Every "folder/.../name.ext" that starts with a top-level folder of the
// repository, in the docs a reader starts from.
TEST(Docs, EveryFileTheyNameExists) {
  const fs::path root = SHADETREE_SOURCE_DIR;
  const std::regex file_name(
      R"(\b((?:nodes|graph|ir|interp|codegen|cppgen|jit|pipeline|render|server|api|cli|bench|tests|fuzz|scripts|editor|docs|examples|graphs|cmake)/[A-Za-z0-9_./-]*[A-Za-z0-9_]\.(?:h|cpp|js|mjs|md|json|sh|py|html|css|obj|png|txt|cmake))\b)");
  int names = 0;
  for (const char* doc : {"README.md", "docs/architecture.md", "docs/graph-format.md"}) {
    std::ifstream file(root / doc);
    ASSERT_TRUE(file) << doc;
    std::stringstream text;
    text << file.rdbuf();
    const std::string contents = text.str();
    for (auto match = std::sregex_iterator(contents.begin(), contents.end(), file_name); match != std::sregex_iterator();
         ++match, ++names) {
      const std::string named = (*match)[1];
      EXPECT_TRUE(fs::exists(root / named)) << doc << " names " << named << ", which does not exist";
    }
  }
  EXPECT_GT(names, 30);
}

}  // namespace

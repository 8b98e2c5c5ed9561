// The served folder's paths: what resolves inside it, and messages that
// name its files relative to it.
#include <gtest/gtest.h>

#include <filesystem>

#include "server/served_folder.h"

namespace shadetree {
namespace {

namespace fs = std::filesystem;

TEST(ServedFolder, MessagesNameItsFilesRelativeToIt) {
  const fs::path root = fs::temp_directory_path() / "shadetree_served_folder_test";
  fs::create_directories(root / "more");
  Result<ServedFolder> folder = ServedFolder::open(root.string());
  ASSERT_TRUE(folder) << folder.error().to_string();
  const std::string prefix = (folder->path() / "").string();
  EXPECT_EQ(folder->relative_text(prefix + "more/waves.json"), "more/waves.json");
  EXPECT_EQ(folder->relative_text("image \"" + prefix + "images/a.png\" (from " + prefix + "g.json)"),
            "image \"images/a.png\" (from g.json)");
  // Only where a path begins: the same letters inside another path stay.
  EXPECT_EQ(folder->relative_text("/elsewhere" + prefix + "x.json"), "/elsewhere" + prefix + "x.json");
  fs::remove_all(root);
}

// Regression: served from "/", every "/" of a message was taken out
// ("images/nope.png" became "imagesnope.png").
TEST(ServedFolder, ServedFromTheRootOnlyLeadingSlashesGo) {
  Result<ServedFolder> folder = ServedFolder::open("/");
  ASSERT_TRUE(folder) << folder.error().to_string();
  EXPECT_EQ(folder->relative_text("/srv/g.json: image \"images/nope.png\" is missing"),
            "srv/g.json: image \"images/nope.png\" is missing");
}

}  // namespace
}  // namespace shadetree

// Diagnostics (graph/diagnostic.h): one line, control characters escaped,
// and never longer than a person can read, whatever the input holds.
#include "graph/diagnostic.h"

#include <gtest/gtest.h>

namespace shadetree {
namespace {

TEST(Diagnostic, NamesTheFileNodeAndInput) {
  EXPECT_EQ((Diagnostic{ExitStatus::invalid_input, "m.json", "t2", "p", "expected vec3, got float"}).to_string(),
            "error: m.json: node \"t2\" input \"p\": expected vec3, got float");
}

TEST(Diagnostic, ControlCharactersAreEscaped) {
  EXPECT_EQ((Diagnostic{ExitStatus::invalid_input, "a\nb.json", "x\ty", {}, std::string("bell\x07\x1b[2J", 9)})
                .to_string(),
            "error: a\\nb.json: node \"x\\ty\": bell\\x07\\x1b[2J");
  EXPECT_EQ(printable("ok\r\n"), "ok\\r\\n");
}

// Issue 21: one error line quoted a 4 MB input whole.
TEST(Diagnostic, LongNamesAndMessagesAreShortened) {
  const std::string huge(4 << 20, 'n');
  const std::string line = Diagnostic{ExitStatus::invalid_input, "g.json", huge, {}, "unknown op \"" + huge + "\""}.to_string();
  EXPECT_LT(line.size(), 1100u);
  EXPECT_EQ(line.rfind("error: g.json: node \"" + std::string(200, 'n') + "... (4194104 more bytes)\": unknown op", 0), 0u)
      << line.substr(0, 300);
  EXPECT_NE(line.find("more bytes)"), std::string::npos);
}

}  // namespace
}  // namespace shadetree

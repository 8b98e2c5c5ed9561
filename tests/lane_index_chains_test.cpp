// Chained per-lane lookups index in general registers
// (jit/lane_index_chains.h), read from the kernel's optimized LLVM IR.

#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <sstream>
#include <string>

#include "jit/jit_compiler.h"
#include "support/gallery.h"

namespace shadetree {
namespace {

// Each value's defining instruction in a listing, by name.
std::map<std::string, std::string> definitions(const std::string& listing) {
  std::map<std::string, std::string> defined;
  const std::regex definition(R"(^  (%[\w.]+) = (.*)$)");
  std::istringstream lines(listing);
  for (std::string line; std::getline(lines, line);)
    if (std::smatch match; std::regex_match(line, match, definition)) defined[match[1]] = match[2];
  return defined;
}

// Cellular noise hashes a cell three times in a chain (Worley 1996:
// hash_y = phi(hash_x + 1), hash_z = phi(hash_y + 1)). With per-lane
// lookups at 8 lanes, each lane of the two later lookups is indexed from
// the value loaded for that lane, never from a lane moved out of the
// vector of the first lookup's results plus 1. Before the rewrite, 16
// lanes were moved out of such vectors.
TEST(LaneIndexChains, ChainedLookupsIndexEachLaneFromItsLoadedValue) {
  Result<LoadedGraph> loaded = testing::load_gallery_graph(SHADETREE_SOURCE_DIR "/graphs/cells.json");
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  JitSettings per_lane;
  per_lane.gathers = GatherStrategy::per_lane;
  Result<std::string> listing = kernel_listing(loaded->ir, 8, Listing::optimized_llvm_ir, per_lane);
  ASSERT_TRUE(listing.ok()) << listing.error().to_string();
  const std::map<std::string, std::string> defined = definitions(*listing);
  const auto defined_as = [&](const std::string& name, const std::string& start) {
    const auto found = defined.find(name);
    return found != defined.end() && found->second.starts_with(start);
  };

  int moved_out_of_chains = 0, indexed_from_loads = 0;
  const std::regex extract(R"(^extractelement <8 x i32> (%[\w.]+), i64 \d$)");
  const std::regex masked(R"(^and <8 x i32> (%[\w.]+), )");
  const std::regex plus_one_vector(R"(^add <8 x i32> (%[\w.]+), <i32 1, )");
  const std::regex plus_one_lane(R"(^add i32 (%[\w.]+), 1$)");
  for (const auto& [name, instruction] : defined) {
    std::smatch match;
    if (std::regex_match(instruction, match, plus_one_lane) && defined_as(match[1], "load i32, "))
      ++indexed_from_loads;
    if (!std::regex_match(instruction, match, extract)) continue;
    const std::string read = match[1];
    const auto mask = defined.find(read);
    if (mask == defined.end() || !std::regex_search(mask->second, match, masked)) continue;
    const auto sum = defined.find(match[1]);
    if (sum != defined.end() && std::regex_search(sum->second, match, plus_one_vector) &&
        defined_as(match[1], "insertelement "))
      ++moved_out_of_chains;
  }
  EXPECT_EQ(moved_out_of_chains, 0);
  EXPECT_EQ(indexed_from_loads, 16);
}

}  // namespace
}  // namespace shadetree

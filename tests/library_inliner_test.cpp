// The op library inlined into kernels (jit/library_inliner.h), read from
// the kernels' optimized LLVM IR.

#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "jit/jit_compiler.h"
#include "support/gallery.h"

namespace shadetree {
namespace {

// What a listing of one or more modules defines and calls: per defined
// function, whether it is noinline (an op compiled apart,
// codegen/emit_kernel.h); and every function called.
struct FunctionsListed {
  std::map<std::string, bool> defined_noinline;
  std::set<std::string> called;
};

FunctionsListed functions_listed(const std::string& listing) {
  FunctionsListed listed;
  const std::regex definition(R"(^define .*@([\w.]+)\(.*\)(?: .*#(\d+))? \{$)");
  const std::regex attributes(R"(^attributes #(\d+) = \{(.*)\}$)");
  const std::regex call(R"(call [^@]*@([\w.]+)\()");
  // A listing holds modules one after the other, each numbering its own
  // attribute groups: a definition's group is the next one listed.
  std::map<std::string, std::vector<std::string>> waiting;  // group -> functions
  std::istringstream lines(listing);
  for (std::string line; std::getline(lines, line);) {
    std::smatch match;
    if (std::regex_match(line, match, definition)) {
      if (match[2].matched)
        waiting[match[2]].push_back(match[1]);
      else
        listed.defined_noinline[match[1]] = false;
    } else if (std::regex_match(line, match, attributes)) {
      const auto functions = waiting.find(match[1]);
      if (functions == waiting.end()) continue;
      for (const std::string& function : functions->second)
        listed.defined_noinline[function] = match[2].str().find(" noinline ") != std::string::npos;
      waiting.erase(functions);
    } else if (std::regex_search(line, match, call)) {
      listed.called.insert(match[1]);
    }
  }
  return listed;
}

// Every call of a library function is inlined, the helpers those
// functions call too (a spline's knot lookups, noise's row lookups), and
// none of the library's functions is left in the module but the ops
// compiled apart: in both pipelines, in a kernel compiled whole (marble),
// split in two (tileable_stones) and with ops compiled apart (ocean's
// `sin` and `normalize`).
TEST(LibraryInliner, EveryLibraryCallIsInlinedAndTheInlinedFunctionsDropped) {
  for (const char* name : {"marble", "tileable_stones", "ocean"})
    for (Optimization optimization : {Optimization::full, Optimization::quick}) {
      SCOPED_TRACE(std::string(name) + (optimization == Optimization::full ? ", full" : ", quick"));
      Result<LoadedGraph> loaded =
          testing::load_gallery_graph(std::string(SHADETREE_SOURCE_DIR "/graphs/") + name + ".json");
      ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
      JitSettings settings;
      settings.optimization = optimization;
      Result<std::string> listing = kernel_listing(loaded->ir, 8, Listing::optimized_llvm_ir, settings);
      ASSERT_TRUE(listing.ok()) << listing.error().to_string();
      const FunctionsListed listed = functions_listed(*listing);
      int kernel_functions = 0, ops_apart = 0;
      for (const auto& [function, noinline] : listed.defined_noinline) {
        if (function.starts_with("shade_kernel")) {
          ++kernel_functions;
          continue;
        }
        EXPECT_TRUE(noinline) << function << " is a library function left in the module";
        ops_apart += noinline;
      }
      EXPECT_GE(kernel_functions, 2);  // bind and run, at least
      EXPECT_EQ(ops_apart, std::string(name) == "ocean" ? 2 : 0);
      for (const std::string& function : listed.called)
        if (function.starts_with("st_"))
          EXPECT_TRUE(listed.defined_noinline.contains(function)) << function << " is called but not inlined";
    }
}

}  // namespace
}  // namespace shadetree

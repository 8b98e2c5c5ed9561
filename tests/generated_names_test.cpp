// Names of a graph in generated code (graph/generated_names.h): identifiers
// that are never keywords, reserved names or macros, unique in a scope,
// and quoted text that no comment or string literal can be ended by.
#include "graph/generated_names.h"

#include <gtest/gtest.h>

namespace shadetree {
namespace {

TEST(CodeIdentifier, KeepsOrdinaryNames) {
  EXPECT_EQ(code_identifier("marble"), "marble");
  EXPECT_EQ(code_identifier("turbulence_amount"), "turbulence_amount");
  EXPECT_EQ(code_identifier("Scale2"), "Scale2");
}

TEST(CodeIdentifier, ReplacesOtherCharactersWithOneUnderscore) {
  EXPECT_EQ(code_identifier("my-graph v2"), "my_graph_v2");
  EXPECT_EQ(code_identifier("a\nstatic_assert(false);"), "a_static_assert_false");
  EXPECT_EQ(code_identifier("caf\xc3\xa9 au lait"), "caf_au_lait");
}

TEST(CodeIdentifier, NeverAReservedNameOrAMacro) {
  EXPECT_EQ(code_identifier("__LINE__"), "LINE_");
  EXPECT_EQ(code_identifier("_Pragma"), "Pragma");
  EXPECT_EQ(code_identifier("a__b"), "a_b");
  EXPECT_EQ(code_identifier("NULL"), "NULL_");
  EXPECT_EQ(code_identifier("M_PI"), "M_PI_");
  EXPECT_EQ(code_identifier("assert"), "assert_");
  EXPECT_EQ(code_identifier("gl_FragColor"), "gl_FragColor_");
}

TEST(CodeIdentifier, NeverAKeywordOfCppOrGlsl) {
  EXPECT_EQ(code_identifier("float"), "float_");
  EXPECT_EQ(code_identifier("static_assert"), "static_assert_");
  EXPECT_EQ(code_identifier("uniform"), "uniform_");
  EXPECT_EQ(code_identifier("vec3"), "vec3_");
}

TEST(CodeIdentifier, StartsWithALetter) {
  EXPECT_EQ(code_identifier("2d"), "n2d");
  EXPECT_EQ(code_identifier("#include <x>"), "include_x");
}

TEST(CodeIdentifier, EmptyOrPunctuationGivesTheFallback) {
  EXPECT_EQ(code_identifier(""), "unnamed");
  EXPECT_EQ(code_identifier("*/ ?\?/", "kernel"), "kernel");
}

TEST(CodeIdentifier, IsCutToTheMaximumLength) {
  EXPECT_EQ(code_identifier(std::string(5000, 'z')), std::string(max_identifier_length, 'z'));
  EXPECT_EQ(code_identifier(std::string(max_identifier_length - 1, 'z') + "-tail"),
            std::string(max_identifier_length - 1, 'z'));
}

TEST(IdentifierScope, NamesThatSanitizeAlikeStayApart) {
  IdentifierScope scope;
  EXPECT_EQ(scope.add("a-b"), "a_b");
  EXPECT_EQ(scope.add("a_b"), "a_b_2");
  EXPECT_EQ(scope.add("a b"), "a_b_3");
  EXPECT_EQ(scope.add("a_b_2"), "a_b_2_2");
}

TEST(IdentifierScope, ReservedIdentifiersAreNotGivenOut) {
  IdentifierScope scope;
  scope.reserve("params");
  EXPECT_EQ(scope.add("params"), "params_2");
}

TEST(QuotedText, EscapesQuotesBackslashesAndLineBreaks) {
  EXPECT_EQ(quoted_text("plain"), "\"plain\"");
  EXPECT_EQ(quoted_text("say \"hi\""), "\"say \\\"hi\\\"\"");
  EXPECT_EQ(quoted_text("ends in \\"), "\"ends in \\\\\"");
  EXPECT_EQ(quoted_text("a\nb\tc\rd"), "\"a\\nb\\tc\\015d\"");
}

TEST(QuotedText, NoCommentCanBeClosedAndNoTrigraphFormed) {
  EXPECT_EQ(quoted_text("*/ x /*"), "\"*\\057 x /*\"");
  EXPECT_EQ(quoted_text("?\?/"), "\"\\077?/\"");
  EXPECT_EQ(quoted_text("why?"), "\"why?\"");
}

TEST(QuotedText, OnlyPrintableAsciiRemains) {
  const std::string quoted = quoted_text("caf\xc3\xa9\x01\x7f");
  EXPECT_EQ(quoted, "\"caf\\303\\251\\001\\177\"");
  for (char c : quoted) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << static_cast<int>(c);
}

TEST(QuotedText, LongTextIsCut) {
  EXPECT_EQ(quoted_text(std::string(300, 'x'), 4), "\"xxxx\"...");
}

}  // namespace
}  // namespace shadetree

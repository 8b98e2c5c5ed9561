// Names and text of a graph that reach generated source code (emit --cpp,
// and every later emitter): the one place they pass through, so that no
// node id, param name, doc or file name a graph supplies is ever live code.
// Identifiers are sanitized and made unique; other user text appears only
// as a quoted, escaped string inside a comment, which it cannot end.
#pragma once

#include <set>
#include <string>

namespace shadetree {

// An identifier made of `text` that is valid in C, C++ and GLSL and is
// none of their keywords, reserved names or common macros: other
// characters become '_', runs of '_' collapse to one, leading '_' are
// dropped (names starting with '_' or holding "__" are reserved, and
// __LINE__ is a macro), a leading digit gets an 'n' before it, and a
// keyword, an all-capitals name (a macro's, as NULL or M_PI) or a
// "gl_" name (GLSL's) gets a '_' after it; it is cut to
// max_identifier_length. Empty text gives `fallback`.
inline constexpr std::size_t max_identifier_length = 64;
std::string code_identifier(const std::string& text, const std::string& fallback = "unnamed");

// Identifiers unique within one scope (a struct's fields, a namespace's
// functions): a name already taken gets _2, _3... after it.
class IdentifierScope {
 public:
  // `text` as an identifier of this scope, unique in it.
  std::string add(const std::string& text);
  // Takes `identifier` (one the generator chose) without renaming it.
  void reserve(const std::string& identifier) { taken_.insert(identifier); }

 private:
  std::set<std::string> taken_;
};

// `text` as a double-quoted string of printable ASCII, safe inside a //
// or /* */ comment of C, C++ and GLSL and inside a C or C++ string
// literal: quotes, backslashes, the '/' of "*/", a '?' before another,
// control characters and bytes above 126 are escaped (\", \\, \n, \t,
// octal \NNN), and text longer than `limit` bytes is cut with "..."
// after the closing quote.
std::string quoted_text(const std::string& text, std::size_t limit = 200);

}  // namespace shadetree

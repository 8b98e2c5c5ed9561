#include "graph/generated_names.h"

#include <cctype>

namespace shadetree {
namespace {

// Keywords of C++20 and GLSL ES 3.00 (with its reserved words), and
// lower-case macros of the C and C++ standard libraries.
const std::set<std::string>& reserved_words() {
  static const std::set<std::string> words = {
      // C++
      "alignas", "alignof", "and", "and_eq", "asm", "auto", "bitand", "bitor", "bool", "break", "case", "catch",
      "char", "char8_t", "char16_t", "char32_t", "class", "co_await", "co_return", "co_yield", "compl", "concept",
      "const", "const_cast", "consteval", "constexpr", "constinit", "continue", "decltype", "default", "delete",
      "do", "double", "dynamic_cast", "else", "enum", "explicit", "export", "extern", "false", "float", "for",
      "friend", "goto", "if", "inline", "int", "long", "mutable", "namespace", "new", "noexcept", "not", "not_eq",
      "nullptr", "operator", "or", "or_eq", "private", "protected", "public", "register", "reinterpret_cast",
      "requires", "return", "short", "signed", "sizeof", "static", "static_assert", "static_cast", "struct",
      "switch", "template", "this", "thread_local", "throw", "true", "try", "typedef", "typeid", "typename",
      "union", "unsigned", "using", "virtual", "void", "volatile", "wchar_t", "while", "xor", "xor_eq",
      // C library macros in lower case
      "assert", "errno", "offsetof", "setjmp", "va_arg", "va_start", "va_end", "va_copy", "stdin", "stdout",
      "stderr", "math_errhandling",
      // GLSL ES 3.00 keywords and reserved words not above
      "attribute", "varying", "uniform", "buffer", "shared", "coherent", "restrict", "readonly", "writeonly",
      "layout", "centroid", "flat", "smooth", "noperspective", "patch", "sample", "subroutine", "in", "out",
      "inout", "invariant", "precise", "discard", "lowp", "mediump", "highp", "precision", "sampler2D",
      "sampler3D", "samplerCube", "vec2", "vec3", "vec4", "ivec2", "ivec3", "ivec4", "bvec2", "bvec3", "bvec4",
      "uvec2", "uvec3", "uvec4", "mat2", "mat3", "mat4", "uint", "half", "fixed", "input", "output", "filter",
      "common", "partition", "active", "superp", "external", "interface", "resource", "iimage2D", "image2D",
      "main", "mainImage", "texture", "radians", "degrees", "sin", "cos", "tan", "pow", "exp", "log", "sqrt",
      "abs", "sign", "floor", "ceil", "fract", "mod", "min", "max", "clamp", "mix", "step", "smoothstep",
      "length", "distance", "dot", "cross", "normalize", "reflect", "refract"};
  return words;
}

bool all_capitals(const std::string& identifier) {
  bool letter = false;
  for (char c : identifier) {
    if (std::islower(static_cast<unsigned char>(c))) return false;
    letter = letter || std::isupper(static_cast<unsigned char>(c));
  }
  return letter;
}

}  // namespace

std::string code_identifier(const std::string& text, const std::string& fallback) {
  std::string result;
  for (char c : text) {
    const bool kept = c != '_' && std::isalnum(static_cast<unsigned char>(c)) && static_cast<unsigned char>(c) < 128;
    if (kept) result += c;
    else if (!result.empty() && result.back() != '_') result += '_';
  }
  if (result.size() > max_identifier_length) result.resize(max_identifier_length);
  while (!result.empty() && result.back() == '_') result.pop_back();
  if (result.empty()) return fallback;
  if (std::isdigit(static_cast<unsigned char>(result[0]))) result = "n" + result;
  if (reserved_words().count(result) || all_capitals(result) || result.rfind("gl_", 0) == 0) result += "_";
  return result;
}

std::string IdentifierScope::add(const std::string& text) {
  const std::string base = code_identifier(text);
  std::string identifier = base;
  for (int suffix = 2; taken_.count(identifier); ++suffix) identifier = base + "_" + std::to_string(suffix);
  taken_.insert(identifier);
  return identifier;
}

std::string quoted_text(const std::string& text, std::size_t limit) {
  std::string result = "\"";
  const std::size_t shown = text.size() > limit ? limit : text.size();
  for (std::size_t i = 0; i < shown; ++i) {
    const char c = text[i];
    const auto byte = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      result += '\\';
      result += c;
    } else if (c == '\n') {
      result += "\\n";
    } else if (c == '\t') {
      result += "\\t";
    } else if (byte < 0x20 || byte >= 0x7f || (c == '/' && i > 0 && text[i - 1] == '*') ||
               (c == '?' && i + 1 < shown && text[i + 1] == '?')) {
      // Octal, whose three digits end the escape (a hex one runs on), and
      // "??" too: a trigraph ("??/" was a backslash before C++17) must not form.
      result += '\\';
      result += static_cast<char>('0' + (byte >> 6));
      result += static_cast<char>('0' + ((byte >> 3) & 7));
      result += static_cast<char>('0' + (byte & 7));
    } else {
      result += c;
    }
  }
  result += '"';
  if (shown < text.size()) result += "...";
  return result;
}

}  // namespace shadetree

// Build tool: writes the C++ source of the op library that `emit --cpp`
// puts in front of every kernel: the node headers reachable from the
// roots, each after the headers it includes, with their own #include and
// #pragma once lines taken out and the standard headers they include
// gathered, so that the library can sit in a namespace of its own. Only
// the semantics are kept: nodes/op_definition.h is not followed, and the
// registry's half of each op (definition(), lay_out() of its attributes
// and their helpers: the functions returning an OpDef, an AttributeSpec or
// the names an attribute takes, or taking Attributes) and `using namespace define;` are taken out, so
// that what remains is C++17 with no dependency on the registry. The
// interval forms (the headers named *interval*, each op's
// evaluate_interval) are left out too: emitted kernels run on floats.
//
//   embed_library_source SOURCE_ROOT OUTPUT.cpp ROOT_HEADER...
#include <algorithm>
#include <fstream>
#include <iostream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Library {
  std::string root;
  std::set<std::string> visited;
  std::set<std::string> system_includes;
  std::vector<std::string> conditional_includes;  // each wrapped in the #if lines around it
  std::string body;

  void add(const std::string& header) {
    if (!visited.insert(header).second) return;
    std::ifstream file(root + "/" + header);
    if (!file) throw std::runtime_error("cannot read " + root + "/" + header);
    static const std::regex local(R"re(^\s*#include\s+"([^"]+)")re"), system(R"re(^\s*#include\s+<([^>]+)>)re"),
        once(R"re(^\s*#pragma\s+once)re"), definition(
            R"re(^\s*(static |inline )?((OpDef|AttributeSpec|std::vector<std::string>) \w+\(|void \w+\(const Attributes&|void evaluate_interval\())re"),
        using_define(R"re(^\s*using namespace define;)re"), opening(R"re(^\s*#\s*if)re"),
        alternative(R"re(^\s*#\s*(else|elif))re"), closing(R"re(^\s*#\s*endif)re");
    std::string text, line;
    std::smatch match;
    std::vector<std::string> conditions;  // the #if lines the current line is in
    while (std::getline(file, line)) {
      if (std::regex_search(line, opening)) conditions.push_back(line);
      else if (std::regex_search(line, closing) && !conditions.empty()) conditions.pop_back();
      else if (std::regex_search(line, alternative) && !conditions.empty()) conditions.back() = "#else";
      if (std::regex_search(line, definition)) {
        skip_function(file, line);
      } else if (std::regex_search(line, match, local)) {
        const std::string included = match[1];
        if (included != "nodes/op_definition.h" && included.find("interval") == std::string::npos) add(included);
      } else if (std::regex_search(line, using_define)) {
        continue;
      } else if (std::regex_search(line, match, system)) {
        if (conditions.empty()) {
          system_includes.insert(match[1]);
          continue;
        }
        // A standard header under a condition keeps it, out of the namespace.
        std::string wrapped;
        for (const std::string& condition : conditions) {
          if (condition == "#else") throw std::runtime_error(header + ": an #include under #else or #elif");
          wrapped += condition + "\n";
        }
        wrapped += line + "\n";
        for (std::size_t i = 0; i < conditions.size(); ++i) wrapped += "#endif\n";
        if (std::find(conditional_includes.begin(), conditional_includes.end(), wrapped) == conditional_includes.end())
          conditional_includes.push_back(wrapped);
      } else if (!std::regex_search(line, once)) {
        text += line + "\n";
      }
    }
    body += "// ---- " + header + "\n" + text;
  }

  // Skips the function that starts on `line`, through the line on which
  // its braces close (braces in string literals do not count).
  static void skip_function(std::istream& file, std::string line) {
    int depth = 0;
    bool opened = false;
    for (;;) {
      bool quoted = false;
      for (std::size_t i = 0; i < line.size(); ++i) {
        if (line[i] == '\\' && quoted) ++i;
        else if (line[i] == '"') quoted = !quoted;
        else if (!quoted && line[i] == '{') depth += 1, opened = true;
        else if (!quoted && line[i] == '}') depth -= 1;
      }
      if (opened && depth <= 0) return;
      if (!std::getline(file, line)) return;
    }
  }
};

// A raw string literal of `text`, in pieces (compilers cap one literal's length).
std::string literal(const std::string& text) {
  std::string result;
  for (std::size_t at = 0; at < text.size(); at += 8000)
    result += "R\"shadetree_source(" + text.substr(at, 8000) + ")shadetree_source\"\n";
  return result.empty() ? "\"\"" : result;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::cerr << "usage: embed_library_source SOURCE_ROOT OUTPUT.cpp ROOT_HEADER...\n";
    return 2;
  }
  try {
    Library library{argv[1], {}, {}, {}};
    for (int i = 3; i < argc; ++i) library.add(argv[i]);
    std::string includes;
    for (const std::string& header : library.system_includes) includes += "#include <" + header + ">\n";
    for (const std::string& wrapped : library.conditional_includes) includes += wrapped;
    std::ostringstream out;
    out << "// Generated by cppgen/embed_library_source.cpp at build time.\n"
        << "#include \"cppgen/library_source.h\"\n\nnamespace shadetree {\n\n"
        << "std::string_view library_includes() {\n  static const char text[] =\n"
        << literal(includes) << ";\n  return {text, sizeof text - 1};\n}\n\n"
        << "std::string_view library_source() {\n  static const char text[] =\n"
        << literal(library.body) << ";\n  return {text, sizeof text - 1};\n}\n\n}  // namespace shadetree\n";
    std::ofstream(argv[2]) << out.str();
  } catch (const std::exception& error) {
    std::cerr << "embed_library_source: " << error.what() << "\n";
    return 1;
  }
  return 0;
}

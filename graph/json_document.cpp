#include "graph/json_document.h"

#include <unordered_set>
#include <vector>

namespace shadetree {
namespace {

// nlohmann's SAX events, built into a document. Each open object keeps a
// hash set of its keys; members are appended to the object's storage
// (ordered_map is a vector of pairs) without ordered_map's linear search.
class DocumentBuilder {
 public:
  using number_integer_t = json::number_integer_t;
  using number_unsigned_t = json::number_unsigned_t;
  using number_float_t = json::number_float_t;
  using string_t = json::string_t;
  using binary_t = json::binary_t;

  bool null() { return add(json(nullptr)); }
  bool boolean(bool value) { return add(json(value)); }
  bool number_integer(number_integer_t value) { return add(json(value)); }
  bool number_unsigned(number_unsigned_t value) { return add(json(value)); }
  bool number_float(number_float_t value, const string_t&) { return add(json(value)); }
  bool string(string_t& value) { return add(json(std::move(value))); }
  bool binary(binary_t& value) { return add(json::binary(std::move(value))); }

  bool start_object(std::size_t) { return open(json::object()); }
  bool key(string_t& key) {
    Open& object = open_.back();
    if (!object.keys.insert(key).second) {
      problem_ = "key \"" + key + "\" appears twice in one object";
      return false;
    }
    object.key = std::move(key);
    return true;
  }
  bool end_object() { return close(); }
  bool start_array(std::size_t) { return open(json::array()); }
  bool end_array() { return close(); }

  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& error) {
    // "[json.exception.parse_error.101] parse error at line 1, column 2: ..."
    std::string reason = error.what();
    const auto start = reason.find("] ");
    if (start != std::string::npos) reason = reason.substr(start + 2);
    problem_ = "invalid JSON: " + reason;
    return false;
  }

  json& document() { return document_; }
  const std::string& problem() const { return problem_; }

 private:
  struct Open {
    json value;
    std::unordered_set<std::string> keys;  // objects only
    std::string key;                       // the member being read
  };

  bool open(json value) {
    if (static_cast<int>(open_.size()) >= max_json_depth) {
      problem_ = "JSON nested deeper than " + std::to_string(max_json_depth) + " levels";
      return false;
    }
    open_.push_back(Open{std::move(value), {}, {}});
    return true;
  }

  bool close() {
    json value = std::move(open_.back().value);
    open_.pop_back();
    return add(std::move(value));
  }

  bool add(json value) {
    if (open_.empty()) {
      document_ = std::move(value);
      return true;
    }
    Open& parent = open_.back();
    if (parent.value.is_array()) {
      parent.value.get_ref<json::array_t&>().push_back(std::move(value));
    } else {
      using Members = json::object_t::Container;
      static_cast<Members&>(parent.value.get_ref<json::object_t&>()).emplace_back(std::move(parent.key), std::move(value));
    }
    return true;
  }

  std::vector<Open> open_;
  json document_;
  std::string problem_;
};

}  // namespace

Result<json> parse_json_document(const std::string& text, const std::string& file) {
  DocumentBuilder builder;
  bool parsed = false;
  try {
    parsed = json::sax_parse(text, &builder);
  } catch (const json::exception& error) {
    return Diagnostic{ExitStatus::invalid_input, file, {}, {}, std::string("invalid JSON: ") + error.what()};
  }
  if (!parsed) return Diagnostic{ExitStatus::invalid_input, file, {}, {}, builder.problem()};
  return std::move(builder.document());
}

}  // namespace shadetree

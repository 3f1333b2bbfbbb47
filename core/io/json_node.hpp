// Validating access to a parsed JSON document: every accessor knows its JSON path and throws a
// DataError naming the file and that path ("faces[3].loop[2]: expected an integer").
#pragma once

#include <functional>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/base/data_error.hpp"
#include "core/math/vec.hpp"

namespace pl {

class JsonNode {
 public:
  JsonNode(const nlohmann::json& value, const std::string& source, std::string path = "")
      : value_(&value), source_(&source), path_(std::move(path)) {}

  const std::string& path() const { return path_; }
  const nlohmann::json& raw() const { return *value_; }
  [[noreturn]] void fail(const std::string& message) const;

  bool is_null() const { return value_->is_null(); }
  // Objects
  void require_object() const;
  JsonNode at(const std::string& key) const;  // required key
  std::optional<JsonNode> find(const std::string& key) const;
  void allow_only(std::initializer_list<const char*> keys) const;  // rejects unknown keys
  // Arrays
  std::vector<JsonNode> items() const;
  std::vector<JsonNode> items(std::size_t exact_length) const;
  std::size_t size() const;  // the length of the array (without a node per item)
  // Scalars
  double number() const;  // finite
  long long integer() const;
  int integer_in(long long lo, long long hi) const;
  std::string string() const;
  Vec3 point() const;  // [x, y, z], each |x| <= kMaxCoordinate (core/io/input_limits.hpp)
  std::vector<Vec3> points() const;

 private:
  std::string child_path(const std::string& key) const;
  std::string child_path(std::size_t index) const;

  const nlohmann::json* value_;
  const std::string* source_;
  std::string path_;
};

// Parses text as JSON; a syntax error is a DataError naming line and column. Also refused, with
// the JSON path: a key given twice in one object (JSON leaves the meaning open; a reader that
// keeps the last one silently drops data) and nesting deeper than kMaxJsonDepth.
nlohmann::json parse_json(const std::string& text, const std::string& source);
// The same, handing each item of the array under `key` of the top-level object to `read` (with
// its index) as soon as the item is parsed; the item is then dropped, and the array stays empty
// in the document. A scene's curves are so read one by one: 400,000 of them held as one JSON tree
// took half a gigabyte (a map per object, an allocation per array), then freed again.
// When `packed_key` is set, that key of an item, when it holds an array of [x, y, z] numbers
// within the coordinate bound (a curve's "points"), is not built as JSON: its points are handed to
// `read` as `packed` and the key holds null in the item. Anything else under it (an error the
// reader reports with its path) is built as usual, with `packed` null. One curve of 400,000
// points held as JSON took 50 MB, an allocation or two per point.
struct StreamedArray {
  std::string key;
  std::function<void(const nlohmann::json& item, std::size_t index, std::vector<Vec3>* packed)>
      read;
  std::string packed_key;
};
nlohmann::json parse_json(const std::string& text, const std::string& source,
                          const StreamedArray& streamed);
inline constexpr int kMaxJsonDepth = 64;

// s with control characters (a JSON key may hold "\u0000") written as \uXXXX, so that a message
// quoting user text is printed whole, on one line.
std::string printable(std::string_view s);
// x with 3 significant digits ("1.5e-154"), for messages.
std::string short_number(double x);

}  // namespace pl

#include "core/io/json_node.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "core/io/input_limits.hpp"

namespace pl {

namespace {
const char* type_name(const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::null:
      return "null";
    case nlohmann::json::value_t::object:
      return "an object";
    case nlohmann::json::value_t::array:
      return "an array";
    case nlohmann::json::value_t::string:
      return "a string";
    case nlohmann::json::value_t::boolean:
      return "a boolean";
    default:
      return "a number";
  }
}
}  // namespace

std::string short_number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

std::string printable(std::string_view s) {
  std::string r;
  r.reserve(s.size());
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", u);
      r += buf;
    } else {
      r += c;
    }
  }
  return r;
}

void JsonNode::fail(const std::string& message) const {
  throw DataError(*source_, path_.empty() ? "(top level)" : path_, printable(message));
}

std::string JsonNode::child_path(const std::string& key) const {
  return path_.empty() ? printable(key) : path_ + "." + printable(key);
}
std::string JsonNode::child_path(std::size_t index) const {
  return path_ + "[" + std::to_string(index) + "]";
}

void JsonNode::require_object() const {
  if (!value_->is_object()) fail(std::string("expected an object, got ") + type_name(*value_));
}

JsonNode JsonNode::at(const std::string& key) const {
  require_object();
  auto it = value_->find(key);
  if (it == value_->end()) fail("missing required key \"" + key + "\"");
  return JsonNode(*it, *source_, child_path(key));
}

std::optional<JsonNode> JsonNode::find(const std::string& key) const {
  require_object();
  auto it = value_->find(key);
  if (it == value_->end()) return std::nullopt;
  return JsonNode(*it, *source_, child_path(key));
}

void JsonNode::allow_only(std::initializer_list<const char*> keys) const {
  require_object();
  for (auto it = value_->begin(); it != value_->end(); ++it) {
    const bool known =
        std::any_of(keys.begin(), keys.end(), [&](const char* k) { return it.key() == k; });
    if (!known) {
      std::string list;
      for (const char* k : keys) list += std::string(list.empty() ? "" : ", ") + k;
      JsonNode(*it, *source_, child_path(it.key())).fail("unknown key (allowed: " + list + ")");
    }
  }
}

std::vector<JsonNode> JsonNode::items() const {
  if (!value_->is_array()) fail(std::string("expected an array, got ") + type_name(*value_));
  std::vector<JsonNode> r;
  r.reserve(value_->size());
  for (std::size_t i = 0; i < value_->size(); ++i)
    r.emplace_back((*value_)[i], *source_, child_path(i));
  return r;
}

std::vector<JsonNode> JsonNode::items(std::size_t n) const {
  auto r = items();
  if (r.size() != n)
    fail("expected an array of length " + std::to_string(n) + ", got length " +
         std::to_string(r.size()));
  return r;
}

double JsonNode::number() const {
  if (!value_->is_number()) fail(std::string("expected a number, got ") + type_name(*value_));
  const double d = value_->get<double>();
  if (!std::isfinite(d)) fail("number is not finite");
  return d;
}

long long JsonNode::integer() const {
  if (value_->is_number_unsigned() && value_->get<unsigned long long>() > 9000000000000000000ull)
    fail("integer " + value_->dump() + " is out of range");
  if (value_->is_number_integer()) return value_->get<long long>();
  if (value_->is_number_float()) {
    const double d = value_->get<double>();
    if (std::isfinite(d) && d == std::floor(d) && std::fabs(d) < 9e15)
      return static_cast<long long>(d);
  }
  fail(std::string("expected an integer, got ") +
       (value_->is_number() ? "a fractional number" : type_name(*value_)));
}

int JsonNode::integer_in(long long lo, long long hi) const {
  const long long v = integer();
  if (v < lo || v > hi)
    fail("value " + std::to_string(v) + " is out of range [" + std::to_string(lo) + ", " +
         std::to_string(hi) + "]");
  return static_cast<int>(v);
}

std::string JsonNode::string() const {
  if (!value_->is_string()) fail(std::string("expected a string, got ") + type_name(*value_));
  return value_->get<std::string>();
}

Vec3 JsonNode::point() const {
  const auto c = items(3);
  Vec3 p;
  for (int k = 0; k < 3; ++k) {
    p[k] = c[k].number();
    if (std::fabs(p[k]) > kMaxCoordinate)
      c[k].fail("coordinate " + c[k].raw().dump() + " is out of range: |x| <= " +
                short_number(kMaxCoordinate) + " keeps squared lengths finite");
  }
  return p;
}

std::vector<Vec3> JsonNode::points() const {
  std::vector<Vec3> r;
  for (const JsonNode& p : items()) r.push_back(p.point());
  return r;
}

namespace {
// Follows the parser's events so that an error raised inside the parser (a number that overflows
// to infinity, say) can still be reported with the JSON path of the value being read.
class PathTracker {
 public:
  explicit PathTracker(const std::string& source) : source_(source) {}
  bool on_event(int, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
    using E = nlohmann::json::parse_event_t;
    switch (event) {
      case E::object_start:
      case E::array_start:
        frames_.push_back({event == E::array_start, 0, "", {}});
        if (frames_.size() > std::size_t(kMaxJsonDepth))
          throw DataError(source_, path(),
                          "nesting deeper than " + std::to_string(kMaxJsonDepth) + " levels");
        break;
      case E::key:
        frames_.back().key = parsed.get<std::string>();
        if (!frames_.back().seen.insert(frames_.back().key).second)
          throw DataError(source_, path(), "duplicate key (a key may appear once in an object)");
        break;
      case E::object_end:
      case E::array_end:
        frames_.pop_back();
        advance();
        break;
      case E::value:
        advance();
        break;
    }
    return true;
  }
  std::string path() const {
    std::string p;
    for (const Frame& f : frames_) {
      if (f.array)
        p += "[" + std::to_string(f.index) + "]";
      else if (!f.key.empty())
        p += (p.empty() ? "" : ".") + printable(f.key);
    }
    return p;
  }

 private:
  struct Frame {
    bool array;
    std::size_t index;
    std::string key;
    std::set<std::string> seen;  // keys of an object so far
  };
  void advance() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
  }
  const std::string& source_;
  std::vector<Frame> frames_;
};
}  // namespace

nlohmann::json parse_json(const std::string& text, const std::string& source) {
  PathTracker tracker(source);
  try {
    return nlohmann::json::parse(
        text, [&](int depth, nlohmann::json::parse_event_t e, nlohmann::json& j) {
          return tracker.on_event(depth, e, j);
        });
  } catch (const nlohmann::json::parse_error& e) {
    // Translate the byte offset into line and column for the message.
    const std::size_t byte = std::min<std::size_t>(e.byte, text.size());
    std::size_t line = 1, col = 1;
    for (std::size_t i = 0; i + 1 < byte; ++i) {
      if (text[i] == '\n')
        ++line, col = 1;
      else
        ++col;
    }
    std::string why = e.what();
    const auto pos = why.find("syntax error");
    if (pos != std::string::npos) why = why.substr(pos);
    throw DataError(source, "line " + std::to_string(line) + ", column " + std::to_string(col),
                    "invalid JSON: " + printable(why));
  } catch (const nlohmann::json::exception& e) {
    std::string why = e.what();
    const auto pos = why.find("] ");
    if (pos != std::string::npos) why = why.substr(pos + 2);
    const std::string path = tracker.path();
    throw DataError(source, path.empty() ? "(top level)" : path, "invalid JSON: " + printable(why));
  }
}

}  // namespace pl

#include "core/io/json_node.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

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
  size();  // an array
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
    // Digits beyond 64 bits reach here as a double (18446744073709551617 is 1.8e19), as do
    // integers written with an exponent: too large, whatever their fraction.
    if (!(std::fabs(d) < 9e15))
      fail("integer " + short_number(d) + " is out of range (an integer here is below 9e15)");
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

namespace {
// The point of [x, y, z] when all three are numbers within the coordinate bound (checked in place,
// without a node and a JSON path per coordinate: a scene of 400,000 points reads 1.2 million).
std::optional<Vec3> plain_point(const nlohmann::json& j) {
  if (!j.is_array() || j.size() != 3) return std::nullopt;
  Vec3 p;
  for (int k = 0; k < 3; ++k) {
    const nlohmann::json& x = j[k];
    if (!x.is_number()) return std::nullopt;
    p[k] = x.get<double>();
    if (!(std::fabs(p[k]) <= kMaxCoordinate)) return std::nullopt;  // NaN too
  }
  return p;
}
}  // namespace

Vec3 JsonNode::point() const {
  if (const auto p = plain_point(*value_)) return *p;
  // Otherwise the checks one by one, for the message naming the offending entry.
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

std::size_t JsonNode::size() const {
  if (!value_->is_array()) fail(std::string("expected an array, got ") + type_name(*value_));
  return value_->size();
}

std::vector<Vec3> JsonNode::points() const {
  std::vector<Vec3> r;
  r.reserve(size());
  for (std::size_t i = 0; i < value_->size(); ++i) {
    const nlohmann::json& item = (*value_)[i];
    if (const auto p = plain_point(item))
      r.push_back(*p);
    else
      r.push_back(JsonNode(item, *source_, child_path(i)).point());  // fails, naming the item
  }
  return r;
}

namespace {
// Builds the document from the parser's events (as nlohmann's own DOM builder does) and knows the
// JSON path of the value being read, so that an error raised inside the parser (a number that
// overflows to infinity, say), a duplicate key or too deep a nesting is reported with it.
// nlohmann's callback parser, used before, searched the whole parent container for a discarded
// value at the end of every object: quadratic in the length of an array of objects (40,000 curves
// took seconds to read).
class TrackingBuilder {
 public:
  using json = nlohmann::json;
  TrackingBuilder(json& root, const std::string& source, const StreamedArray* streamed)
      : root_(root), source_(source), streamed_(streamed) {}

  bool null() { return unpacked().value(nullptr); }
  bool boolean(bool v) { return unpacked().value(v); }
  bool number_integer(json::number_integer_t v) { return number(v); }
  bool number_unsigned(json::number_unsigned_t v) { return number(v); }
  bool number_float(json::number_float_t v, const json::string_t&) { return number(v); }
  bool string(json::string_t& v) { return unpacked().value(std::move(v)); }
  bool binary(json::binary_t& v) { return unpacked().value(std::move(v)); }
  bool start_object(std::size_t) { return unpacked().open(json::value_t::object, false); }
  bool start_array(std::size_t) {
    if (pack_.on && !pack_.in_item) {  // a point begins
      pack_.in_item = true;
      pack_.count = 0;
      frames_.push_back({true, 0, ""});
      return true;
    }
    if (!pack_.on && packs_here()) {  // the packed array begins; its slot holds null meanwhile
      pack_.on = true;
      pack_.slot = place(json(nullptr));
      frames_.push_back({true, 0, ""});
      return true;
    }
    return unpacked().open(json::value_t::array, true);
  }
  bool end_array() {
    if (pack_.on && pack_.in_item && pack_.count == 3) {
      pack_.points.emplace_back(pack_.xyz[0], pack_.xyz[1], pack_.xyz[2]);
      pack_.in_item = false;
      frames_.pop_back();
      advance();
      return true;
    }
    if (pack_.on && !pack_.in_item) {  // the packed array ends: its slot stays null
      pack_.on = false;
      pack_.done = true;
      frames_.pop_back();
      advance();
      return true;
    }
    return unpacked().close();
  }
  bool key(json::string_t& k) {
    unpacked();
    json& object = *open_.back();
    if (object.contains(k)) {
      frames_.back().key = k;
      throw DataError(source_, path(), "duplicate key (a key may appear once in an object)");
    }
    frames_.back().key = k;
    slot_ = &object[k];
    return true;
  }
  bool end_object() { return unpacked().close(); }
  bool parse_error(std::size_t byte, const std::string&, const json::exception& e) {
    if (dynamic_cast<const json::parse_error*>(&e)) {
      syntax_byte_ = byte;
      syntax_what_ = e.what();
      return false;
    }
    std::string why = e.what();
    const auto pos = why.find("] ");
    if (pos != std::string::npos) why = why.substr(pos + 2);
    const std::string p = path();
    throw DataError(source_, p.empty() ? "(top level)" : p, "invalid JSON: " + printable(why));
  }

  // Set when the parser stopped at a syntax error: its byte offset and nlohmann's message.
  std::optional<std::size_t> syntax_byte_;
  std::string syntax_what_;

 private:
  struct Frame {
    bool array;
    std::size_t index;
    std::string key;
  };
  // A packed array being read: its points so far, and the coordinates of the point being read.
  struct Packing {
    bool on = false, in_item = false;
    bool done = false;  // the current streamed item's array was packed whole
    int count = 0;
    double xyz[3] = {0, 0, 0};
    std::vector<Vec3> points;
    json* slot = nullptr;
  };
  // At the start of an array: is it the packed key of a streamed item?
  bool packs_here() const {
    return streamed_ && !streamed_->packed_key.empty() && frames_.size() == 3 &&
           !frames_[0].array && frames_[0].key == streamed_->key && frames_[1].array &&
           !frames_[2].array && frames_[2].key == streamed_->packed_key;
  }
  template <class N>
  bool number(N v) {
    const double d = static_cast<double>(v);
    if (pack_.on && pack_.in_item && pack_.count < 3 && std::fabs(d) <= kMaxCoordinate) {
      pack_.xyz[pack_.count++] = d;
      advance();
      return true;
    }
    return unpacked().value(v);
  }
  // Leaves packing for an event that does not fit a point: the points so far (and the open
  // point's coordinates) become JSON, and the event is built as usual, so the reader sees the
  // array as written and reports the offending entry with its path.
  TrackingBuilder& unpacked() {
    if (!pack_.on) return *this;
    pack_.on = false;
    json array = json::array();
    array.get_ptr<json::array_t*>()->reserve(pack_.points.size());
    for (const Vec3& p : pack_.points) array.push_back({p.x, p.y, p.z});
    *pack_.slot = std::move(array);
    open_.push_back(pack_.slot);
    pack_.points.clear();
    if (pack_.in_item) {
      pack_.in_item = false;
      const Frame item = frames_.back();  // the open point: reopened as JSON with its frame
      frames_.pop_back();
      open(json::value_t::array, true);
      for (int k = 0; k < pack_.count; ++k) open_.back()->push_back(pack_.xyz[k]);
      frames_.back() = item;
    }
    return *this;
  }
  // The place of the next value: the root, the end of the open array, or the slot of its key.
  json* place(json&& v) {
    if (open_.empty()) {
      root_ = std::move(v);
      return &root_;
    }
    if (open_.back()->is_array()) {
      open_.back()->push_back(std::move(v));
      return &open_.back()->back();
    }
    *slot_ = std::move(v);
    return slot_;
  }
  template <class V>
  bool value(V&& v) {
    place(json(std::forward<V>(v)));
    hand_over();
    advance();
    return true;
  }
  // An item just completed in the streamed array goes to its reader and out of the document.
  void hand_over() {
    if (!streamed_ || frames_.size() != 2 || frames_[0].array || !frames_[1].array ||
        frames_[0].key != streamed_->key)
      return;
    auto& items = *open_.back()->get_ptr<json::array_t*>();
    streamed_->read(items.back(), frames_[1].index, pack_.done ? &pack_.points : nullptr);
    items.pop_back();
    pack_.done = false;
    pack_.points.clear();
  }
  bool open(json::value_t type, bool array) {
    open_.push_back(place(json(type)));
    // Room for a point [x, y, z] at once: grown one item at a time, it was allocated three times
    // (capacity 1, 2, 4), and a scene of 400,000 curves holds 1.6 million such arrays.
    if (array) open_.back()->get_ptr<json::array_t*>()->reserve(4);
    frames_.push_back({array, 0, ""});
    if (frames_.size() > std::size_t(kMaxJsonDepth))
      throw DataError(source_, path(),
                      "nesting deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    return true;
  }
  bool close() {
    open_.pop_back();
    frames_.pop_back();
    hand_over();
    advance();
    return true;
  }
  void advance() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
  }
  std::string path() const {
    std::string p;
    // Built by appends: GCC 12 reports a false -Wrestrict for "literal" + std::string at -O3.
    for (const Frame& f : frames_) {
      if (f.array) {
        p += '[';
        p += std::to_string(f.index);
        p += ']';
      } else if (!f.key.empty()) {
        if (!p.empty()) p += '.';
        p += printable(f.key);
      }
    }
    return p;
  }

  json& root_;
  const std::string& source_;
  std::vector<json*> open_;  // the containers being filled, innermost last
  std::vector<Frame> frames_;
  json* slot_ = nullptr;
  const StreamedArray* streamed_;
  Packing pack_;
};
}  // namespace

namespace {
// "line L, column C" of a byte offset, as the messages of every syntax error give it.
std::string line_and_column(const std::string& text, std::size_t byte) {
  std::size_t line = 1, col = 1;
  for (std::size_t i = 0; i + 1 < byte && i < text.size(); ++i) {
    if (text[i] == '\n')
      ++line, col = 1;
    else
      ++col;
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(col);
}
}  // namespace

nlohmann::json parse_json(const std::string& text, const std::string& source) {
  return parse_json(text, source, StreamedArray{});
}

nlohmann::json parse_json(const std::string& text, const std::string& source,
                          const StreamedArray& streamed) {
  // The parser takes a NUL byte for the end of the input, so a value followed by one (and by
  // anything after it) was accepted. JSON text holds no raw NUL anywhere, not even in a string.
  if (const std::size_t nul = text.find('\0'); nul != std::string::npos)
    throw DataError(source, line_and_column(text, nul + 1),
                    "invalid JSON: a NUL byte (JSON text holds none; after the value only "
                    "white space may follow)");
  nlohmann::json root;
  TrackingBuilder builder(root, source, streamed.read ? &streamed : nullptr);
  nlohmann::json::sax_parse(text, &builder);
  if (builder.syntax_byte_) {
    // Translate the byte offset into line and column for the message.
    const std::size_t byte = std::min<std::size_t>(*builder.syntax_byte_, text.size());
    std::string why = builder.syntax_what_;
    const auto pos = why.find("syntax error");
    if (pos != std::string::npos) why = why.substr(pos);
    throw DataError(source, line_and_column(text, byte), "invalid JSON: " + printable(why));
  }
  return root;
}

}  // namespace pl

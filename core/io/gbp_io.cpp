#include "core/io/gbp_io.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "core/base/data_error.hpp"
#include "core/io/atomic_file.hpp"
#include "core/io/input_limits.hpp"
#include "core/io/json_node.hpp"
#include "core/io/scene_checks.hpp"

namespace pl {

namespace {

std::vector<std::string_view> tokens(const std::string& text) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  const auto space = [](char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
  };
  while (i < text.size()) {
    while (i < text.size() && space(text[i])) ++i;
    const std::size_t b = i;
    while (i < text.size() && !space(text[i])) ++i;
    if (i > b) out.emplace_back(text.data() + b, i - b);
  }
  return out;
}

std::string where(std::size_t index) {
  return "token " + std::to_string(index + 1);
}

std::string quoted(std::string_view t) {
  return "\"" + printable(t.substr(0, 40)) + (t.size() > 40 ? "...\"" : "\"");
}

long long header_integer(const std::vector<std::string_view>& t, std::size_t i,
                         const std::string& source, const char* what) {
  if (i >= t.size())
    throw DataError(source, where(i), std::string("missing header: expected the ") + what);
  long long v = 0;
  const char* b = t[i].data();
  const char* e = b + t[i].size();
  if (*b == '+') ++b;
  const auto r = std::from_chars(b, e, v);
  if (r.ec != std::errc() || r.ptr != e)
    throw DataError(source, where(i),
                    std::string("expected the ") + what + " as an integer, got " + quoted(t[i]));
  return v;
}

double number(std::string_view t, std::size_t i, const std::string& source) {
  double v = 0;
  const char* b = t.data();
  const char* e = b + t.size();
  if (b != e && *b == '+') ++b;
  const auto r = std::from_chars(b, e, v);
  if (r.ec == std::errc::result_out_of_range)
    throw DataError(source, where(i), "number out of range: " + quoted(t));
  if (r.ec != std::errc() || r.ptr != e)
    throw DataError(source, where(i), "expected a number, got " + quoted(t));
  if (!std::isfinite(v)) throw DataError(source, where(i), "non-finite number " + quoted(t));
  if (std::fabs(v) > kMaxCoordinate)
    throw DataError(source, where(i),
                    "coordinate " + quoted(t) + " is out of range: |x| <= " +
                        short_number(kMaxCoordinate) + " keeps squared lengths finite");
  return v;
}

}  // namespace

GBPatch parse_gbp(const std::string& text, const std::string& source) {
  const auto t = tokens(text);
  const long long n = header_integer(t, 0, source, "number of sides n");
  if (n < 3) throw DataError(source, where(0), "n = " + std::to_string(n) + ": need n >= 3");
  if (n > GBPatch::kMaxSides)
    throw DataError(source, where(0),
                    "n = " + std::to_string(n) + ": at most " + std::to_string(GBPatch::kMaxSides) +
                        " sides supported");
  const long long d = header_integer(t, 1, source, "degree d");
  if (d < 1) throw DataError(source, where(1), "d = " + std::to_string(d) + ": need d >= 1");
  if (d > GBPatch::kMaxDegree)
    throw DataError(source, where(1),
                    "d = " + std::to_string(d) + ": at most degree " +
                        std::to_string(GBPatch::kMaxDegree) + " supported");
  const std::size_t count = GBPatch::point_count(static_cast<int>(n), static_cast<int>(d));
  const std::size_t needed = 2 + 3 * count;
  if (t.size() < needed)
    throw DataError(source, where(t.size()),
                    "too few points: n = " + std::to_string(n) + ", d = " + std::to_string(d) +
                        " needs " + std::to_string(count) + " points (" +
                        std::to_string(3 * count) + " numbers), the file has " +
                        std::to_string(t.size() - 2) + " numbers");
  if (t.size() > needed)
    throw DataError(source, where(needed),
                    "extra token " + quoted(t[needed]) + " after the " + std::to_string(count) +
                        " points of n = " + std::to_string(n) + ", d = " + std::to_string(d));
  std::vector<Vec3> points(count);
  for (std::size_t p = 0; p < count; ++p)
    for (int c = 0; c < 3; ++c) {
      const std::size_t i = 2 + 3 * p + c;
      points[p][c] = number(t[i], i, source);
    }
  check_span(points, source, "");
  try {
    return GBPatch(static_cast<int>(n), static_cast<int>(d), std::move(points));
  } catch (const std::invalid_argument& e) {
    throw DataError(source, "", e.what());
  }
}

GBPatch read_gbp(const std::filesystem::path& path) {
  return parse_gbp(read_text_file(path), path.string());
}

std::string gbp_to_text(const GBPatch& patch) {
  std::string out = std::to_string(patch.sides()) + " " + std::to_string(patch.degree()) + "\n";
  // Each coordinate in the shortest spelling that reads back as the same double: a file read
  // and saved again keeps its "-65.3028", so a diff shows the points that were edited.
  char buf[32];
  for (const Vec3& p : patch.control_points())
    for (int c = 0; c < 3; ++c) {
      const auto end = std::to_chars(buf, buf + sizeof buf, p[c]).ptr;
      out.append(buf, end);
      out += c < 2 ? ' ' : '\n';
    }
  return out;
}

void write_gbp(const std::filesystem::path& path, const GBPatch& patch) {
  write_file_atomically(path, gbp_to_text(patch));
}

}  // namespace pl

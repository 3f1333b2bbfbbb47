// A data error (malformed file, degenerate input): says which file and where.
#pragma once

#include <stdexcept>
#include <string>

namespace pl {

class DataError : public std::runtime_error {
 public:
  // where: a JSON path ("faces[3].loop[2]"), "line 4", "token 17", or empty.
  DataError(std::string source, std::string where, std::string message)
      : std::runtime_error(format(source, where, message)),
        source_(std::move(source)),
        where_(std::move(where)),
        message_(std::move(message)) {}

  const std::string& source() const { return source_; }
  const std::string& where() const { return where_; }
  const std::string& message() const { return message_; }

 private:
  static std::string format(const std::string& s, const std::string& w, const std::string& m) {
    std::string r = s.empty() ? std::string() : s + ": ";
    if (!w.empty()) r += w + ": ";
    return r + m;
  }
  std::string source_, where_, message_;
};

}  // namespace pl

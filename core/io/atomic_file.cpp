#include "core/io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>

#include "core/base/data_error.hpp"

namespace pl {

namespace {
std::filesystem::path temporary_beside(const std::filesystem::path& target) {
  std::random_device rd;
  // Built by appends: GCC 12 reports a false -Wrestrict for "literal" + std::string at -O3.
  std::string name = ".";
  name += target.filename().string();
  name += ".tmp";
  name += std::to_string(rd() % 1000000);
  return target.parent_path() / name;
}

void fsync_path(const std::filesystem::path& p) {
  const int fd = ::open(p.c_str(), O_RDONLY);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}
}  // namespace

void write_atomically_via(const std::filesystem::path& target,
                          const std::function<void(const std::filesystem::path&)>& produce) {
  const auto tmp = temporary_beside(target);
  try {
    produce(tmp);
    fsync_path(tmp);
    std::error_code ec;
    std::filesystem::rename(tmp, target, ec);
    if (ec) throw DataError(target.string(), "", "cannot replace file: " + ec.message());
  } catch (...) {
    std::error_code ignore;
    std::filesystem::remove(tmp, ignore);
    throw;
  }
}

void write_file_atomically(const std::filesystem::path& target, const std::string& content) {
  write_atomically_via(target, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out)
      throw DataError(target.string(), "", std::string("cannot write: ") + std::strerror(errno));
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    if (!out) throw DataError(target.string(), "", "write failed (disk full?)");
  });
}

std::string read_text_file(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw DataError(path.string(), "", "is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw DataError(path.string(), "", std::string("cannot open: ") + std::strerror(errno));
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw DataError(path.string(), "", "read failed");
  return ss.str();
}

}  // namespace pl

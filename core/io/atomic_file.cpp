#include "core/io/atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/base/data_error.hpp"
#include "core/io/input_limits.hpp"

namespace pl {

namespace {

std::string temporary_prefix(const std::filesystem::path& target) {
  // Built by appends: GCC 12 reports a false -Wrestrict for "literal" + std::string at -O3.
  std::string name = ".";
  name += target.filename().string();
  name += ".tmp";
  return name;
}

std::filesystem::path temporary_beside(const std::filesystem::path& target) {
  static std::atomic<unsigned> counter{0};
  std::string name = temporary_prefix(target);
  name += std::to_string(::getpid());
  name += "-";
  name += std::to_string(counter++);
  return target.parent_path() / name;
}

std::string directory_of(const std::filesystem::path& target) {
  const auto dir = target.parent_path();
  return dir.empty() ? std::string(".") : dir.string();
}

// Writes all of content to fd; returns 0 or the errno of the failure.
int write_all(int fd, std::string_view content) {
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    done += static_cast<std::size_t>(n);
  }
  return 0;
}

int fsync_path(const std::filesystem::path& p) {
  const int fd = ::open(p.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return errno;
  const int r = ::fsync(fd) == 0 ? 0 : errno;
  ::close(fd);
  return r;
}

// The temporary files being written now, for remove_temporaries_in_flight. A slot is claimed by
// an atomic exchange, its name copied in, and only then marked readable, so a handler never
// reads a half-copied name; a name too long for a slot is not listed (the next write to the
// target still removes it once this process is gone).
constexpr int kInFlightSlots = 16;
constexpr std::size_t kInFlightName = 4096;
struct InFlight {
  std::atomic<int> state{0};  // 0 free, 1 being filled, 2 readable
  char name[kInFlightName];
};
InFlight in_flight[kInFlightSlots];

// Lists tmp while it exists; a slot index, or -1 when the table is full or the name too long.
class InFlightEntry {
 public:
  explicit InFlightEntry(const std::filesystem::path& tmp) {
    const std::string& s = tmp.native();
    if (s.size() >= kInFlightName) return;
    for (int i = 0; i < kInFlightSlots; ++i) {
      int expected = 0;
      if (!in_flight[i].state.compare_exchange_strong(expected, 1)) continue;
      std::memcpy(in_flight[i].name, s.c_str(), s.size() + 1);
      in_flight[i].state.store(2);
      slot_ = i;
      return;
    }
  }
  ~InFlightEntry() {
    if (slot_ >= 0) in_flight[slot_].state.store(0);
  }
  InFlightEntry(const InFlightEntry&) = delete;
  InFlightEntry& operator=(const InFlightEntry&) = delete;

 private:
  int slot_ = -1;
};

bool process_gone(long pid) {
  return pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

}  // namespace

void throw_write_error(const std::filesystem::path& target, int error) {
  std::string why;
  switch (error) {
    case ENOENT:
    case ENOTDIR:
      why = "no such directory " + directory_of(target);
      break;
    case EACCES:
    case EPERM:
      why = "permission denied in directory " + directory_of(target);
      break;
    case EROFS:
      why = "read-only file system";
      break;
    case ENOSPC:
    case EDQUOT:
      why = "disk full";
      break;
    case EFBIG:
      why = "file too large (the file size limit was reached)";
      break;
    case EISDIR:
      why = "is a directory";
      break;
    default:
      why = std::strerror(error);
  }
  throw DataError(target.string(), "", "cannot write: " + why);
}

int remove_stale_temporaries(const std::filesystem::path& target) {
  const std::string prefix = temporary_prefix(target);
  const auto dir = target.parent_path().empty() ? std::filesystem::path(".") : target.parent_path();
  std::error_code ec;
  std::filesystem::directory_iterator it(dir, ec), end;
  int removed = 0;
  for (; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.compare(0, prefix.size(), prefix) != 0) continue;
    // ".NAME.tmp<pid>-<n>[.ext]": the writer's process id.
    std::size_t i = prefix.size();
    long pid = 0;
    while (i < name.size() && name[i] >= '0' && name[i] <= '9' && pid < 100000000)
      pid = pid * 10 + (name[i++] - '0');
    if (i == prefix.size() || i >= name.size() || name[i] != '-') continue;
    if (!process_gone(pid)) continue;
    std::error_code ignore;
    removed += std::filesystem::remove(it->path(), ignore) ? 1 : 0;
  }
  return removed;
}

void write_atomically_via(const std::filesystem::path& target,
                          const std::function<void(const std::filesystem::path&)>& produce) {
  remove_stale_temporaries(target);
  const auto tmp = temporary_beside(target);
  const InFlightEntry listed(tmp);  // listed before the file exists, unlisted after it is gone
  try {
    produce(tmp);
    if (const int e = fsync_path(tmp)) throw_write_error(target, e);
    std::error_code ec;
    std::filesystem::rename(tmp, target, ec);
    if (ec) {
      if (ec.value() == EISDIR || ec.value() == ENOTEMPTY || ec.value() == EEXIST)
        throw_write_error(target, EISDIR);
      throw_write_error(target, ec.value());
    }
  } catch (...) {
    std::error_code ignore;
    std::filesystem::remove(tmp, ignore);
    throw;
  }
}

void write_file_atomically(const std::filesystem::path& target, const std::string& content) {
  write_text_atomically(target, [&](const TextSink& write) { write(content); });
}

void write_text_atomically(const std::filesystem::path& target,
                           const std::function<void(const TextSink&)>& produce) {
  write_atomically_via(target, [&](const std::filesystem::path& tmp) {
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) throw_write_error(target, errno);
    try {
      produce([&](std::string_view piece) {
        if (const int e = write_all(fd, piece)) throw_write_error(target, e);
      });
    } catch (...) {
      ::close(fd);
      throw;
    }
    if (::close(fd) != 0) throw_write_error(target, errno);
  });
}

void remove_temporaries_in_flight() noexcept {
  for (InFlight& f : in_flight)
    if (f.state.load() == 2) ::unlink(f.name);
}

std::string read_text_file(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw DataError(path.string(), "", "is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw DataError(path.string(), "", std::string("cannot open: ") + std::strerror(errno));
  const auto bytes = std::filesystem::file_size(path, ec);
  if (!ec && bytes > kMaxInputBytes)
    throw DataError(path.string(), "",
                    "the file has " + std::to_string(bytes) + " bytes; PatchLab reads at most " +
                        std::to_string(kMaxInputBytes));
  if (ec) {  // no size known (a pipe, say): read it as it comes
    std::ostringstream ss;
    ss << in.rdbuf();
    if (in.bad()) throw DataError(path.string(), "", "read failed");
    return ss.str();
  }
  // Read into a string of the file's size at once: through a string stream the text was copied
  // twice and grown by doubling (a 55 MB scene moved about 200 MB).
  std::string text(bytes, '\0');
  in.read(text.data(), static_cast<std::streamsize>(bytes));
  if (in.bad()) throw DataError(path.string(), "", "read failed");
  text.resize(static_cast<std::size_t>(in.gcount()));  // a file that shrank meanwhile
  if (in.gcount() == static_cast<std::streamsize>(bytes) && in.peek() != EOF) {
    std::ostringstream rest;  // one that grew: the rest as it comes
    rest << in.rdbuf();
    text += rest.str();
  }
  return text;
}

}  // namespace pl

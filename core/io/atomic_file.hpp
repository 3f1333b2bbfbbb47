// Atomic file replacement: write a temporary file beside the target, flush it to disk, rename it
// over the target. A failure at any step leaves the previous file untouched.
//
// The temporary file is ".NAME.tmp<pid>-<n>" (plus the target's extension for writers that choose
// their format by it). While it is being written its name is kept in a fixed table that a signal
// handler may read (remove_temporaries_in_flight), so a process stopped by SIGTERM or SIGINT
// removes it before it dies. A process killed while writing (SIGKILL, or SIGXFSZ where it is not
// ignored) cannot remove its own; every later write to the same target removes the temporary
// files of that target whose process is gone.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <string_view>

namespace pl {

// Throws DataError (source = target path, never the temporary file) naming the reason: no such
// directory, permission denied, disk full, file too large, ...
void write_file_atomically(const std::filesystem::path& target, const std::string& content);
// The same for text made in pieces: `produce` hands each piece to the sink it is given, which
// writes it (or throws write_file_atomically's DataError), so the whole text is never held.
using TextSink = std::function<void(std::string_view)>;
void write_text_atomically(const std::filesystem::path& target,
                           const std::function<void(const TextSink&)>& produce);
// For writers that stream: `produce` writes to a temporary file path; it is renamed on success.
// `produce` reports its own failures with throw_write_error(target, errno).
void write_atomically_via(const std::filesystem::path& target,
                          const std::function<void(const std::filesystem::path& tmp)>& produce);

// The DataError of a failed write to target (error: an errno value).
[[noreturn]] void throw_write_error(const std::filesystem::path& target, int error);

// Removes the temporary files left beside target by processes that no longer run; returns how
// many. Called by every atomic write before it starts.
int remove_stale_temporaries(const std::filesystem::path& target);

// Unlinks every temporary file now being written by this process. Async-signal-safe (only
// unlink(2) on names copied into static storage beforehand): meant for a handler of SIGTERM or
// SIGINT, which then lets the signal end the process.
void remove_temporaries_in_flight() noexcept;

std::string read_text_file(const std::filesystem::path& path);  // throws DataError

}  // namespace pl

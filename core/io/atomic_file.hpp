// Atomic file replacement: write a temporary file beside the target, flush it to disk, rename it
// over the target. A failure at any step leaves the previous file untouched.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

namespace pl {

// Throws DataError (source = target path) on failure.
void write_file_atomically(const std::filesystem::path& target, const std::string& content);
// For writers that stream: `produce` writes to a temporary file path; it is renamed on success.
void write_atomically_via(const std::filesystem::path& target,
                          const std::function<void(const std::filesystem::path& tmp)>& produce);

std::string read_text_file(const std::filesystem::path& path);  // throws DataError

}  // namespace pl

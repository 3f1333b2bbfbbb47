// Shared by the libFuzzer targets: what counts as a correct answer to hostile input. A DataError
// (a located message, exit 1 in the CLI) is correct; any other exception escapes and libFuzzer
// reports it as a crash, as do the sanitizers' findings (memory errors, leaks, undefined
// behaviour) and timeouts.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace pl::fuzz {

inline std::string text(const uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

}  // namespace pl::fuzz

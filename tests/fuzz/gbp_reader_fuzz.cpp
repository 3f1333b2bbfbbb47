// libFuzzer target: the .gbp reader, and the writer on what it accepts (bit-exact round trip).
#include "core/base/data_error.hpp"
#include "core/io/gbp_io.hpp"
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  std::string once;
  try {
    once = pl::gbp_to_text(pl::parse_gbp(pl::fuzz::text(data, size), "fuzz.gbp"));
  } catch (const pl::DataError&) {
    return 0;  // refused with a located message: correct
  }
  // What was accepted must write and read back bit for bit (any exception here escapes).
  if (pl::gbp_to_text(pl::parse_gbp(once, "again.gbp")) != once) __builtin_trap();
  return 0;
}

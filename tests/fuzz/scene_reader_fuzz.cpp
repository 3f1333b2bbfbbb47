// libFuzzer target: the scene reader (JSON syntax, the reading rules and every patch codec
// through it) and the writer on what it accepts (a read scene must write and read back).
#include "core/base/data_error.hpp"
#include "core/io/scene_io.hpp"
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  pl::Scene scene;
  try {
    scene = pl::parse_scene(pl::fuzz::text(data, size), "fuzz.json");
  } catch (const pl::DataError&) {
    return 0;  // refused with a located message: correct
  }
  // What was accepted must write and read back to the same text (any exception here escapes).
  const std::string once = pl::scene_to_json(scene);
  if (pl::scene_to_json(pl::parse_scene(once, "again.json")) != once) __builtin_trap();
  return 0;
}

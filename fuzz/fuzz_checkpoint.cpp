// rupture/fuzz/fuzz_checkpoint.cpp
// libFuzzer harness: every input as a checkpoint of the fuzz case, a case source and a part
// file (fuzz_entry.hpp: checkpoint_one). Seeds: fuzz/corpus/checkpoint/.
#include <cstddef>
#include <cstdint>

#include "fuzz_entry.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  (void)rupture::fuzz::checkpoint_one(data, size);
  return 0;
}

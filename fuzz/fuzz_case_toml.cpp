// rupture/fuzz/fuzz_case_toml.cpp
// libFuzzer harness: every input as a case file (fuzz_entry.hpp: case_toml_one). Seeds:
// examples/*.toml and tests/inputs/*.toml (build/fuzz/corpus/case_toml/ holds what the runs add, scripts/fuzz.sh).
#include <cstddef>
#include <cstdint>

#include "fuzz_entry.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  (void)rupture::fuzz::case_toml_one(data, size);
  return 0;
}

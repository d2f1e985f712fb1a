// rupture/fuzz/fuzz_entry.hpp
// What the fuzzers (fuzz/fuzz_*.cpp, libFuzzer) and their regression tests (tests/
// test_fuzz_regressions.cpp, every build) feed one input to. A bad input must be refused with
// the documented errors (InputError, IoError; SimulationError when a restored state steps
// into trouble); every other exception escapes and anything else (a crash, undefined
// behaviour) is what the fuzzers look for.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

#include "input/case.hpp"
#include "run/run_context.hpp"

namespace rupture::fuzz {

enum class Outcome { accepted, refused, unstable };

// The case a checkpoint input is restored into: a 20 x 2 mm Homalite plate of two bodies
// with a cohesive interface between them (2 x 2 particles per 0.5 mm cell, two scatter
// strips), an impact on its left edge, snapshots and crack samples.
std::string checkpoint_case_toml();

// A context set up from `c` as run/driver.cpp sets one up before it restores a checkpoint (the
// state, a crack tracker per interface, the snapshot writer into `dir`, the schedules).
void set_up_like_driver(RunContext& r, const Case& c, const std::string& dir);

// The checkpoint checksum (the last 8 bytes) recomputed over the rest, as a forger would: the
// fuzzer's mutations then reach what lies behind the checksum.
void reseal(std::string& bytes);

// `bytes`, resealed, as a checkpoint.bin of that case: restored (run/checkpoint.hpp:
// restore_run_checkpoint_bytes) into a context set up as the driver sets one up and, when it
// restores, stepped twice with the trackers sampled and summarized; also its case source
// (checkpoint_source_from_bytes) and, as a part file, its particles (read_checkpoint_part_bytes
// into the state's checks).
Outcome checkpoint_one(const std::uint8_t* data, std::size_t size);

// `text` as a case file (input/case_toml.hpp: parse_case).
Outcome case_toml_one(const std::uint8_t* data, std::size_t size);

}  // namespace rupture::fuzz

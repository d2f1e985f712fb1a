// The fuzzers' inputs in every build (fuzz/: the libFuzzer harnesses need clang): each seed and
// each saved regression input goes through the same entry the harness calls
// (fuzz/fuzz_entry.hpp) and must come back (refused or accepted), and the committed checkpoint
// seeds still restore into the fuzz case. RUPTURE_WRITE_SEEDS=1 writes the seeds anew (after a
// change of the checkpoint format).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "fuzz_entry.hpp"
#include "input/case_toml.hpp"
#include "run/checkpoint.hpp"
#include "solver/energy.hpp"
#include "solver/step.hpp"

using namespace rupture;
namespace fs = std::filesystem;

namespace {

const fs::path kFuzz = fs::path(RUPTURE_SOURCE_DIR) / "fuzz";

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}
void write(const fs::path& p, const std::string& bytes) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << bytes;
}
std::vector<fs::path> files_in(const fs::path& dir, const std::string& ext = "") {
  std::vector<fs::path> out;
  if (fs::is_directory(dir))
    for (const auto& e : fs::directory_iterator(dir))
      if (e.is_regular_file() && (ext.empty() || e.path().extension() == ext)) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

// The seeds: the fuzz case's checkpoint after 30 steps (past a re-sort, the interface
// loaded) and its particles as part 0 of 1 at step 0 (what checkpoint_one reads a part as).
void write_seeds() {
  const Case c = parse_case(fuzz::checkpoint_case_toml());
  const std::string dir = (fs::temp_directory_path() / "rupture_fuzz_seeds").string();
  fs::remove_all(dir);
  RunContext r;
  fuzz::set_up_like_driver(r, c, dir);
  auto record = [&]() {
    r.history.samples.push_back(EnergySample{r.s.time, kinetic_energy(r.s.levels[0].particles),
                                             strain_energy(r.s.levels[0].particles, r.s.levels[0].stiffness), r.s.external_work,
                                             r.s.initial_energy});
    for (std::size_t i = 0; i < r.cracks.size(); ++i) r.cracks[i].sample(r.s.levels[0].interfaces[i], r.s.time);
  };
  record();
  for (int k = 0; k < 30; ++k) step(r.s), record();
  r.s.levels[0].cohesive_seconds = 0.0;  // wall time: the seed is the same on every machine
  const CaseSource source{fuzz::checkpoint_case_toml(), "fuzz case", {"time.end=2e-6"}};
  write(kFuzz / "corpus/checkpoint/plate_30_steps.bin", checkpoint_bytes(source, r));
  write_checkpoint_part(dir, 0, 0, 1, r.s.levels[0].particles);
  write(kFuzz / "corpus/checkpoint/plate_part.bin", read(checkpoint_part_path(dir, 0, 0)));
}

}  // namespace

TEST(FuzzRegressions, checkpoint_seeds_restore_and_saved_inputs_come_back) {
  if (const char* w = std::getenv("RUPTURE_WRITE_SEEDS"); w && std::string(w) == "1") write_seeds();
  const std::vector<fs::path> seeds = files_in(kFuzz / "corpus/checkpoint");
  ASSERT_FALSE(seeds.empty()) << "no seeds in " << kFuzz / "corpus/checkpoint";
  const std::string main_seed = read(kFuzz / "corpus/checkpoint/plate_30_steps.bin");
  EXPECT_EQ(fuzz::checkpoint_one(reinterpret_cast<const std::uint8_t*>(main_seed.data()), main_seed.size()),
            fuzz::Outcome::accepted)
      << "the seed no longer restores: RUPTURE_WRITE_SEEDS=1 ctest -R FuzzRegressions writes it anew";
  std::vector<fs::path> all = seeds;
  const std::size_t kept = all.size();
  for (const fs::path& p : files_in(kFuzz / "regressions/checkpoint")) all.push_back(p);
  for (std::size_t k = 0; k < all.size(); ++k) {
    const std::string b = read(all[k]);
    fuzz::Outcome o = fuzz::Outcome::accepted;
    EXPECT_NO_THROW(o = fuzz::checkpoint_one(reinterpret_cast<const std::uint8_t*>(b.data()), b.size())) << all[k];
    // A saved crash is in the current format (its version and entries brought up to date when
    // the format changes), so it reaches the checks after decoding and is refused there.
    if (k >= kept && all[k].extension() == ".bin") {
      EXPECT_EQ(o, fuzz::Outcome::refused) << all[k];
    }
  }
}

TEST(FuzzRegressions, case_files_and_saved_inputs_come_back) {
  std::vector<fs::path> all = files_in(fs::path(RUPTURE_SOURCE_DIR) / "examples", ".toml");
  const std::size_t examples = all.size();
  for (const fs::path& p : files_in(kFuzz / "regressions/case_toml")) all.push_back(p);
  for (std::size_t k = 0; k < all.size(); ++k) {
    const std::string b = read(all[k]);
    fuzz::Outcome o = fuzz::Outcome::refused;
    EXPECT_NO_THROW(o = fuzz::case_toml_one(reinterpret_cast<const std::uint8_t*>(b.data()), b.size())) << all[k];
    if (k < examples) {
      EXPECT_EQ(o, fuzz::Outcome::accepted) << all[k] << " is a valid case";
    }
  }
}

// Tests for core/fp_mode.hpp: after flush_subnormals_to_zero(), every OpenMP thread flushes a
// subnormal result to zero and reads a subnormal operand as zero; normal numbers are untouched.
#include <gtest/gtest.h>
#include <omp.h>

#include <cfloat>
#include <cstdint>
#include <cstring>
#include <vector>

#include "core/fp_mode.hpp"

using namespace rupture;

namespace {
// Kept out of the compiler's reach, so the products are computed at run time.
volatile double g_smallest_normal = DBL_MIN;
volatile double g_half = 0.5;

double subnormal_operand() {
  const std::uint64_t bits = 1;  // the smallest subnormal, 4.9e-324
  double d;
  std::memcpy(&d, &bits, sizeof d);
  return d;
}
}  // namespace

TEST(FpMode, SubnormalsAreKeptUntilTheModeIsSet) {
  if (flushes_subnormals()) GTEST_SKIP() << "the mode was already set in this process";
  EXPECT_GT(g_smallest_normal * g_half, 0.0);  // gradual underflow, IEEE default
}

TEST(FpMode, EveryThreadFlushesSubnormalResultsAndOperands) {
  flush_subnormals_to_zero();
#if defined(__SSE2__)
  omp_set_num_threads(2);
  std::vector<int> ok(2, 0);
#pragma omp parallel num_threads(2)
  {
    const double product = g_smallest_normal * g_half;  // subnormal result
    volatile double sub = subnormal_operand();
    const double sum = sub + 0.0;  // subnormal operand
    const double normal = g_smallest_normal * 4.0;  // normal numbers unchanged
    ok[std::size_t(omp_get_thread_num())] =
        flushes_subnormals() && product == 0.0 && sum == 0.0 && normal == 4.0 * DBL_MIN;
  }
  EXPECT_EQ(ok[0], 1);
  EXPECT_EQ(ok[1], 1);
#else
  GTEST_SKIP() << "no SSE: the mode is not set on this processor";
#endif
}

// rupture/core/fp_mode.cpp
#include "core/fp_mode.hpp"

#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

namespace rupture {
namespace {

#if defined(__SSE2__)
constexpr unsigned kFtzDaz = 0x8040u;  // MXCSR: flush to zero (bit 15), denormals are zero (bit 6)
#endif

void set_on_this_thread() {
#if defined(__SSE2__)
  _mm_setcsr(_mm_getcsr() | kFtzDaz);
#endif
}

}  // namespace

void flush_subnormals_to_zero() {
  set_on_this_thread();
#pragma omp parallel
  set_on_this_thread();
}

bool flushes_subnormals() {
#if defined(__SSE2__)
  return (_mm_getcsr() & kFtzDaz) == kFtzDaz;
#else
  return false;
#endif
}

}  // namespace rupture

// rupture/core/fp_mode.hpp
// The floating-point mode of a run: subnormal numbers (|x| < 2.2e-308) flushed to zero, as
// results and as operands (x86 MXCSR FTZ and DAZ), on the calling thread and on every OpenMP
// thread. Why: the wave fronts of a run (and rupture-bench's) drag exponentially decaying
// round-off ahead of them into quiet regions; once those values are subnormal, every
// operation on them takes a microcode assist, about a hundred cycles on Intel (measured in
// docs/performance.md, "Choices in the code"). No quantity of a run in SI units
// means anything below 1e-300, so the flush changes no result that matters; runs stay
// deterministic (the same mode on every thread). Call once at the start of a program, before
// other threads exist (threads created later inherit the mode of their creator).
#pragma once

namespace rupture {

void flush_subnormals_to_zero();
// Whether the calling thread flushes them (false on processors where the mode is not set).
bool flushes_subnormals();

}  // namespace rupture

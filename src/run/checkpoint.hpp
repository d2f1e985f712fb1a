// rupture/run/checkpoint.hpp
// Checkpoints: DIR/checkpoint/checkpoint.bin holds a whole RunContext (run/run_context.hpp)
// plus the case source, so `rupture resume DIR` continues a run bit for bit, also after kill -9.
// Format (native byte order, checked): magic "RUPTCKPT", format version, byte-order mark, then
// named entries (name, kind, element type and size, count, bytes), then an FNV-1a checksum of
// everything before it. Reading checks every name, type and size in order, so a truncated,
// corrupt or foreign file, or one from another layout, stops with a clear IoError/InputError.
// Written atomically (tmp + fsync + rename): the previous checkpoint stays until the new one
// is complete. What is derived from the case (grid, stiffnesses, boundary conditions, bonded
// nodes) is rebuilt by make_state() and not written; per-step scratch (grid fields, the sort's
// scratch arrays) neither.
#pragma once
#include <string>

#include "run/run_context.hpp"

namespace rupture {

inline constexpr int kCheckpointVersion = 21;  // 2: State::strain_work; 3: Mach readings;
                                              // 4: interface rupture times, peak slip rates;
                                              // 5: nested levels; 6: particles store the
                                              // stress only (no strain, szz, volume);
                                              // 7: the scatter plan's drift since its sort;
                                              // 8: particle part files (distributed runs);
                                              // 9: snapshot rows as runs of ids;
                                              // 10: the run's identity (run_id);
                                              // 11: refined grids default to nested levels
                                              // with per-level steps (a stored case without
                                              // grid.refinement meant "graded" before);
                                              // 12: rate-and-state history (gp_state,
                                              // gp_rate) and the interfaces' time;
                                              // 13: the nodes' slip rate (node_slip_rate),
                                              // fault stations' jump_rate column, the
                                              // particles' Kelvin-Voigt stress (viscous_on,
                                              // vsxx, vsyy, vsxy) and viscous_dissipated;
                                              // 14: the normal stress friction sees
                                              // (gp_normal, normal-stress regularization);
                                              // 15: the fault stations' state column;
                                              // 16: the particles' reference position
                                              // (x0, y0: the J-integral's displacement);
                                              // 17: the grown cracks' segments (run.growth,
                                              // before the state); 18: the wall time in
                                              // crack growth (run.growth_seconds); 19: the
                                              // tips' speed column (run.tips rows); 20: when
                                              // a crack nucleated (run.growth[].nucleation_time);
                                              // 21: where the ties are laid (interfaces'
                                              // tie_x0 ... tie_uy, tie_drift, travel)

std::string checkpoint_path(const std::string& dir);  // DIR/checkpoint/checkpoint.bin

// Writes the checkpoint of `ctx` for the case `source` into DIR/checkpoint/.
void write_checkpoint(const std::string& dir, const CaseSource& source, const RunContext& ctx);

// The case source stored in a checkpoint file.
CaseSource read_checkpoint_source(const std::string& path);

// Overwrites the evolving parts of `ctx` with the checkpoint's. `ctx` must have been set up
// from the same case (make_state, trackers, snapshot writer); sizes are checked against it.
// The checkpoint of a run (the driver's): its records hold the samples of t = 0 as well.
void read_checkpoint(const std::string& path, RunContext& ctx);

// A distributed run's checkpoint: checkpoint.bin (rank 0: everything but the particles,
// State::particle_parts = N) and one part file per rank with its particles, named by the step
// so a new checkpoint never overwrites the parts the previous checkpoint.bin refers to
// (run/checkpoint_ranks.hpp writes and reads them together).
std::string checkpoint_part_path(const std::string& dir, long step, int rank);
void write_checkpoint_part(const std::string& dir, long step, int rank, int ranks,
                           const Particles& particles);
// Appends the particles of every part (0 .. ranks - 1) of the checkpoint at `step` to `out`.
void read_checkpoint_parts(const std::string& dir, long step, int ranks, Particles& out);
// Parts first .. first + count - 1 of a checkpoint written in `ranks` parts (nested levels:
// level l's particles of rank r are part l N + r of L N).
void read_checkpoint_parts(const std::string& dir, long step, int first, int count, int ranks, Particles& out);

// The same as bytes (tests, the fuzzers in fuzz/, and the file functions above). `origin`
// names the bytes in messages. Every failure is an InputError or IoError.
std::string checkpoint_bytes(const CaseSource& source, const RunContext& ctx);
void restore_checkpoint_bytes(const std::string& bytes, const std::string& origin, RunContext& ctx);
void restore_run_checkpoint_bytes(const std::string& bytes, const std::string& origin, RunContext& ctx);  // read_checkpoint's
CaseSource checkpoint_source_from_bytes(const std::string& bytes, const std::string& origin);
// One part file's bytes (part `rank` of `ranks` at `step`): its particles appended to `out`
// (arrays of one length; run/checkpoint_ranks.cpp checks them against the state).
void read_checkpoint_part_bytes(const std::string& bytes, const std::string& origin, long step, int rank,
                                int ranks, Particles& out);

}  // namespace rupture

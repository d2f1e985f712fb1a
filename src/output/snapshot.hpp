// rupture/output/snapshot.hpp
// Particle snapshots: one HDF5 file per output time under DIR/snapshots/, plus DIR/particles.xdmf,
// an XDMF 3 temporal collection that ParaView opens as a time series (Polyvertex topology).
// Datasets (SI): position [N,3] m (z = 0), velocity [N,3] m/s, half_size [N,2] m (the GIMP
// half-widths l_x, l_y: each particle's own extent, for drawing), sxx syy sxy szz tau_max [N] Pa,
// body [N] (velocity field id), id [N] (particle creation index; rows are in id order, the
// same particles in the same rows in every file), connectivity [N] (0..N-1: one vertex cell
// per particle; without it ParaView's Xdmf3 readers load the points but no cells, and the
// default view shows nothing); root attributes time (s) and step.
// tau_max = (sigma_1 - sigma_2)/2, the in-plane maximum shear stress (theory E13).
// Optionally only a region of interest is written. Every file is written to a temporary name
// and renamed when complete.
// Distributed runs (a Comm of N > 1 ranks): every rank calls write() with its own particles;
// the file is written collectively (parallel HDF5, MPI-IO), each rank its particles' rows (the
// same rows as one process would write), and rank 0 renames it and writes the XDMF index.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "material/elastic.hpp"
#include "parallel/comm.hpp"
#include "particles/particles.hpp"

namespace rupture {

// Which particle ids the snapshots hold and each one's row (rows in id order): maximal runs of
// consecutive ids, each with its first row, so the table stays small (one run per body and
// row of particles in a region of interest, one in all without) whatever the particle count.
struct SnapshotRows {
  std::vector<std::int64_t> first_id, first_row;  // per run, increasing
  std::int64_t rows = 0;                          // ids held
  void add(std::uint32_t id);                     // ids in increasing order
  std::int64_t row(std::uint32_t id) const;       // -1: not held
};

// The rows of the particles of `p` (every particle at t = 0) that lie inside `region`
// (xmin, ymin, xmax, ymax; every particle when null).
SnapshotRows snapshot_rows(const Particles& p, const double* region);
bool in_snapshot_region(const double* region, double x, double y);

class SnapshotWriter {
 public:
  // Writes every particle, or only those that start inside `region` (xmin, ymin, xmax, ymax)
  // when given: the same particles at every output time, so ParaView sees one point set.
  // `p`: every particle at t = 0.
  SnapshotWriter(std::string dir, const Particles& p, const double* region = nullptr,
                 const Comm& comm = Comm::single());
  // The same with the rows chosen already (a distributed run: among every particle the case
  // seeds, solver/case_seeding.hpp, each rank holding only its own).
  SnapshotWriter(std::string dir, SnapshotRows rows, const Comm& comm);
  // stiffness: the run's table indexed by p.material (sigma_zz follows from the in-plane stress).
  void write(const Particles& p, const std::vector<ElasticStiffness>& stiffness, double time,
             long step);
  const std::vector<std::string>& files() const { return files_; }
  const std::vector<double>& times() const { return times_; }  // each file's time, s
  // After a resume: the snapshots whose files are gone from the run directory (deleted by
  // hand) leave the index, so particles.xdmf names only files that exist; returns their names.
  // Rank 0 looks, every rank learns it (collective).
  std::vector<std::string> drop_missing_files();

 private:
  friend struct CheckpointAccess;  // every member below must also be written in run/checkpoint.cpp
  void write_xdmf() const;
  void write_collective(const Particles& p, const std::vector<ElasticStiffness>& stiffness,
                        double time, long step, const std::string& tmp);
  std::string dir_;
  Comm comm_ = Comm::single();
  SnapshotRows rows_;  // the particles written and their rows, the same in every file
  std::size_t selected_ = 0;
  std::vector<std::string> files_;  // relative to dir_
  std::vector<double> times_;
  std::vector<std::size_t> counts_;
};

}  // namespace rupture

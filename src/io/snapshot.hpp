// rupture/io/snapshot.hpp
// Particle snapshots: one HDF5 file per output time under DIR/snapshots/, plus DIR/particles.xdmf,
// an XDMF 3 temporal collection that ParaView opens as a time series (Polyvertex topology).
// Datasets (SI): position [N,3] m (z = 0), velocity [N,3] m/s, sxx syy sxy szz tau_max [N] Pa,
// body [N] (velocity field id), id [N] (particle creation index; rows are in id order, the
// same particles in the same rows in every file), connectivity [N] (0..N-1: one vertex cell
// per particle; without it ParaView's Xdmf3 readers load the points but no cells, and the
// default view shows nothing); root attributes time (s) and step.
// tau_max = (sigma_1 - sigma_2)/2, the in-plane maximum shear stress (SPEC E13).
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

class SnapshotWriter {
 public:
  // Writes every particle, or only those that start inside `region` (xmin, ymin, xmax, ymax)
  // when given: the same particles at every output time, so ParaView sees one point set.
  // `p`: every particle at t = 0 (a distributed run makes the writer before its split).
  SnapshotWriter(std::string dir, const Particles& p, const double* region = nullptr,
                 const Comm& comm = Comm::single());
  // stiffness: the run's table indexed by p.material (sigma_zz follows from the in-plane stress).
  void write(const Particles& p, const std::vector<ElasticStiffness>& stiffness, double time,
             long step);
  const std::vector<std::string>& files() const { return files_; }

 private:
  friend struct CheckpointAccess;  // every member below must also be written in io/checkpoint.cpp
  void write_xdmf() const;
  void write_collective(const Particles& p, const std::vector<ElasticStiffness>& stiffness,
                        double time, long step, const std::string& tmp);
  std::string dir_;
  Comm comm_ = Comm::single();
  std::vector<std::int64_t> slot_of_id_;  // row of particle id in every file, -1: not written
  std::size_t selected_ = 0;
  std::vector<std::string> files_;  // relative to dir_
  std::vector<double> times_;
  std::vector<std::size_t> counts_;
};

}  // namespace rupture

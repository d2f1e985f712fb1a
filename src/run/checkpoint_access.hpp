// rupture/run/checkpoint_access.hpp
// Internal to run/checkpoint*.cpp: the private members of CrackTracker and SnapshotWriter that a
// checkpoint stores (both name CheckpointAccess their friend), listed once for writing,
// reading and checking.
#pragma once
#include "cohesive/crack_tip.hpp"
#include "output/snapshot.hpp"

namespace rupture {

struct CheckpointAccess {
  template <class A>
  static void fields(A& a, CrackTracker& t) {
    a("samples", t.samples_);
    a("end_tolerance", t.end_tolerance_);
    a("end_reached_time", t.end_reached_time_);
  }
  template <class A>
  static void fields(A& a, SnapshotWriter& w) {
    // dir_ is the run directory, given when the writer is made
    a("rows_first_id", w.rows_.first_id);
    a("rows_first_row", w.rows_.first_row);
    a("rows", w.rows_.rows);
    a("selected", w.selected_);
    a("files", w.files_);
    a("times", w.times_);
    a("counts", w.counts_);
  }
  // What run/checkpoint_checks.cpp reads.
  static double end_tolerance(const CrackTracker& t) { return t.end_tolerance_; }
  static const SnapshotRows& rows(const SnapshotWriter& w) { return w.rows_; }
  static std::size_t selected(const SnapshotWriter& w) { return w.selected_; }
  static const std::vector<std::string>& files(const SnapshotWriter& w) { return w.files_; }
  static const std::vector<double>& times(const SnapshotWriter& w) { return w.times_; }
  static const std::vector<std::size_t>& counts(const SnapshotWriter& w) { return w.counts_; }
};

}  // namespace rupture

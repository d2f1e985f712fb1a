// rupture/solver/crack_record.cpp
// What a growing crack's record says (solver/crack_growth.hpp): its grown length, its splits and
// its tips' speeds.
#include <algorithm>

#include "solver/crack_growth.hpp"

namespace rupture {
namespace {

// Whether record row i belongs to the tip (label, end): a branch's tip by its label, the
// crack's own by its end (its label, the index among its tips, changes when the other stops).
bool row_of_tip(const std::vector<double>& r, std::size_t i, int label, LineEnd end) {
  if (r[i + 2] >= kSplitAtStart) return false;
  if (label >= 2) return r[i + 1] == double(label);
  return r[i + 1] < 2.0 && r[i + 2] == (end == LineEnd::start ? 0.0 : 1.0);
}

}  // namespace

double tip_grown(const CrackGrowthRecord& record, int label, LineEnd end) {
  double l = 0.0;
  const std::vector<double>& r = record.rows;
  for (std::size_t i = 0; i + kGrowthColumns <= r.size(); i += kGrowthColumns)
    if (row_of_tip(r, i, label, end)) l += r[i + 6];
  return l;
}

double CrackGrowthRecord::length() const {
  double l = 0.0;
  for (std::size_t i = 0; i + kGrowthColumns <= rows.size(); i += kGrowthColumns) l += rows[i + 6];
  return l;
}

int CrackGrowthRecord::branches() const {
  int n = 0;
  for (std::size_t i = 0; i + kGrowthColumns <= rows.size(); i += kGrowthColumns) n += rows[i + 2] >= kSplitAtStart;
  return n;
}

double tip_speed(const CrackGrowthRecord& record, int label, LineEnd end, double now, double window,
                 std::size_t rows) {
  const std::vector<double>& r = record.rows;
  double grown = 0.0;
  for (std::size_t i = std::min(r.size(), rows * kGrowthColumns); i >= kGrowthColumns;) {
    i -= kGrowthColumns;
    if (!row_of_tip(r, i, label, end)) continue;
    // The window starts where this row's segment starts: its time is the row before's for
    // the same tip, or (its first) this row's own; the speed is the path since then over time.
    grown += r[i + 6];
    if (grown < window * (1.0 - 1e-9)) continue;  // whole segments summing to the window, to round-off
    for (std::size_t j = i; j >= kGrowthColumns;) {
      j -= kGrowthColumns;
      if (row_of_tip(r, j, label, end)) return now > r[j] ? (grown) / (now - r[j]) : 0.0;
    }
    return 0.0;  // the first segments: no time before them to measure from
  }
  return 0.0;
}

}  // namespace rupture

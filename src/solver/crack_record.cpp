// rupture/solver/crack_record.cpp
// What a growing crack's record says (solver/crack_growth.hpp): its grown length, its splits,
// its tips' speeds, and the rows' checkpoint form.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "solver/crack_growth.hpp"

namespace rupture {

std::vector<double> growth_rows_flat(const std::vector<GrowthRow>& rows) {
  std::vector<double> flat;
  flat.reserve(rows.size() * kGrowthColumns);
  for (const GrowthRow& r : rows)
    flat.insert(flat.end(), {r.time, double(r.tip), double(r.end_code()), r.x, r.y, r.angle, r.length, r.K_I, r.K_II});
  return flat;
}

std::vector<GrowthRow> growth_rows_from_flat(const std::vector<double>& flat, const std::string& where) {
  if (flat.size() % kGrowthColumns != 0)
    throw InputError(fmt::format("{}.rows.length = {}: must be a multiple of {} (whole rows)", where, flat.size(),
                                 kGrowthColumns));
  std::vector<GrowthRow> rows(flat.size() / kGrowthColumns);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double* f = flat.data() + i * kGrowthColumns;
    const double tip = f[1], code = f[2];
    if (!(tip >= 0.0 && tip < 1e6 && tip == std::floor(tip)))
      throw InputError(fmt::format("{}.rows[{}] = {}: must be a tip index (a whole number from 0 to 999999)", where,
                                   i * kGrowthColumns + 1, tip));
    if (code != 0.0 && code != 1.0 && code != 2.0 && code != 3.0)
      throw InputError(fmt::format("{}.rows[{}] = {}: must be 0 or 1 (the end of the line the segment grew at) "
                                   "or 2 or 3 (the end whose tip split)",
                                   where, i * kGrowthColumns + 2, code));
    GrowthRow& r = rows[i];
    r.time = f[0];
    r.tip = int(tip);
    r.split = code >= 2.0;
    r.end = (code == 1.0 || code == 3.0) ? LineEnd::end : LineEnd::start;
    r.x = f[3], r.y = f[4], r.angle = f[5], r.length = f[6], r.K_I = f[7], r.K_II = f[8];
  }
  return rows;
}

double tip_grown(const CrackGrowthRecord& record, int label, LineEnd end) {
  double l = 0.0;
  for (const GrowthRow& r : record.rows)
    if (r.grows(label, end)) l += r.length;
  return l;
}

double CrackGrowthRecord::length() const {
  double l = 0.0;
  for (const GrowthRow& r : rows) l += r.length;
  return l;
}

int CrackGrowthRecord::branches() const {
  int n = 0;
  for (const GrowthRow& r : rows) n += r.split;
  return n;
}

double tip_speed(const CrackGrowthRecord& record, int label, LineEnd end, double now, double window,
                 std::size_t rows) {
  const std::vector<GrowthRow>& r = record.rows;
  double grown = 0.0;
  for (std::size_t i = std::min(r.size(), rows); i > 0;) {
    --i;
    if (!r[i].grows(label, end)) continue;
    // The window starts where this row's segment starts: its time is the row before's for
    // the same tip, or (its first) this row's own; the speed is the path since then over time.
    grown += r[i].length;
    if (grown < window * (1.0 - 1e-9)) continue;  // whole segments summing to the window, to round-off
    for (std::size_t j = i; j > 0;) {
      --j;
      if (r[j].grows(label, end)) return now > r[j].time ? (grown) / (now - r[j].time) : 0.0;
    }
    return 0.0;  // the first segments: no time before them to measure from
  }
  return 0.0;
}

}  // namespace rupture

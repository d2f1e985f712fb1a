// rupture/cohesive/mach_angle.cpp
#include "cohesive/mach_angle.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/atomic_file.hpp"

namespace rupture {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

// tau_max averaged into bins of size h over xi in [xi_min, xi_min + nx h), eta in
// [eta_min, eta_min + ny h); per row, prefix sums over the non-empty bins so that the mean over
// any xi interval (fractions of bins included) costs two look-ups.
class BinnedField {
 public:
  BinnedField(int nx, int ny, double xi_min, double eta_min, double h)
      : nx_(nx), ny_(ny), xi_min_(xi_min), eta_min_(eta_min), h_(h),
        sum_(std::size_t(nx) * std::size_t(ny), 0.0), count_(sum_.size(), 0.0) {}
  void add(double xi, double eta, double value) {
    const double u = (xi - xi_min_) / h_, w = (eta - eta_min_) / h_;
    if (u < 0.0 || w < 0.0 || u >= nx_ || w >= ny_) return;
    const std::size_t k = std::size_t(int(w)) * std::size_t(nx_) + std::size_t(int(u));
    sum_[k] += value;
    count_[k] += 1.0;
  }
  // Distributed: every rank's sums and counts added (before finish).
  void sum_over_ranks(const SumOverRanks& sum) {
    sum(sum_.data(), int(sum_.size()));
    sum(count_.data(), int(count_.size()));
  }
  // Bin means, then per row the prefix sums of the means and of the non-empty-bin count.
  void finish() {
    mean_prefix_.assign(std::size_t(nx_ + 1) * std::size_t(ny_), 0.0);
    full_prefix_.assign(mean_prefix_.size(), 0.0);
    for (int j = 0; j < ny_; ++j)
      for (int i = 0; i < nx_; ++i) {
        const std::size_t k = std::size_t(j) * std::size_t(nx_) + std::size_t(i);
        const std::size_t p = std::size_t(j) * std::size_t(nx_ + 1) + std::size_t(i);
        const bool has = count_[k] > 0.0;
        mean_prefix_[p + 1] = mean_prefix_[p] + (has ? sum_[k] / count_[k] : 0.0);
        full_prefix_[p + 1] = full_prefix_[p] + (has ? 1.0 : 0.0);
      }
  }
  int rows() const { return ny_; }
  double row_eta(int j) const { return eta_min_ + (j + 0.5) * h_; }
  // Mean tau over xi in [a, b) in row j (bins counted by the fraction covered); false when the
  // interval holds less than half a bin of data.
  bool mean(int j, double a, double b, double& out) const {
    const double s = cumulative(mean_prefix_, j, b) - cumulative(mean_prefix_, j, a);
    const double c = cumulative(full_prefix_, j, b) - cumulative(full_prefix_, j, a);
    if (c < 0.5) return false;
    out = s / c;
    return true;
  }

 private:
  double cumulative(const std::vector<double>& prefix, int j, double xi) const {
    const double u = std::clamp((xi - xi_min_) / h_, 0.0, double(nx_));
    const int i = std::min(int(u), nx_ - 1);
    const std::size_t p = std::size_t(j) * std::size_t(nx_ + 1) + std::size_t(i);
    return prefix[p] + (u - i) * (prefix[p + 1] - prefix[p]);
  }
  int nx_, ny_;
  double xi_min_, eta_min_, h_;
  std::vector<double> sum_, count_, mean_prefix_, full_prefix_;
};

// The two-sided edge filter at xi = edge in row j: mean tau over [edge - half, edge) (behind the
// front, reached by the shear wave) minus mean over [edge, edge + half) (ahead of it).
bool edge_jump(const BinnedField& f, int j, double edge, double half, double& jump) {
  double behind = 0.0, ahead = 0.0;
  if (!f.mean(j, edge - half, edge, behind) || !f.mean(j, edge, edge + half, ahead)) return false;
  jump = behind - ahead;
  return true;
}

}  // namespace

double mach_angle_of_speed(double v, double c_s) {
  return v > c_s ? std::asin(c_s / v) / kDeg : std::numeric_limits<double>::quiet_NaN();
}

double speed_of_mach_angle(double beta_degrees, double c_s) {
  return c_s / std::sin(beta_degrees * kDeg);
}

MachLine find_mach_line(const double* x, const double* y, const double* tau_max,
                        const std::uint8_t* material, std::size_t n, const MachSearch& where,
                        int side, const SumOverRanks* over_ranks) {
  MachLine line;
  const double h = where.spacing, run = where.run;
  if (!(h > 0.0) || !(run > 0.0)) return line;
  const double eta_min = 2.0 * h, eta_max = 0.5 * run;
  const int ny = int(std::floor((eta_max - eta_min) / h));
  if (ny < kMinRows) return line;
  const double xi_min = -1.5 * run;
  const int nx = int(std::ceil(2.0 * run / h));
  BinnedField field(nx, ny, xi_min, eta_min, h);
  // The crack's frame: xi along dir, eta along side x (dir rotated by +90 degrees).
  const double ex = where.dir_x, ey = where.dir_y;
  const double nx_ = -ey * side, ny_ = ex * side;
  std::vector<double> materials(256, 0.0);
  for (std::size_t p = 0; p < n; ++p) {
    const double dx = x[p] - where.tip_x, dy = y[p] - where.tip_y;
    const double xi = dx * ex + dy * ey, eta = dx * nx_ + dy * ny_;
    if (eta < eta_min || eta >= eta_min + ny * h || xi < xi_min || xi >= xi_min + nx * h) continue;
    field.add(xi, eta, tau_max[p]);
    materials[material[p]] += 1.0;
  }
  if (over_ranks) {
    field.sum_over_ranks(*over_ranks);
    (*over_ranks)(materials.data(), int(materials.size()));
  }
  field.finish();
  line.material = int(std::max_element(materials.begin(), materials.end()) - materials.begin());

  // 2. The straight front with the largest mean jump (filter half-width 2h across the line).
  const double half_across = 2.0 * h;
  double best = -std::numeric_limits<double>::infinity(), best_beta = 0.0, best_xi0 = 0.0;
  for (double beta_deg = kMinAngle; beta_deg <= kMaxAngle + 1e-9; beta_deg += 0.5) {
    const double beta = beta_deg * kDeg;
    const double cot = 1.0 / std::tan(beta), half = half_across / std::sin(beta);
    for (double xi0 = -0.5 * run; xi0 <= 0.5 * run; xi0 += h) {
      double sum = 0.0;
      int rows = 0;
      for (int j = 0; j < ny; ++j) {
        double jump = 0.0;
        if (!edge_jump(field, j, xi0 - field.row_eta(j) * cot, half, jump)) continue;
        sum += jump;
        ++rows;
      }
      if (rows >= kMinRows && sum / rows > best) {
        best = sum / rows;
        best_beta = beta;
        best_xi0 = xi0;
      }
    }
  }
  if (!(best > 0.0)) return line;

  // 3. The edge in every row within one filter width of that line, and a least-squares line.
  const double cot = 1.0 / std::tan(best_beta), half = half_across / std::sin(best_beta);
  std::vector<double> etas, xis;
  for (int j = 0; j < ny; ++j) {
    const double centre = best_xi0 - field.row_eta(j) * cot;
    double top = -std::numeric_limits<double>::infinity(), at = 0.0;
    for (double xc = centre - 2.0 * half; xc <= centre + 2.0 * half; xc += 0.25 * h) {
      double jump = 0.0;
      if (edge_jump(field, j, xc, half, jump) && jump > top) {
        top = jump;
        at = xc;
      }
    }
    if (top > -std::numeric_limits<double>::infinity()) {
      etas.push_back(field.row_eta(j));
      xis.push_back(at);
    }
  }
  const std::size_t m = etas.size();
  if (m < std::size_t(kMinRows)) return line;
  double me = 0.0, mx = 0.0;
  for (std::size_t k = 0; k < m; ++k) me += etas[k], mx += xis[k];
  me /= double(m), mx /= double(m);
  double see = 0.0, sex = 0.0;
  for (std::size_t k = 0; k < m; ++k) {
    see += (etas[k] - me) * (etas[k] - me);
    sex += (etas[k] - me) * (xis[k] - mx);
  }
  const double slope = sex / see;  // d xi / d eta = -cot(beta)
  double residual = 0.0;
  for (std::size_t k = 0; k < m; ++k) {
    const double r = xis[k] - (mx + slope * (etas[k] - me));
    residual += r * r;
  }
  // The fit's scatter, and the quarter-bin raster the edges are placed on (a uniform error of
  // h/4: variance (h/4)^2 / 12 per point), in quadrature.
  const double raster = 0.25 * h;
  const double slope_error = std::sqrt((residual / double(m - 2) + raster * raster / 12.0) / see);
  line.angle = std::atan2(1.0, -slope) / kDeg;
  // Only inside the searched range: a fit that leaves it did not follow one front.
  line.found = slope < 0.0 && line.angle >= kMinAngle && line.angle <= kMaxAngle;
  line.angle_error = slope_error / (1.0 + slope * slope) / kDeg;  // |d beta / d slope| s_slope
  line.origin = mx - slope * me;
  line.jump = best;
  line.rows = int(m);
  return line;
}

namespace {
double median(std::vector<double> v) {
  if (v.empty()) return -1.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}
}  // namespace

MachSummary summarize_mach(const std::vector<MachReading>& readings, int interface, double from,
                           double to) {
  bool any_inside = false;
  for (const MachReading& r : readings)
    any_inside = any_inside || (r.interface == interface && (r.left.found || r.right.found) &&
                                r.time >= from && r.time <= to);
  MachSummary out;
  std::vector<double> both, left, right, speed;
  for (const MachReading& r : readings) {
    if (r.interface != interface || !(r.left.found || r.right.found)) continue;
    if (any_inside && (r.time < from || r.time > to)) continue;
    ++out.readings;
    for (int k = 0; k < 2; ++k) {
      const MachLine& m = k == 0 ? r.left : r.right;
      if (!m.found) continue;
      both.push_back(m.angle);
      (k == 0 ? left : right).push_back(m.angle);
      speed.push_back(speed_of_mach_angle(m.angle, k == 0 ? r.c_s_left : r.c_s_right));
    }
  }
  out.angle = median(both);
  out.angle_left = median(left);
  out.angle_right = median(right);
  out.speed = median(speed);
  if (both.size() >= 2) {
    double mean = 0.0, var = 0.0;
    for (double a : both) mean += a;
    mean /= double(both.size());
    for (double a : both) var += (a - mean) * (a - mean);
    out.angle_spread = std::sqrt(var / double(both.size() - 1));
  }
  return out;
}

void write_mach_angles(const std::string& dir, const std::string& suffix,
                       const std::vector<MachReading>& readings, int interface) {
  std::string csv =
      "time,tip_x,tip_y,e11_speed,angle_left,angle_left_error,implied_speed_left,jump_left,"
      "origin_left,angle_right,angle_right_error,implied_speed_right,jump_right,origin_right,dir_x,"
      "dir_y\n";
  auto side = [](const MachLine& m, double c_s) {
    if (!m.found) return std::string("nan,nan,nan,nan,nan");
    return fmt::format("{:.4f},{:.4f},{:.6e},{:.6e},{:.6e}", m.angle, m.angle_error,
                       speed_of_mach_angle(m.angle, c_s), m.jump, m.origin);
  };
  for (const MachReading& r : readings)
    if (r.interface == interface)
      csv += fmt::format("{:.9e},{:.9e},{:.9e},{:.6e},{},{},{:.9f},{:.9f}\n", r.time, r.tip_x,
                         r.tip_y, r.speed, side(r.left, r.c_s_left), side(r.right, r.c_s_right),
                         r.dir_x, r.dir_y);
  write_file_atomic(dir + "/mach_angle" + suffix + ".csv", csv);
}

bool read_mach_angle(const CrackTracker& crack, double c_s, const Particles& P, const Grid& grid,
                     const std::vector<double>& shear_speed, double time, MachReading& out,
                     const SumOverRanks* sum) {
  const std::vector<CrackSample>& samples = crack.samples();
  // (Distributed: every rank reads, with or without particles of its own.)
  if (samples.empty() || (P.size() == 0 && !sum)) return false;
  const std::vector<double> v = crack.speeds();
  double speed = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t j = v.size(); j-- > 0;)
    if (!std::isnan(v[j])) {
      speed = v[j];
      break;
    }
  if (!(speed > c_s)) return false;
  std::size_t first = 0;
  while (first < v.size() && !(v[first] > c_s)) ++first;
  const double tip_s = samples.back().tip;
  MachSearch where;
  where.run = tip_s - samples[first].tip;
  crack.position(tip_s, where.tip_x, where.tip_y);
  const int i = std::clamp(grid.x.cell_of(where.tip_x), 0, grid.x.cells - 1);
  const int j = std::clamp(grid.y.cell_of(where.tip_y), 0, grid.y.cells - 1);
  where.spacing = std::max(grid.x.width(i), grid.y.width(j));
  const double back = std::min(where.spacing, tip_s);
  if (!(where.run > 0.0) || !(back > 0.0)) return false;
  double bx = 0.0, by = 0.0;
  crack.position(tip_s - back, bx, by);
  const double len = std::hypot(where.tip_x - bx, where.tip_y - by);
  where.dir_x = (where.tip_x - bx) / len;
  where.dir_y = (where.tip_y - by) / len;
  std::vector<double> tau(P.size());
  for (std::size_t p = 0; p < P.size(); ++p) {
    const double a = 0.5 * (P.sxx[p] - P.syy[p]);
    tau[p] = std::sqrt(a * a + P.sxy[p] * P.sxy[p]);  // (sigma_1 - sigma_2) / 2, theory E13
  }
  out = MachReading{};
  out.time = time;
  out.tip_x = where.tip_x, out.tip_y = where.tip_y;
  out.dir_x = where.dir_x, out.dir_y = where.dir_y;
  out.speed = speed;
  out.left = find_mach_line(P.x.data(), P.y.data(), tau.data(), P.material.data(), P.size(), where, +1, sum);
  out.right = find_mach_line(P.x.data(), P.y.data(), tau.data(), P.material.data(), P.size(), where, -1, sum);
  auto shear = [&](const MachLine& m) {
    return m.material >= 0 && std::size_t(m.material) < shear_speed.size() ? shear_speed[std::size_t(m.material)] : c_s;
  };
  out.c_s_left = shear(out.left);
  out.c_s_right = shear(out.right);
  return true;
}

}  // namespace rupture

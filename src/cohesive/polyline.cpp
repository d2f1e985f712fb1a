// rupture/cohesive/polyline.cpp
#include "cohesive/polyline.hpp"

#include <algorithm>
#include <cmath>

namespace rupture {

double Polyline::piece_length(std::size_t i) const {
  const std::size_t j = piece_end(i);
  return std::hypot(x[j] - x[i], y[j] - y[i]);
}

double Polyline::length() const {
  double L = 0.0;
  for (std::size_t i = 0; i < num_pieces(); ++i) L += piece_length(i);
  return L;
}

LineNodes discretize(const Polyline& line, int segments) {
  const std::size_t pieces = line.num_pieces();
  // Segments per piece: proportional to length, at least one, summing to `segments`.
  std::vector<int> n(pieces, 1);
  const double L = line.length();
  int given = int(pieces);
  std::vector<std::pair<double, std::size_t>> remainder;
  for (std::size_t i = 0; i < pieces; ++i) {
    const double share = std::max(0.0, double(segments) * line.piece_length(i) / L - 1.0);
    const int whole = int(std::floor(share));
    n[i] += whole;
    given += whole;
    remainder.push_back({share - whole, i});
  }
  std::stable_sort(remainder.begin(), remainder.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  for (std::size_t k = 0; given < segments && k < remainder.size(); ++k, ++given)
    ++n[remainder[k].second];
  LineNodes out;
  double s = 0.0;
  for (std::size_t i = 0; i < pieces; ++i) {
    const std::size_t j = line.piece_end(i);
    const double x0 = line.x[i], y0 = line.y[i], x1 = line.x[j], y1 = line.y[j];
    const double len = line.piece_length(i);
    for (int k = 0; k < n[i]; ++k) {
      out.x.push_back(x0 + (x1 - x0) * double(k) / double(n[i]));
      out.y.push_back(y0 + (y1 - y0) * double(k) / double(n[i]));
      out.s.push_back(s + len * double(k) / double(n[i]));
    }
    s += len;
  }
  if (!line.closed) {
    out.x.push_back(line.x.back());
    out.y.push_back(line.y.back());
    out.s.push_back(s);
  }
  return out;
}

LineProjection project(const Polyline& line, double px, double py) {
  LineProjection best;
  best.distance = INFINITY;
  double s0 = 0.0;
  const std::size_t pieces = line.num_pieces();
  for (std::size_t i = 0; i < pieces; ++i) {
    const std::size_t j = line.piece_end(i);
    const double dx = line.x[j] - line.x[i], dy = line.y[j] - line.y[i];
    const double len = std::hypot(dx, dy);
    const double tx = dx / len, ty = dy / len;
    const double along = (px - line.x[i]) * tx + (py - line.y[i]) * ty;
    const double a = std::clamp(along, 0.0, len);
    const double d = std::hypot(px - (line.x[i] + a * tx), py - (line.y[i] + a * ty));
    if (d < best.distance) {
      best.distance = d;
      best.s = s0 + a;
      best.nx = -ty, best.ny = tx;
      best.beyond = 0.0;
      if (!line.closed && i == 0 && along < 0.0) best.beyond = -along;
      if (!line.closed && i + 1 == pieces && along > len) best.beyond = along - len;
    }
    s0 += len;
  }
  return best;
}

void point_at(const Polyline& line, double s, double& x, double& y) {
  double s0 = 0.0;
  const std::size_t pieces = line.num_pieces();
  for (std::size_t i = 0; i < pieces; ++i) {
    const std::size_t j = line.piece_end(i);
    const double len = line.piece_length(i);
    if (s <= s0 + len || i + 1 == pieces) {
      const double f = std::clamp((s - s0) / len, 0.0, 1.0);
      x = line.x[i] + f * (line.x[j] - line.x[i]);
      y = line.y[i] + f * (line.y[j] - line.y[i]);
      return;
    }
    s0 += len;
  }
}

namespace {
double cross(double ax, double ay, double bx, double by) {
  return ax * by - ay * bx;
}
bool on_segment(double px, double py, double ax, double ay, double bx, double by) {
  return std::min(ax, bx) <= px && px <= std::max(ax, bx) && std::min(ay, by) <= py &&
         py <= std::max(ay, by);
}
int orientation(double ax, double ay, double bx, double by, double cx, double cy) {
  const double v = cross(bx - ax, by - ay, cx - ax, cy - ay);
  const double scale =
      std::max({std::fabs(bx - ax), std::fabs(by - ay), std::fabs(cx - ax), std::fabs(cy - ay)});
  if (std::fabs(v) <= 1e-12 * scale * scale) return 0;
  return v > 0 ? 1 : -1;
}
}  // namespace

bool segments_intersect(double ax0, double ay0, double ax1, double ay1, double bx0, double by0,
                        double bx1, double by1) {
  const int o1 = orientation(ax0, ay0, ax1, ay1, bx0, by0);
  const int o2 = orientation(ax0, ay0, ax1, ay1, bx1, by1);
  const int o3 = orientation(bx0, by0, bx1, by1, ax0, ay0);
  const int o4 = orientation(bx0, by0, bx1, by1, ax1, ay1);
  if (o1 != o2 && o3 != o4) return true;
  if (o1 == 0 && on_segment(bx0, by0, ax0, ay0, ax1, ay1)) return true;
  if (o2 == 0 && on_segment(bx1, by1, ax0, ay0, ax1, ay1)) return true;
  if (o3 == 0 && on_segment(ax0, ay0, bx0, by0, bx1, by1)) return true;
  if (o4 == 0 && on_segment(ax1, ay1, bx0, by0, bx1, by1)) return true;
  return false;
}

bool segments_cross(double ax0, double ay0, double ax1, double ay1, double bx0, double by0,
                    double bx1, double by1) {
  const int o1 = orientation(ax0, ay0, ax1, ay1, bx0, by0);
  const int o2 = orientation(ax0, ay0, ax1, ay1, bx1, by1);
  const int o3 = orientation(bx0, by0, bx1, by1, ax0, ay0);
  const int o4 = orientation(bx0, by0, bx1, by1, ax1, ay1);
  return o1 * o2 < 0 && o3 * o4 < 0;
}

PieceCrossing first_self_crossing(const Polyline& line) {
  const std::size_t n = line.num_pieces();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const bool adjacent = j == i + 1 || (line.closed && i == 0 && j + 1 == n);
      if (adjacent) continue;
      const std::size_t i1 = line.piece_end(i), j1 = line.piece_end(j);
      if (segments_intersect(line.x[i], line.y[i], line.x[i1], line.y[i1], line.x[j], line.y[j],
                             line.x[j1], line.y[j1]))
        return {int(i), int(j)};
    }
  return {};
}

}  // namespace rupture

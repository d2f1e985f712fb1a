// rupture/particles/particles.cpp
#include "particles/particles.hpp"

#include <cmath>
#include <type_traits>
#include <utility>

namespace rupture {

// Each operation below walks ParticleArrays (particles.hpp); a store holds the viscous arrays
// only while viscous_on.

void Particles::resize(std::size_t n) {
  for_each_particle_array([&](const auto& a) {
    if (a.kind == ParticleArrayKind::every || viscous_on) (this->*a.member).resize(n, 0);
  });
}

void Particles::enable_viscous() {
  viscous_on = true;
  for_each_particle_array([&](const auto& a) {
    if (a.kind == ParticleArrayKind::viscous) (this->*a.member).resize(size(), 0);
  });
}

namespace {
template <class T>
void permute_one(std::vector<T>& v, const std::vector<std::uint32_t>& order, std::vector<T>& tmp) {
  const long n = long(order.size());
  // The buffers swap roles: keep the larger capacity, so arrays that grow by appends (particles
  // moving between nested levels) are not re-allocated after every sort.
  if (tmp.capacity() < v.capacity()) tmp.reserve(v.capacity());
  tmp.resize(order.size());
#pragma omp parallel for schedule(static)
  for (long k = 0; k < n; ++k) tmp[std::size_t(k)] = v[order[std::size_t(k)]];
  v.swap(tmp);
}

// The scratch of one element type (double: the caller's, kept between calls).
template <class T>
std::vector<T>& scratch_of(std::vector<double>& doubles) {
  if constexpr (std::is_same_v<T, double>) {
    return doubles;
  } else {
    thread_local std::vector<T> tmp;
    return tmp;
  }
}
}  // namespace

void Particles::permute(const std::vector<std::uint32_t>& order, std::vector<double>& scratch) {
  for_each_particle_array([&](const auto& a) {
    using T = typename std::decay_t<decltype(a)>::value_type;
    if (a.kind == ParticleArrayKind::every || viscous_on) permute_one(this->*a.member, order, scratch_of<T>(scratch));
  });
}

namespace {
template <class T>
void move_one(std::vector<T>& from, std::vector<T>& to, const std::vector<unsigned char>& mark) {
  std::size_t kept = 0;
  for (std::size_t p = 0; p < from.size(); ++p) {
    if (mark[p]) {
      to.push_back(from[p]);
    } else {
      from[kept++] = from[p];
    }
  }
  from.resize(kept);
}
}  // namespace

std::size_t Particles::move_marked(const std::vector<unsigned char>& mark, Particles& to) {
  const std::size_t before = size();
  if (viscous_on || to.viscous_on) enable_viscous(), to.enable_viscous();  // both stores of a damped run carry it
  for_each_particle_array([&](const auto& a) {
    if (a.kind == ParticleArrayKind::every || viscous_on) move_one(this->*a.member, to.*a.member, mark);
  });
  return before - size();
}

void Particles::append_copy(const Particles& from) {
  const std::size_t n = size() + from.size();
  if (from.viscous_on && !viscous_on) enable_viscous();
  for_each_particle_array([&](const auto& a) {
    if (a.kind == ParticleArrayKind::viscous && !viscous_on) return;
    auto& to = this->*a.member;
    const auto& v = from.*a.member;
    if (a.kind == ParticleArrayKind::viscous && !from.viscous_on)
      to.resize(n, 0);  // an undamped store's particles carry no viscous stress
    else
      to.insert(to.end(), v.begin(), v.end());
  });
}

void Particles::pack(std::size_t p, double* out) const {
  std::size_t k = 0;
  for_each_particle_array([&](const auto& a) {
    const bool held = a.kind == ParticleArrayKind::every || viscous_on;
    out[k++] = held ? double((this->*a.member)[p]) : 0.0;
  });
}

void Particles::push_packed(const double* in) {
  std::size_t k = 0;
  for_each_particle_array([&](const auto& a) {
    using T = typename std::decay_t<decltype(a)>::value_type;
    const double v = in[k++];
    if (a.kind == ParticleArrayKind::every || viscous_on) (this->*a.member).push_back(T(v));
  });
}

void seed_rectangle(Particles& p, const double min[2], const double max[2], double h, int ppc,
                    double density, std::uint8_t field, std::uint8_t material,
                    const double velocity[2], const double origin[2]) {
  const long cx = std::lround((max[0] - min[0]) / h);
  const long cy = std::lround((max[1] - min[1]) / h);
  const double side = h / ppc;
  const long ix = std::lround((min[0] - origin[0]) / h) * ppc;  // first sub-cell on the lattice
  const long iy = std::lround((min[1] - origin[1]) / h) * ppc;
  const long nx = cx * ppc, ny = cy * ppc;
  const std::size_t start = p.size();
  p.resize(start + std::size_t(nx * ny));
  std::size_t k = start;
  for (long j = 0; j < ny; ++j) {
    for (long i = 0; i < nx; ++i, ++k) {
      p.x[k] = p.x0[k] = lattice_centre(origin[0], side, ix + i);
      p.y[k] = p.y0[k] = lattice_centre(origin[1], side, iy + j);
      p.vx[k] = velocity[0];
      p.vy[k] = velocity[1];
      p.volume0[k] = side * side;
      p.mass[k] = density * side * side;
      p.half_x[k] = p.half_y[k] = 0.5 * side;
      p.field[k] = field;
      p.material[k] = material;
      p.id[k] = std::uint32_t(k);
    }
  }
}

}  // namespace rupture

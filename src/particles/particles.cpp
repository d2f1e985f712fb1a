// rupture/particles/particles.cpp
#include "particles/particles.hpp"

#include <cmath>
#include <utility>

namespace rupture {

void Particles::resize(std::size_t n) {
  for (auto* v : {&x, &y, &vx, &vy, &mass, &volume0, &half_x, &half_y, &sxx, &syy, &sxy, &x0, &y0}) {
    v->resize(n, 0.0);
  }
  field.resize(n, 0);
  material.resize(n, 0);
  id.resize(n, 0);
  if (viscous_on)
    for (auto* v : {&vsxx, &vsyy, &vsxy}) v->resize(n, 0.0);
}

void Particles::enable_viscous() {
  viscous_on = true;
  for (auto* v : {&vsxx, &vsyy, &vsxy}) v->resize(size(), 0.0);
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
}  // namespace

void Particles::permute(const std::vector<std::uint32_t>& order, std::vector<double>& scratch) {
  for (auto* v : {&x, &y, &vx, &vy, &mass, &volume0, &half_x, &half_y, &sxx, &syy, &sxy, &x0, &y0}) {
    permute_one(*v, order, scratch);
  }
  thread_local std::vector<std::uint8_t> tmp8;
  permute_one(field, order, tmp8);
  permute_one(material, order, tmp8);
  thread_local std::vector<std::uint32_t> tmp32;
  permute_one(id, order, tmp32);
  if (viscous_on)
    for (auto* v : {&vsxx, &vsyy, &vsxy}) permute_one(*v, order, scratch);
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
  for (auto [a, b] : {std::pair{&x, &to.x}, {&y, &to.y}, {&vx, &to.vx}, {&vy, &to.vy},
                      {&mass, &to.mass}, {&volume0, &to.volume0},
                      {&half_x, &to.half_x}, {&half_y, &to.half_y}, {&sxx, &to.sxx},
                      {&syy, &to.syy}, {&sxy, &to.sxy}, {&x0, &to.x0}, {&y0, &to.y0}}) {
    move_one(*a, *b, mark);
  }
  move_one(field, to.field, mark);
  move_one(material, to.material, mark);
  move_one(id, to.id, mark);
  if (viscous_on || to.viscous_on) {  // both stores of a damped run carry it
    enable_viscous(), to.enable_viscous();
    for (auto [a, b] : {std::pair{&vsxx, &to.vsxx}, {&vsyy, &to.vsyy}, {&vsxy, &to.vsxy}})
      move_one(*a, *b, mark);
    to.enable_viscous();
  }
  return before - size();
}

void Particles::append_copy(const Particles& from) {
  const auto add = [](auto& to, const auto& v) { to.insert(to.end(), v.begin(), v.end()); };
  add(x, from.x), add(y, from.y), add(vx, from.vx), add(vy, from.vy), add(mass, from.mass);
  add(volume0, from.volume0), add(half_x, from.half_x), add(half_y, from.half_y);
  add(sxx, from.sxx), add(syy, from.syy), add(sxy, from.sxy);
  add(x0, from.x0), add(y0, from.y0);
  add(field, from.field), add(material, from.material), add(id, from.id);
  if (viscous_on || from.viscous_on) {
    const std::size_t n = x.size();
    viscous_on = true;
    for (auto [to, v] : {std::pair{&vsxx, &from.vsxx}, {&vsyy, &from.vsyy}, {&vsxy, &from.vsxy}}) {
      to->resize(n - from.size(), 0.0);
      if (v->empty()) to->resize(n, 0.0); else add(*to, *v);
    }
  }
}

void Particles::pack(std::size_t p, double* out) const {
  const double v[kPacked] = {x[p],   y[p],   vx[p],  vy[p],           mass[p],
                             volume0[p], half_x[p], half_y[p], sxx[p], syy[p],
                             sxy[p], double(field[p]), double(material[p]), double(id[p]),
                             viscous_on ? vsxx[p] : 0.0, viscous_on ? vsyy[p] : 0.0,
                             viscous_on ? vsxy[p] : 0.0, x0[p], y0[p]};
  for (std::size_t k = 0; k < kPacked; ++k) out[k] = v[k];
}

void Particles::push_packed(const double* in) {
  std::vector<double>* d[11] = {&x, &y, &vx, &vy, &mass, &volume0, &half_x, &half_y, &sxx, &syy, &sxy};
  for (std::size_t k = 0; k < 11; ++k) d[k]->push_back(in[k]);
  x0.push_back(in[17]), y0.push_back(in[18]);
  field.push_back(std::uint8_t(in[11]));
  material.push_back(std::uint8_t(in[12]));
  id.push_back(std::uint32_t(in[13]));
  if (viscous_on) vsxx.push_back(in[14]), vsyy.push_back(in[15]), vsxy.push_back(in[16]);
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

// rupture/particles/particles.hpp
// Structure-of-arrays particle store (SI: m, m/s, kg, m^3 per unit thickness -> m^2, Pa).
// Every array has size(); index p is one material point. The solver re-sorts particles by
// cell (solver/step.hpp), so an index is not stable in time: `id` is. The state is the in-plane
// Cauchy stress: for the linear elastic materials (material/elastic.hpp) the strain, sigma_zz
// and the current area V = V0 (1 + tr eps) follow from it and the particle's material, so they
// are not stored (each array costs every particle loop that streams it). `field` is the
// velocity field the particle maps to (one per body), `material` indexes the material table.
#pragma once
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace rupture {

// Which particles an array holds a value for: every one, or (viscous) every one while the store
// carries the Kelvin-Voigt stress (Particles::viscous_on), none otherwise.
enum class ParticleArrayKind : unsigned char { every, viscous };

// Every array is listed once, in ParticleArrays below: the operations over all of them (resize,
// permute, moving and appending particles, packing one for another rank, the checkpoint and its
// checks, the bytes per particle) walk that list, so an array added there is carried by all.
struct Particles {
  std::vector<double> x, y;            // position, m
  std::vector<double> vx, vy;          // velocity, m/s
  std::vector<double> mass;            // kg (per unit thickness)
  std::vector<double> volume0;         // initial area (volume per unit thickness), m^2
  std::vector<double> half_x, half_y;  // GIMP half-widths l_p, m (fixed: uGIMP)
  std::vector<double> sxx, syy, sxy;       // in-plane Cauchy stress, Pa
  std::vector<std::uint8_t> field;         // velocity field (body) id
  std::vector<std::uint8_t> material;      // material id
  std::vector<std::uint32_t> id;           // creation index: identity across re-sorting
  // Reference position X (where the particle was made, t = 0), m: the displacement u = x - X
  // that fracture/ needs for the J-integral's du/dx (rotation included, which the stress does
  // not give). No step loop streams it; sorting, migration and checkpoints carry it.
  std::vector<double> x0, y0;
  // Kelvin-Voigt viscous stress eta C : eps_dot of the last stress update, Pa (in-plane), which
  // the next internal force adds to the elastic stress (material/elastic.hpp: kelvin_voigt).
  // Empty unless a material is damped (enable_viscous); then of size(), and every operation
  // below carries it.
  std::vector<double> vsxx, vsyy, vsxy;
  bool viscous() const { return viscous_on; }
  void enable_viscous();  // sizes the viscous arrays (zeros) and keeps them from now on
  bool viscous_on = false;

  std::size_t size() const { return x.size(); }
  void resize(std::size_t n);
  // Bytes held per particle by the arrays (with the viscous ones: a damped run's).
  static constexpr std::size_t bytes_per_particle(bool viscous = false);
  // Reorders every array so that the particle now at index k is the one that was at
  // order[k]. `scratch` is reused between calls to avoid allocating in the time loop.
  void permute(const std::vector<std::uint32_t>& order, std::vector<double>& scratch);
  // Appends the particles with mark[p] != 0 to `to`, in index order, and removes them from
  // this store, keeping the others' order; returns how many moved.
  std::size_t move_marked(const std::vector<unsigned char>& mark, Particles& to);
  // Appends a copy of every particle of `from`.
  void append_copy(const Particles& from);
  // One particle as kPacked doubles (every array in ParticleArrays' order; the integers are
  // exact in a double), for sending it to another process (parallel/halo.hpp), and back; the
  // viscous stress travels too (zeros when the store has none).
  static constexpr std::size_t kPacked = 19;
  void pack(std::size_t p, double* out) const;
  void push_packed(const double* in);
};

// One entry of the list: the array's name (the checkpoint's), the member, its kind.
template <class T>
struct ParticleArray {
  using value_type = T;
  const char* name;
  std::vector<T> Particles::*member;
  ParticleArrayKind kind;
};

// The list, in the checkpoint's order (run/checkpoint.cpp): for_each_particle_array(f) calls
// f(entry) for each entry of ParticleArrays.
inline constexpr auto ParticleArrays = std::make_tuple(
    ParticleArray<double>{"x", &Particles::x, ParticleArrayKind::every},
    ParticleArray<double>{"y", &Particles::y, ParticleArrayKind::every},
    ParticleArray<double>{"vx", &Particles::vx, ParticleArrayKind::every},
    ParticleArray<double>{"vy", &Particles::vy, ParticleArrayKind::every},
    ParticleArray<double>{"mass", &Particles::mass, ParticleArrayKind::every},
    ParticleArray<double>{"volume0", &Particles::volume0, ParticleArrayKind::every},
    ParticleArray<double>{"half_x", &Particles::half_x, ParticleArrayKind::every},
    ParticleArray<double>{"half_y", &Particles::half_y, ParticleArrayKind::every},
    ParticleArray<double>{"sxx", &Particles::sxx, ParticleArrayKind::every},
    ParticleArray<double>{"syy", &Particles::syy, ParticleArrayKind::every},
    ParticleArray<double>{"sxy", &Particles::sxy, ParticleArrayKind::every},
    ParticleArray<std::uint8_t>{"field", &Particles::field, ParticleArrayKind::every},
    ParticleArray<std::uint8_t>{"material", &Particles::material, ParticleArrayKind::every},
    ParticleArray<std::uint32_t>{"id", &Particles::id, ParticleArrayKind::every},
    ParticleArray<double>{"x0", &Particles::x0, ParticleArrayKind::every},
    ParticleArray<double>{"y0", &Particles::y0, ParticleArrayKind::every},
    ParticleArray<double>{"vsxx", &Particles::vsxx, ParticleArrayKind::viscous},
    ParticleArray<double>{"vsyy", &Particles::vsyy, ParticleArrayKind::viscous},
    ParticleArray<double>{"vsxy", &Particles::vsxy, ParticleArrayKind::viscous});

template <class F>
constexpr void for_each_particle_array(F&& f) {
  std::apply([&](const auto&... entry) { (f(entry), ...); }, ParticleArrays);
}

constexpr std::size_t Particles::bytes_per_particle(bool viscous) {
  std::size_t bytes = 0;
  for_each_particle_array([&](const auto& a) {
    if (a.kind == ParticleArrayKind::every || viscous) bytes += sizeof(typename std::decay_t<decltype(a)>::value_type);
  });
  return bytes;
}
static_assert(Particles::kPacked == std::tuple_size_v<std::decay_t<decltype(ParticleArrays)>>,
              "kPacked: one double per array of ParticleArrays");

// The centre of sub-cell k (side `side`) of a uniform lattice starting at `origin` (m): every
// seeding path computes a particle position this way, from the grid's origin and the global
// index, so one point gets one number whichever body or axis asks for it.
inline double lattice_centre(double origin, double side, long k) {
  return origin + (double(k) + 0.5) * side;
}

// Fill the rectangle [xmin,xmax]x[ymin,ymax] (whole cells of size h, on the lines of the grid
// whose origin is `origin`) with ppc x ppc particles per cell, each a square of side h/ppc, at
// rest and stress-free. Appends to `p`.
void seed_rectangle(Particles& p, const double min[2], const double max[2], double h, int ppc,
                    double density, std::uint8_t field, std::uint8_t material,
                    const double velocity[2], const double origin[2]);

}  // namespace rupture

// Tests of particles/particles.hpp: every array of the store is on its one list (ParticleArrays),
// and every operation over the arrays carries each of them with its particle: resize, permute,
// move_marked (damped stores too), append_copy, pack and push_packed, the bytes per particle.
// The checks walk the list, so an array added to it is checked by every test here; an array
// added to the struct but not to the list fails the first test.
#include <gtest/gtest.h>

#include <numeric>
#include <string_view>

#include "particles/particles.hpp"

using namespace rupture;

namespace {

// The value array a holds for the particle with id i: distinct per array and particle, exact in
// every element type (the integer arrays hold small numbers).
template <class T>
T value_of(std::size_t array, std::uint32_t i) {
  if constexpr (std::is_floating_point_v<T>)
    return T(1000.0 * double(array) + double(i) + 0.25);
  else
    return T((7 * array + i) % 200);
}

// n particles, ids 0..n-1, every array filled by value_of (the viscous ones when damped).
Particles made(std::size_t n, bool damped) {
  Particles p;
  if (damped) p.enable_viscous();
  p.resize(n);
  std::iota(p.id.begin(), p.id.end(), 0u);
  std::size_t k = 0;
  for_each_particle_array([&](const auto& a) {
    using T = typename std::decay_t<decltype(a)>::value_type;
    const std::size_t array = k++;
    if (std::string_view(a.name) == "id") return;
    if (a.kind == ParticleArrayKind::viscous && !damped) return;
    for (std::size_t q = 0; q < n; ++q) (p.*a.member)[q] = value_of<T>(array, std::uint32_t(q));
  });
  return p;
}

// What the viscous arrays of a store must hold: nothing (undamped), zeros (the particles came
// from an undamped store into a damped one), or their particles' values.
enum class Viscous { none, zeros, values };

// Every array of p holds one value per particle (the viscous ones as `viscous` says) and each
// particle's values are those of its id.
void expect_carried(const Particles& p, Viscous viscous) {
  std::size_t k = 0;
  for_each_particle_array([&](const auto& a) {
    using T = typename std::decay_t<decltype(a)>::value_type;
    const std::size_t array = k++;
    const auto& v = p.*a.member;
    if (a.kind == ParticleArrayKind::viscous && viscous == Viscous::none) {
      EXPECT_TRUE(v.empty()) << a.name;
      return;
    }
    ASSERT_EQ(v.size(), p.size()) << a.name;
    if (std::string_view(a.name) == "id") return;
    if (a.kind == ParticleArrayKind::viscous && viscous == Viscous::zeros) {
      for (std::size_t q = 0; q < p.size(); ++q) EXPECT_EQ(v[q], T(0)) << a.name << " at " << q;
      return;
    }
    for (std::size_t q = 0; q < p.size(); ++q) EXPECT_EQ(v[q], value_of<T>(array, p.id[q])) << a.name << " at " << q;
  });
}

}  // namespace

TEST(Particles, every_array_of_the_struct_is_on_the_list) {
  // Each array is a std::vector (all of one size); the struct holds them and one flag. An
  // array added to the struct but not to ParticleArrays makes the struct larger than the list.
  EXPECT_EQ(sizeof(Particles), Particles::kPacked * sizeof(std::vector<double>) + alignof(std::vector<double>));
  EXPECT_EQ(Particles::bytes_per_particle(), 13 * sizeof(double) + 2 + 4);
  EXPECT_EQ(Particles::bytes_per_particle(true), 16 * sizeof(double) + 2 + 4);
}

TEST(Particles, permute_carries_every_array) {
  for (const bool damped : {false, true}) {
    Particles p = made(7, damped);
    std::vector<double> scratch;
    p.permute({3, 0, 6, 1, 5, 2, 4}, scratch);
    EXPECT_EQ(p.id, (std::vector<std::uint32_t>{3, 0, 6, 1, 5, 2, 4}));
    expect_carried(p, damped ? Viscous::values : Viscous::none);
  }
}

TEST(Particles, move_marked_carries_every_array_damped_or_not) {
  for (const bool damped : {false, true}) {
    for (const bool to_damped : {false, true}) {
      Particles p = made(9, damped), to;
      if (to_damped) to.enable_viscous();
      const std::vector<unsigned char> mark{0, 1, 1, 0, 0, 1, 0, 0, 1};
      EXPECT_EQ(p.move_marked(mark, to), 4u);
      EXPECT_EQ(p.id, (std::vector<std::uint32_t>{0, 3, 4, 6, 7}));
      EXPECT_EQ(to.id, (std::vector<std::uint32_t>{1, 2, 5, 8}));
      // Both stores of a damped run carry the viscous stress; the particles of an undamped one
      // arrive with none (zeros).
      const bool both = damped || to_damped;
      EXPECT_EQ(p.viscous(), both);
      EXPECT_EQ(to.viscous(), both);
      const Viscous held = damped ? Viscous::values : both ? Viscous::zeros : Viscous::none;
      expect_carried(p, held);
      expect_carried(to, held);
    }
  }
}

TEST(Particles, append_copy_and_packing_carry_every_array) {
  for (const bool damped : {false, true}) {
    const Particles from = made(5, damped);
    Particles p;
    if (damped) p.enable_viscous();
    p.append_copy(from);
    expect_carried(p, damped ? Viscous::values : Viscous::none);
    // One particle at a time, as a rank sends it: kPacked doubles each.
    Particles q;
    if (damped) q.enable_viscous();
    std::vector<double> rec(Particles::kPacked);
    for (std::size_t k = 0; k < from.size(); ++k) {
      from.pack(k, rec.data());
      q.push_packed(rec.data());
    }
    expect_carried(q, damped ? Viscous::values : Viscous::none);
    EXPECT_EQ(q.size(), from.size());
  }
}

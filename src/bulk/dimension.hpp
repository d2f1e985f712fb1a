// rupture/bulk/dimension.hpp
// What the dimension fixes at compile time. The bulk kernels (this folder) are templates on
// `int dim` (2 or 3, in the manner of deal.II's dim and CB-Geo's Tdim), explicitly instantiated
// in .cpp files; nothing above them chooses a dimension but the place a run starts. Fixed here:
//  - a symmetric tensor's stored components and their order (SymmetricComponents): 2D xx, yy,
//    xy (the particles' sxx, syy, sxy); 3D xx, yy, zz, yz, xz, xy (Voigt's order). Normal
//    components come first, so component i < dim is the diagonal (i, i);
//  - the GIMP stencil: 3 nodes per axis (lp <= h/2, theory E3), 3^dim nodes, node n at the
//    offsets n % 3, (n / 3) % 3, n / 9 from the stencil's first node along x, y, z.
#pragma once
#include <array>
#include <cstddef>

namespace rupture {

template <int dim>
struct SymmetricComponents;

template <>
struct SymmetricComponents<2> {
  static constexpr int kCount = 3;
  static constexpr std::array<int, kCount> row = {0, 1, 0};
  static constexpr std::array<int, kCount> col = {0, 1, 1};
  static constexpr std::array<const char*, kCount> name = {"xx", "yy", "xy"};
};

template <>
struct SymmetricComponents<3> {
  static constexpr int kCount = 6;
  static constexpr std::array<int, kCount> row = {0, 1, 2, 1, 0, 0};
  static constexpr std::array<int, kCount> col = {0, 1, 2, 2, 2, 1};
  static constexpr std::array<const char*, kCount> name = {"xx", "yy", "zz", "yz", "xz", "xy"};
};

// The stored components of a symmetric dim x dim tensor (stress, strain): 3 or 6.
template <int dim>
inline constexpr int kSymmetric = SymmetricComponents<dim>::kCount;

// The component holding (i, j) (either order).
template <int dim>
constexpr int symmetric_index(int i, int j) {
  for (int c = 0; c < kSymmetric<dim>; ++c) {
    const int r = SymmetricComponents<dim>::row[std::size_t(c)];
    const int s = SymmetricComponents<dim>::col[std::size_t(c)];
    if ((r == i && s == j) || (r == j && s == i)) return c;
  }
  return -1;
}

// Nodes of a GIMP stencil: 3 per axis.
template <int dim>
inline constexpr int kStencilNodes = dim == 2 ? 9 : 27;

// Offset of stencil node n from the stencil's first node along axis d.
template <int dim>
constexpr int stencil_offset(int n, int d) {
  return d == 0 ? n % 3 : (d == 1 ? (n / 3) % 3 : n / 9);
}

}  // namespace rupture

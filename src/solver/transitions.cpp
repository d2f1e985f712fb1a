// rupture/solver/transitions.cpp
// The transitions between nested levels (solver/levels.hpp): condense_to_dofs after every
// scatter, spread_to_slaves before every gather, over the levels' arrays in one pass per
// group of columns.
#include <algorithm>
#include <initializer_list>

#include "solver/levels.hpp"
#include "solver/nested_phases.hpp"

namespace rupture::detail {
namespace {
// Fields are whole-lattice on every level: element of (field f, node n) is start[f] + n.
// One column per (field, array) of `arrays`: column c's array on level l starts at
// base[c * levels + l]. The transitions treat up to kMaxColumns columns in one pass, so each
// term's indices are read once for all of them; more columns (many fields) go in chunks of
// kMaxColumns, which gives the same sums (every column is independent of the others).
constexpr std::size_t kMaxColumns = 16;

// A level's nodal array: one of its fields' (GridFields) or of its loads' (LoadState: the same
// layout as the fields).
std::vector<double>& array_of(State& s, NodalArray a) { return s.fields.*a; }
std::vector<double>& array_of(State& s, LoadArray a) { return s.loads.*a; }

template <class Array>
std::size_t column_bases(RunState& n, std::initializer_list<Array> arrays, std::vector<double*>& base) {
  const std::size_t levels = n.levels.size(), fields = std::size_t(n.levels[0].fields.num_fields);
  const std::size_t columns = fields * arrays.size();
  base.resize(columns * levels);
  std::size_t c = 0;
  for (std::size_t f = 0; f < fields; ++f)
    for (Array a : arrays) {
      for (std::size_t l = 0; l < levels; ++l) {
        State& s = n.levels[l];
        base[c * levels + l] = array_of(s, a).data() + s.fields.start[f];
      }
      ++c;
    }
  return columns;
}

}  // namespace

static void condense_columns(RunState& n, double* const* base, std::size_t columns);
static void spread_columns(RunState& n, double* const* base, std::size_t columns);

// grid/nested.hpp's condense_to_dofs over the levels' arrays: every DOF adds c * (slave's value) of
// the slaves it serves, in slave order (the transposed terms: RunState::dof_start), so the
// threads split the DOFs without sharing one and the sums are those of a loop over the
// slaves; then the slaves are cleared.
template <class Array>
void condense_arrays(RunState& n, std::initializer_list<Array> arrays) {
  thread_local std::vector<double*> base_store;
  const std::size_t all = column_bases(n, arrays, base_store), levels = n.levels.size();
  for (std::size_t first = 0; first < all; first += kMaxColumns)
    condense_columns(n, base_store.data() + first * levels, std::min(kMaxColumns, all - first));
}

void condense_to_dofs(RunState& n, std::initializer_list<NodalArray> arrays) { condense_arrays(n, arrays); }
void condense_to_dofs(RunState& n, std::initializer_list<LoadArray> arrays) { condense_arrays(n, arrays); }

// The same over `columns` (at most kMaxColumns) columns from `base`.
void condense_columns(RunState& n, double* const* base, std::size_t columns) {
  const std::size_t levels = n.levels.size();
  const long dofs = long(n.dof_level.size()), slaves = long(n.active_slaves.size());
#pragma omp parallel
  {
#pragma omp for schedule(static)
    for (long d = 0; d < dofs; ++d) {
      const std::size_t dl = n.dof_level[std::size_t(d)], dn = n.dof_node[std::size_t(d)];
      double v[kMaxColumns];
      for (std::size_t c = 0; c < columns; ++c) v[c] = base[c * levels + dl][dn];
      for (std::uint32_t j = n.dof_start[std::size_t(d)]; j < n.dof_start[std::size_t(d) + 1]; ++j) {
        const std::uint32_t k = n.dof_slave[j];
        const std::size_t sl = n.slave_level[k], sn = n.slave_node[k];
        const double coef = n.dof_c[j];
        for (std::size_t c = 0; c < columns; ++c) v[c] += coef * base[c * levels + sl][sn];
      }
      for (std::size_t c = 0; c < columns; ++c) base[c * levels + dl][dn] = v[c];
    }
#pragma omp for schedule(static)
    for (long i = 0; i < slaves; ++i) {
      const std::uint32_t k = n.active_slaves[std::size_t(i)];
      const std::size_t sl = n.slave_level[k], sn = n.slave_node[k];
      for (std::size_t c = 0; c < columns; ++c) base[c * levels + sl][sn] = 0.0;
    }
  }
}

// grid/nested.hpp's spread_to_slaves: every slave from its DOFs (slaves only read DOFs: no race).
void spread_to_slaves(RunState& n, std::initializer_list<NodalArray> arrays) {
  thread_local std::vector<double*> base_store;
  const std::size_t all = column_bases(n, arrays, base_store), levels = n.levels.size();
  for (std::size_t first = 0; first < all; first += kMaxColumns)
    spread_columns(n, base_store.data() + first * levels, std::min(kMaxColumns, all - first));
}

void spread_columns(RunState& n, double* const* base, std::size_t columns) {
  const NestedGrid& g = n.grid;
  const std::size_t levels = n.levels.size();
  const long slaves = long(n.active_slaves.size());
#pragma omp parallel for schedule(static)
  for (long i = 0; i < slaves; ++i) {
    const std::uint32_t k = n.active_slaves[std::size_t(i)];
    double v[kMaxColumns] = {};
    for (std::uint32_t t = g.term_start[k]; t < g.term_start[k + 1]; ++t) {
      const std::size_t tl = n.term_level[t], tn = n.term_node[t];
      const double coef = g.terms[t].c;
      for (std::size_t c = 0; c < columns; ++c) v[c] += coef * base[c * levels + tl][tn];
    }
    const std::size_t sl = n.slave_level[k], sn = n.slave_node[k];
    for (std::size_t c = 0; c < columns; ++c) base[c * levels + sl][sn] = v[c];
  }
}

}  // namespace rupture::detail

namespace rupture {

void condense_to_dofs(const Levels& L, std::initializer_list<NodalArray> arrays) {
  if (L.nested) detail::condense_to_dofs(*L.nested, arrays);
}

void condense_to_dofs(const Levels& L, std::initializer_list<LoadArray> arrays) {
  if (L.nested) detail::condense_to_dofs(*L.nested, arrays);
}

void spread_to_slaves(const Levels& L, std::initializer_list<NodalArray> arrays) {
  if (L.nested) detail::spread_to_slaves(*L.nested, arrays);
}

}  // namespace rupture

// rupture/tests/mpi/mpi_all_to_all.cpp
// Comm::all_to_all (parallel/comm.hpp) under `mpirun -n N`: every rank sends rank q a message
// of its own length (0 included, one far longer than the rest) and contents, in rounds of a
// small chunk (1 byte, 7, 64, 1000 bytes) and of the default one; every rank checks each
// message it received, byte for byte, and prints `all_to_all ok messages_checked=K` on rank 0
// when all of them hold on every rank; Comm::sum_in_rank_order checked alike (the rank-order
// sums, the same bits on every rank). Exit 0 then, 1 otherwise.
#include <mpi.h>

#include <fmt/format.h>

#include <cstdint>
#include <vector>

#include "parallel/comm.hpp"

using namespace rupture;

namespace {

// The message rank `from` sends rank `to`: its length and each byte.
std::size_t length(int from, int to) {
  if (from == 1 && to == 0) return 5003;  // one long message: many rounds of small chunks
  return std::size_t((from * 37 + to * 11) % 97);  // 0 for (0, 0)
}
unsigned char byte(int from, int to, std::size_t k) { return static_cast<unsigned char>((from * 131 + to * 17 + k * 7 + k / 251) & 0xff); }

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  const Comm world = Comm::world();
  const int n = world.size(), me = world.rank();
  std::vector<std::vector<unsigned char>> send{std::size_t(n)};
  for (int q = 0; q < n; ++q)
    for (std::size_t k = 0; k < length(me, q); ++k) send[std::size_t(q)].push_back(byte(me, q, k));
  long bad = 0, checked = 0;
  for (const std::size_t chunk : {std::size_t(1), std::size_t(7), std::size_t(64), std::size_t(1000), Comm::kAllToAllChunk}) {
    std::vector<std::vector<unsigned char>> recv;
    world.all_to_all(send, recv, chunk);
    for (int q = 0; q < n; ++q) {
      const std::vector<unsigned char>& m = recv[std::size_t(q)];
      if (m.size() != length(q, me)) {
        fmt::print("rank {}: chunk {}: from rank {}: {} bytes, expected {}\n", me, chunk, q, m.size(), length(q, me));
        ++bad;
        continue;
      }
      for (std::size_t k = 0; k < m.size(); ++k)
        if (m[k] != byte(q, me, k)) {
          fmt::print("rank {}: chunk {}: from rank {}: byte {} = {}, expected {}\n", me, chunk, q, k, int(m[k]), int(byte(q, me, k)));
          ++bad;
          break;
        }
      ++checked;
    }
  }
  // Comm::sum_in_rank_order: each element the ranks' values added 0, 1, 2, ... (values whose sum
  // depends on the order: 1e16 and 1 from different ranks), the same bits on every rank.
  {
    const std::vector<double> mine{1e16 * (me % 2 == 0 ? 1.0 : -1.0) + 1.0, 0.1 * (me + 1), me == 0 ? 1e16 : 1.0};
    std::vector<double> v = mine;
    world.sum_in_rank_order(v.data(), int(v.size()));
    for (std::size_t i = 0; i < v.size(); ++i) {
      double expected = 0.0;
      for (int q = 0; q < n; ++q) {
        const double vq[3] = {1e16 * (q % 2 == 0 ? 1.0 : -1.0) + 1.0, 0.1 * (q + 1), q == 0 ? 1e16 : 1.0};
        expected = q == 0 ? vq[i] : expected + vq[i];
      }
      const bool same_everywhere = world.min(v[i]) == world.max(v[i]);
      if (v[i] != expected || !same_everywhere) {
        fmt::print("rank {}: sum_in_rank_order element {} = {:.17g}, rank-order sum {:.17g}, same on every rank: {}\n",
                   me, i, v[i], expected, same_everywhere);
        ++bad;
      }
      ++checked;
    }
  }
  bad = world.sum(bad);
  checked = world.sum(checked);
  if (me == 0 && bad == 0) fmt::print("all_to_all ok messages_checked={}\n", checked);
  MPI_Finalize();
  return bad == 0 ? 0 : 1;
}

// rupture/parallel/comm.hpp
// The processes of a distributed run (MPI, OpenMPI from Debian) and the few operations the
// solver needs from them: scalar reductions (time step, energies, decisions every rank must
// take together), neighbour-only exchanges of byte buffers (halo sums, particle migration) and
// a broadcast of a diagnosis. A Comm of one process (`rupture` started without mpirun, every
// in-process test) does all of it locally without calling MPI, so the serial code path needs
// no MPI set-up. Collective calls must be made by every rank in the same order.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace rupture {

// Whether this process was started by mpirun/mpiexec (OpenMPI's or a PMI launcher's
// environment): only then does `rupture` initialize MPI.
bool launched_by_mpi();

// Initializes MPI (threads: funneled, OpenMP regions never call MPI) for the lifetime of the
// object when `use` is true; finalizes it at the end. Not copyable.
class MpiSession {
 public:
  explicit MpiSession(bool use);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  bool active() const { return active_; }

 private:
  bool active_ = false;
};

// One message of an exchange: bytes to send to `rank` and the room for what it sends back.
struct PeerBuffers {
  int rank = 0;
  std::vector<unsigned char> send, recv;  // recv is resized to what arrives (sizes: first)
};

class Comm {
 public:
  // MPI_COMM_WORLD when MPI is initialized, else the one-process communicator.
  static Comm world();
  static Comm single() { return Comm(); }
  int rank() const { return rank_; }
  int size() const { return size_; }
  bool distributed() const { return size_ > 1; }

  double min(double v) const;
  double max(double v) const;
  double sum(double v) const;
  void sum(double* v, int n) const;  // element-wise, in place
  void max(double* v, int n) const;  // element-wise, in place
  // Element-wise sums added in rank order (0, 1, ...) on every rank: the same bits everywhere,
  // for sums that decisions every rank must take alike are made from (a crack tip's K).
  void sum_in_rank_order(double* v, int n) const;
  long sum(long v) const;
  // The lowest rank for which `flag` is true, or -1 when none is.
  int first_with(bool flag) const;
  // `text` as held by `root`, on every rank.
  std::string broadcast(const std::string& text, int root) const;
  // Neighbour exchange: every peer's send buffer goes to it, its message lands in recv. Peers
  // must list each other (the relation is symmetric). Sizes travel first, so a peer may send
  // any number of bytes (0 included).
  void exchange(std::vector<PeerBuffers>& peers) const;
  // The same when every recv buffer already has the size the peer sends (halo sums: both
  // sides know the shared box): one message per peer and direction.
  void exchange_sized(std::vector<PeerBuffers>& peers) const;
  // Every rank sends send[q] to rank q and receives recv[q] from it (all ranks; rare: a
  // rebalance). Buffers of any size: counts are 64-bit and the bytes go in rounds of at most
  // `chunk_bytes` per rank (1 to kAllToAllChunk; tests choose small ones); every rank must
  // pass the same chunk.
  static constexpr std::size_t kAllToAllChunk = std::size_t(1) << 30;  // 1 GiB: int counts
  void all_to_all(const std::vector<std::vector<unsigned char>>& send,
                  std::vector<std::vector<unsigned char>>& recv,
                  std::size_t chunk_bytes = kAllToAllChunk) const;
  // Stops every rank (after a failure that cannot be agreed on in step, e.g. an I/O error on
  // one rank), exit code `code`.
  [[noreturn]] void abort(int code) const;

 private:
  Comm() = default;
  int rank_ = 0, size_ = 1;
};

}  // namespace rupture

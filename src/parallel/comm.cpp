// rupture/parallel/comm.cpp
#include "parallel/comm.hpp"

#include <mpi.h>

#include <algorithm>
#include <climits>
#include <cstdint>
#include <cstring>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace rupture {
namespace {

bool mpi_initialized() {
  int init = 0, fin = 0;
  MPI_Initialized(&init);
  MPI_Finalized(&fin);
  return init && !fin;
}

void check(int rc, const char* what) {
  if (rc != MPI_SUCCESS) throw std::runtime_error(std::string("MPI call failed: ") + what);
}

}  // namespace

bool launched_by_mpi() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE", "PMI_RANK"})
    if (std::getenv(v)) return true;
  return false;
}

MpiSession::MpiSession(bool use) {
  if (!use || mpi_initialized()) return;
  int provided = 0;
  check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
  active_ = true;
}

MpiSession::~MpiSession() {
  if (active_ && mpi_initialized()) MPI_Finalize();
}

Comm Comm::world() {
  Comm c;
  if (!mpi_initialized()) return c;
  MPI_Comm_rank(MPI_COMM_WORLD, &c.rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &c.size_);
  return c;
}

namespace {
// One value reduced over every rank with `op` (the value itself on one process).
template <class T>
T all_reduce(int size, T v, MPI_Datatype type, MPI_Op op) {
  if (size == 1) return v;
  T r = v;
  check(MPI_Allreduce(&v, &r, 1, type, op, MPI_COMM_WORLD), "MPI_Allreduce");
  return r;
}
}  // namespace

double Comm::min(double v) const { return all_reduce(size_, v, MPI_DOUBLE, MPI_MIN); }
double Comm::max(double v) const { return all_reduce(size_, v, MPI_DOUBLE, MPI_MAX); }
long Comm::sum(long v) const { return all_reduce(size_, v, MPI_LONG, MPI_SUM); }

double Comm::sum(double v) const {
  sum(&v, 1);
  return v;
}

// The reduction's order is MPI's (fixed for a given N): sums over ranks agree with one
// process to round-off.
void Comm::sum(double* v, int n) const {
  if (size_ == 1 || n == 0) return;
  check(MPI_Allreduce(MPI_IN_PLACE, v, n, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD), "MPI_Allreduce");
}

void Comm::sum_in_rank_order(double* v, int n) const {
  if (size_ == 1 || n == 0) return;
  std::vector<double> all(std::size_t(n) * std::size_t(size_));
  check(MPI_Allgather(v, n, MPI_DOUBLE, all.data(), n, MPI_DOUBLE, MPI_COMM_WORLD), "MPI_Allgather");
  for (int i = 0; i < n; ++i) {
    double total = all[std::size_t(i)];
    for (int r = 1; r < size_; ++r) total += all[std::size_t(r) * std::size_t(n) + std::size_t(i)];
    v[i] = total;
  }
}

void Comm::max(double* v, int n) const {
  if (size_ == 1 || n == 0) return;
  check(MPI_Allreduce(MPI_IN_PLACE, v, n, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD), "MPI_Allreduce");
}

int Comm::first_with(bool flag) const {
  const int r = all_reduce(size_, flag ? rank_ : INT_MAX, MPI_INT, MPI_MIN);
  return r == INT_MAX ? -1 : r;
}

std::string Comm::broadcast(const std::string& text, int root) const {
  if (size_ == 1) return text;
  long n = rank_ == root ? long(text.size()) : 0;
  check(MPI_Bcast(&n, 1, MPI_LONG, root, MPI_COMM_WORLD), "MPI_Bcast");
  std::string out = rank_ == root ? text : std::string(std::size_t(n), '\0');
  if (n > 0) check(MPI_Bcast(out.data(), int(n), MPI_CHAR, root, MPI_COMM_WORLD), "MPI_Bcast");
  return out;
}

void Comm::exchange(std::vector<PeerBuffers>& peers) const {
  if (peers.empty()) return;
  std::vector<long> out(peers.size()), in(peers.size());
  std::vector<MPI_Request> req(2 * peers.size());
  for (std::size_t k = 0; k < peers.size(); ++k) {
    out[k] = long(peers[k].send.size());
    check(MPI_Irecv(&in[k], 1, MPI_LONG, peers[k].rank, 1, MPI_COMM_WORLD, &req[2 * k]), "MPI_Irecv");
    check(MPI_Isend(&out[k], 1, MPI_LONG, peers[k].rank, 1, MPI_COMM_WORLD, &req[2 * k + 1]), "MPI_Isend");
  }
  check(MPI_Waitall(int(req.size()), req.data(), MPI_STATUSES_IGNORE), "MPI_Waitall");
  for (std::size_t k = 0; k < peers.size(); ++k) peers[k].recv.resize(std::size_t(in[k]));
  exchange_sized(peers);
}

void Comm::exchange_sized(std::vector<PeerBuffers>& peers) const {
  if (peers.empty()) return;
  std::vector<MPI_Request> req;
  req.reserve(2 * peers.size());
  constexpr long kChunk = INT_MAX / 2;  // MPI counts are int: long buffers go in pieces
  int tag = 2;
  for (PeerBuffers& p : peers) {
    for (long off = 0; off < long(p.recv.size()); off += kChunk) {
      req.emplace_back();
      const int n = int(std::min(kChunk, long(p.recv.size()) - off));
      check(MPI_Irecv(p.recv.data() + off, n, MPI_BYTE, p.rank, tag, MPI_COMM_WORLD, &req.back()), "MPI_Irecv");
    }
    for (long off = 0; off < long(p.send.size()); off += kChunk) {
      req.emplace_back();
      const int n = int(std::min(kChunk, long(p.send.size()) - off));
      check(MPI_Isend(p.send.data() + off, n, MPI_BYTE, p.rank, tag, MPI_COMM_WORLD, &req.back()), "MPI_Isend");
    }
  }
  check(MPI_Waitall(int(req.size()), req.data(), MPI_STATUSES_IGNORE), "MPI_Waitall");
}

// Counts travel as 64-bit integers; the bytes go in rounds of MPI_Alltoallv whose int counts
// and displacements stay below `chunk_bytes` in all: each round moves up to chunk_bytes / N
// bytes of every pair's message (at least one), and every rank takes part in as many rounds
// as the longest message anywhere needs.
void Comm::all_to_all(const std::vector<std::vector<unsigned char>>& send,
                      std::vector<std::vector<unsigned char>>& recv, std::size_t chunk_bytes) const {
  const std::size_t n = std::size_t(size_);
  if (send.size() != n)
    throw std::invalid_argument("Comm::all_to_all: " + std::to_string(send.size()) + " send buffers for " +
                                std::to_string(n) + " ranks");
  if (chunk_bytes == 0 || chunk_bytes > kAllToAllChunk)
    throw std::invalid_argument("Comm::all_to_all: chunk of " + std::to_string(chunk_bytes) + " bytes (1 to " +
                                std::to_string(kAllToAllChunk) + " allowed)");
  recv.assign(n, {});
  if (size_ == 1) {
    recv[0] = send[0];
    return;
  }
  std::vector<std::int64_t> out(n), in(n);
  for (std::size_t q = 0; q < n; ++q) out[q] = std::int64_t(send[q].size());
  check(MPI_Alltoall(out.data(), 1, MPI_INT64_T, in.data(), 1, MPI_INT64_T, MPI_COMM_WORLD), "MPI_Alltoall");
  const std::int64_t piece = std::max<std::int64_t>(1, std::int64_t(chunk_bytes / n));
  std::int64_t longest = 0;
  for (std::size_t q = 0; q < n; ++q) {
    recv[q].resize(std::size_t(in[q]));
    longest = std::max({longest, out[q], in[q]});
  }
  long rounds = long((longest + piece - 1) / piece);
  check(MPI_Allreduce(MPI_IN_PLACE, &rounds, 1, MPI_LONG, MPI_MAX, MPI_COMM_WORLD), "MPI_Allreduce");
  std::vector<int> out_n(n), in_n(n), out_at(n), in_at(n);
  std::vector<unsigned char> flat_out, flat_in;
  for (long r = 0; r < rounds; ++r) {
    const std::int64_t from = std::int64_t(r) * piece;  // this round's bytes of every message
    int out_total = 0, in_total = 0;
    for (std::size_t q = 0; q < n; ++q) {
      out_n[q] = int(std::clamp<std::int64_t>(out[q] - from, 0, piece));
      in_n[q] = int(std::clamp<std::int64_t>(in[q] - from, 0, piece));
      out_at[q] = out_total, in_at[q] = in_total;
      out_total += out_n[q], in_total += in_n[q];
    }
    flat_out.resize(std::size_t(out_total));
    flat_in.resize(std::size_t(in_total));
    for (std::size_t q = 0; q < n; ++q)
      if (out_n[q] > 0) std::memcpy(flat_out.data() + out_at[q], send[q].data() + from, std::size_t(out_n[q]));
    check(MPI_Alltoallv(flat_out.data(), out_n.data(), out_at.data(), MPI_BYTE, flat_in.data(), in_n.data(),
                        in_at.data(), MPI_BYTE, MPI_COMM_WORLD),
          "MPI_Alltoallv");
    for (std::size_t q = 0; q < n; ++q)
      if (in_n[q] > 0) std::memcpy(recv[q].data() + from, flat_in.data() + in_at[q], std::size_t(in_n[q]));
  }
}

void Comm::abort(int code) const {
  if (size_ > 1) MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);
}

}  // namespace rupture

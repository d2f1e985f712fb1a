// rupture/parallel/comm.cpp
#include "parallel/comm.hpp"

#include <mpi.h>

#include <algorithm>
#include <climits>
#include <cstdlib>
#include <stdexcept>

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

void Comm::all_to_all(const std::vector<std::vector<unsigned char>>& send,
                      std::vector<std::vector<unsigned char>>& recv) const {
  recv.assign(std::size_t(size_), {});
  if (size_ == 1) {
    recv[0] = send[0];
    return;
  }
  const std::size_t n = std::size_t(size_);
  std::vector<int> out(n), in(n), out_at(n, 0), in_at(n, 0);
  for (std::size_t q = 0; q < n; ++q) out[q] = int(send[q].size());
  check(MPI_Alltoall(out.data(), 1, MPI_INT, in.data(), 1, MPI_INT, MPI_COMM_WORLD), "MPI_Alltoall");
  std::vector<unsigned char> flat_out, flat_in;
  for (std::size_t q = 0; q < n; ++q) {
    out_at[q] = int(flat_out.size());
    flat_out.insert(flat_out.end(), send[q].begin(), send[q].end());
  }
  long total = 0;
  for (std::size_t q = 0; q < n; ++q) in_at[q] = int(total), total += in[q];
  flat_in.resize(std::size_t(total));
  check(MPI_Alltoallv(flat_out.data(), out.data(), out_at.data(), MPI_BYTE, flat_in.data(), in.data(),
                      in_at.data(), MPI_BYTE, MPI_COMM_WORLD),
        "MPI_Alltoallv");
  for (std::size_t q = 0; q < n; ++q)
    recv[q].assign(flat_in.begin() + in_at[q], flat_in.begin() + in_at[q] + in[q]);
}

void Comm::abort(int code) const {
  if (size_ > 1) MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);
}

}  // namespace rupture

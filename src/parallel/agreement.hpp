// rupture/parallel/agreement.hpp
// A failure on any rank of a distributed run reaches every rank at one agreed point, so that no
// rank waits in a collective call that a failed rank will never make. agree_on_failure runs a
// piece of work that holds no collective call on every rank, catches what it throws, and at
// its end every rank learns (one reduction, one broadcast) the failure of the lowest failing
// rank, then throws it: InputError as InputError (exit 1), the others as AgreedFailure, which
// keeps the kind (exit 2 for an unstable run, 3 for I/O and other failures) and which the CLI
// prints once (rank 0) before every rank exits with its code. One process: the work runs and
// its exceptions pass unchanged.
#pragma once
#include <stdexcept>
#include <string>

#include "parallel/comm.hpp"

namespace rupture {

enum class FailureKind : char { input = 'I', io = 'O', simulation = 'S', other = 'X' };

struct AgreedFailure : std::runtime_error {
  AgreedFailure(FailureKind k, int r, const std::string& what)
      : std::runtime_error(what), kind(k), rank(r) {}
  FailureKind kind;
  int rank;  // the lowest rank that failed
  int exit_code() const { return kind == FailureKind::input ? 1 : kind == FailureKind::simulation ? 2 : 3; }
};

// This rank's failure ("" when none) of kind `kind`: when any rank has one, throws the lowest
// failing rank's on every rank (collective); the message ends "(rank r)".
void throw_if_any_failed(const Comm& comm, FailureKind kind, const std::string& failure);

// The kind of the exception being handled (inside a catch block) and its message.
FailureKind current_failure(std::string& message);

template <class F>
void agree_on_failure(const Comm& comm, F&& work) {
  if (!comm.distributed()) {
    work();
    return;
  }
  std::string failure;
  FailureKind kind = FailureKind::other;
  try {
    work();
  } catch (...) {
    kind = current_failure(failure);
  }
  throw_if_any_failed(comm, kind, failure);
}

}  // namespace rupture

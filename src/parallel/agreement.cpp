// rupture/parallel/agreement.cpp
#include "parallel/agreement.hpp"

#include <fmt/format.h>

#include <exception>

#include "core/errors.hpp"

namespace rupture {

void throw_if_any_failed(const Comm& comm, FailureKind kind, const std::string& failure) {
  const int failed = comm.first_with(!failure.empty());
  if (failed < 0) return;
  // The kind travels as the message's first character.
  const std::string text = comm.broadcast(std::string(1, char(kind)) + failure, failed);
  const auto k = FailureKind(text[0]);
  const std::string what = comm.distributed() ? fmt::format("{} (rank {})", text.substr(1), failed) : text.substr(1);
  if (k == FailureKind::input) throw InputError(what);
  throw AgreedFailure(k, failed, what);
}

FailureKind current_failure(std::string& message) {
  try {
    throw;
  } catch (const AgreedFailure& e) {
    message = e.what();
    return e.kind;
  } catch (const InputError& e) {
    message = e.what();
    return FailureKind::input;
  } catch (const IoError& e) {
    message = e.what();
    return FailureKind::io;
  } catch (const SimulationError& e) {
    message = e.what();
    return FailureKind::simulation;
  } catch (const std::exception& e) {
    message = e.what();
  } catch (...) {
    message = "unknown failure";
  }
  if (message.empty()) message = "failure without a message";
  return FailureKind::other;
}

}  // namespace rupture

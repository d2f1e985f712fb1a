// rupture/core/fault_injection.cpp
#include "core/fault_injection.hpp"

#include <cstdlib>
#include <cstring>
#include <string>

#include "core/errors.hpp"

namespace rupture {
namespace {

struct Armed {
  FaultSite site = FaultSite::none;
  long step = 0;
};
Armed g_armed;  // written once by main before any thread or step

FaultSite site_named(const std::string& name) {
  if (name == "face_outside_grid") return FaultSite::face_outside_grid;
  if (name == "face_out_of_reach") return FaultSite::face_out_of_reach;
  if (name == "cohesive_oscillation") return FaultSite::cohesive_oscillation;
  if (name == "gimp_contract") return FaultSite::gimp_contract;
  if (name == "record_write") return FaultSite::record_write;
  if (name == "setup") return FaultSite::setup;
  if (name == "snapshot_index") return FaultSite::snapshot_index;
  if (name == "case_read") return FaultSite::case_read;
  throw InputError("RUPTURE_INJECT_FAULT: unknown site '" + name + "'");
}

}  // namespace

void arm_fault_from_environment(int rank) {
  const char* v = std::getenv("RUPTURE_INJECT_FAULT");
  if (!v || !*v) return;
  const std::string text(v);
  const auto a = text.find(':'), b = text.rfind(':');
  if (a == std::string::npos || a == b)
    throw InputError("RUPTURE_INJECT_FAULT = '" + text + "': must be SITE:RANK:STEP");
  const FaultSite site = site_named(text.substr(0, a));
  char* end = nullptr;
  const long r = std::strtol(text.c_str() + a + 1, &end, 10);
  const long step = std::strtol(text.c_str() + b + 1, &end, 10);
  if (r == rank) g_armed = {site, step};
}

bool fault_due(FaultSite site, long step) {
  return g_armed.site == site && step >= g_armed.step;
}

}  // namespace rupture

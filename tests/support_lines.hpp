// Shared helpers for tests of lines and ties: a polyline from its vertices, and a file's text.
#pragma once
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "cohesive/polyline.hpp"

namespace rupture::test {

inline Polyline polyline(std::vector<double> x, std::vector<double> y) {
  Polyline p;
  p.x = std::move(x), p.y = std::move(y);
  return p;
}

// The whole file (empty if it cannot be read).
inline std::string read_text(const std::string& path) {
  std::string text;
  FILE* f = std::fopen(path.c_str(), "r");
  if (!f) return text;
  char buf[4096];
  for (std::size_t k; (k = std::fread(buf, 1, sizeof buf, f)) > 0;) text.append(buf, k);
  std::fclose(f);
  return text;
}

}  // namespace rupture::test

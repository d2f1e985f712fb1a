// rupture/bc/absorbing.cpp
#include "bc/absorbing.hpp"

namespace rupture {

const char* edge_name(Edge e) {
  switch (e) {
    case Edge::left: return "left";
    case Edge::right: return "right";
    case Edge::bottom: return "bottom";
    case Edge::top: return "top";
  }
  return "?";
}

}  // namespace rupture

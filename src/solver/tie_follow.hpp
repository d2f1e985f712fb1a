// rupture/solver/tie_follow.hpp
// Ties that follow the material (docs/fracture.md, "A tie that follows the material").
// A tied stretch (InterfaceSpec::tie_geometries: a crack's extension through intact material, a
// site, a bonded stretch) joins its two fields on the grid nodes near its line
// (solver/cohesive_step.hpp, bonded_nodes). The line is drawn where the material was at t = 0;
// the nodes are where it is now. The band's reach allows the material beside the line to move by
// half a cell from where the band was laid (docs/theory.md, "Bonded stretches"), so a body that
// moves further would come apart along the tie. So the ties are laid where the material has
// carried them: at points sampled along each tied line (its vertices, and at most two cells
// apart), moved by the mean displacement of the particles within a cell of the point (by
// reference position, every field, summed over the ranks in rank order), joined by the fewest
// straight pieces that miss none of them by more than a sixteenth of a cell; whether an end is a crack's tip is read on the drawn line. They are laid again when
// that displacement has changed by more than a quarter of a cell since they were laid (the other
// quarter is the margin for what the mean and the pieces miss), and when growth has
// changed an interface's tied lines. The particles' largest move per step bounds how far the
// material can have gone: until the bound reaches a quarter cell nothing is measured, so a run
// whose material moves less than that lays every tie where it is drawn, as before.
// Any grid, one process or several; with per-level time steps the ties stay where drawn (the
// levels' coupled nodes hold them, fixed at set-up).
#pragma once
#include <cstddef>
#include <functional>
#include <vector>

#include "cohesive/polyline.hpp"
#include "solver/run_state.hpp"

namespace rupture {

// Points along ties (reference positions, m): each tie's vertices and, on each piece, equally
// spaced points at most `spacing` apart; tie i's are [start[i], start[i + 1]).
struct TieSamples {
  std::vector<double> x, y;
  std::vector<std::size_t> start;
};
TieSamples sample_ties(const std::vector<Polyline>& ties, double spacing);

// The ties through the samples moved by (ux, uy) (one per sample), each laid as the fewest
// straight pieces through them that miss none by more than `tolerance` (m; Douglas-Peucker: its
// ends kept, and every point the chord misses by more, the farthest first).
std::vector<Polyline> carried_ties(const TieSamples& at, const std::vector<double>& ux,
                                   const std::vector<double>& uy, double tolerance = 0.0);

// The mean displacement (x - x0) of the particles of `s` whose reference position lies within
// `radius` of each sample, summed over the ranks (collective); a point with none takes the
// nearest sample's of its tie that has some (none on the whole tie: 0).
void material_displacement(const State& s, const TieSamples& at, double radius, std::vector<double>& ux,
                           std::vector<double>& uy);

// After a step (the driver's, after growth; every rank alike): adds the step's largest move to
// the bounds, and lays again, over the whole grid, the ties the material or growth has moved;
// `before_laying` is called once before the first is laid (the driver gathers the interfaces'
// state there, and distributes the ties again after). Whether any was laid. A no-op without ties
// and with per-level time steps.
bool follow_ties(RunState& s, const std::function<void()>& before_laying = {});

// After a restore (the ties laid again from the case and the grown cracks): lays each
// interface's ties where the checkpoint says they were laid (on every level).
void lay_followed_ties(RunState& s);

}  // namespace rupture

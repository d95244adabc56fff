// Standard racks on a table model: ball positions only; all balls at rest.
#pragma once

#include <string>
#include <vector>

#include "cue_sim/physics/table_model.hpp"
#include "cue_sim/physics/table_state.hpp"

namespace cue_sim
{
namespace physics
{
struct RackOptions
{
  /// Gap [m] between neighbouring balls of the triangle or diamond (a tight rack has small
  /// gaps; 0 freezes the balls together).
  double gap = 1e-5;
  /// Largest random displacement [m] of each ball but the apex, in [0, gap / 2]: the uneven
  /// gaps of a real rack. 0 gives the perfect triangle.
  double jitter = 0.0;
  /// Seed of the displacements: the same seed gives the same rack on every machine.
  unsigned seed = 0;
};

/// The names rackLayout() accepts.
std::vector<std::string> rackNames();
/// rackNames() for a message: "eight, nine, ten, carom, snooker, empty".
std::string rackNamesText();

/// "eight": cue ball on the head string, balls 1-15 in a triangle with the apex on the foot
/// spot (8 in the centre, a solid and a stripe in the back corners). "nine": balls 1-9 in a
/// diamond, 1 at the apex, 9 in the centre. "ten": balls 1-10 in a triangle, 10 in the centre.
/// "carom": three-cushion's starting position, the red (2) on the foot spot, the yellow (1) on
/// the head spot and the white (0) on the head string 18.2 cm to its left (UMB Art. 13, 23).
/// "snooker": the reds (1-15) in a triangle whose apex is as near the pink spot as the gap allows,
/// the colours (16 yellow, 17 green, 18 brown, 19 blue, 20 pink, 21 black) on their spots and the
/// cue ball in the D midway between the yellow and brown spots (snooker_markings.hpp; WPBSA
/// Section 3, 2). "empty": the cue ball alone on the head string.
/// Otherwise the cue ball stands on TableModel::headSpot(), the apex on footSpot(). Throws
/// std::invalid_argument for another name.
template <typename S>
TableState<S> rackLayout(const std::string& name, const TableModel& table, S ball_radius,
                         const RackOptions& options = {});

}  // namespace physics
}  // namespace cue_sim

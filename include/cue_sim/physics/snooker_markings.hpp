// A snooker table's markings (WPBSA Official Rules of the Games of Snooker and English Billiards,
// Section 1, "The Standard Table"): the baulk line, the D and the six colour spots. On the
// standard table (a playing area of 3569 x 1778 mm) they are where the rules put them; on another
// table, in proportion (the simulator's choice: the rules describe one table). The table's bottom
// (baulk) cushion is its head (-x) end, the top cushion its foot end.
#pragma once

#include <Eigen/Core>
#include <array>

#include "cue_sim/physics/table_model.hpp"

namespace cue_sim
{
namespace physics
{
/// The colours by value, the order of their spots.
enum class SnookerColour : int
{
  Yellow = 0,  ///< 2 points
  Green,       ///< 3
  Brown,       ///< 4
  Blue,        ///< 5
  Pink,        ///< 6
  Black,       ///< 7
};

struct SnookerMarkings
{
  double baulk_line_x = 0;                 ///< [m] the baulk line, across the table (x = const)
  Eigen::Vector2d d_centre;                ///< the D's centre: the middle of the baulk line
  double d_radius = 0;                     ///< [m]
  std::array<Eigen::Vector2d, 6> spots{};  ///< yellow, green, brown, blue, pink, black

  const Eigen::Vector2d& spotOf(SnookerColour colour) const { return spots[static_cast<std::size_t>(colour)]; }
  /// Whether p (a ball's centre) is in the D: in baulk, within the semicircle, its lines included.
  bool inD(const Eigen::Vector2d& p) const;
};

/// The markings of `table`. Viewed from baulk (looking along +x) the yellow spot is on the right
/// (-y), the green on the left.
SnookerMarkings snookerMarkings(const TableModel& table);

}  // namespace physics
}  // namespace cue_sim

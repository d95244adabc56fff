#include "cue_sim/physics/snooker_markings.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
// The standard table (WPBSA Section 1) [m].
constexpr double kStandardLength = 3.569, kStandardWidth = 1.778;
constexpr double kBaulkLineFromBottom = 0.737;  ///< 29 in from the bottom cushion's face
constexpr double kDRadius = 0.292;              ///< 11 1/2 in
constexpr double kBlackSpotFromTop = 0.324;     ///< 12 3/4 in from the top cushion's face
/// [m] A ball's centre this near the D's lines is on them, and so in the D: the rounding of a
/// place computed on a line, far below any referee's eye.
constexpr double kOnTheLine = 1e-9;
}  // namespace

bool SnookerMarkings::inD(const Eigen::Vector2d& p) const
{
  return p.x() <= baulk_line_x + kOnTheLine && (p - d_centre).norm() <= d_radius + kOnTheLine;
}

SnookerMarkings snookerMarkings(const TableModel& table)
{
  const Eigen::Vector2d c = table.clothCentre();
  const double along = table.clothLength() / kStandardLength, across = table.clothWidth() / kStandardWidth;
  const double bottom = c.x() - table.clothLength() / 2, top = c.x() + table.clothLength() / 2;
  SnookerMarkings m;
  m.baulk_line_x = bottom + kBaulkLineFromBottom * along;
  m.d_centre = Eigen::Vector2d(m.baulk_line_x, c.y());
  m.d_radius = kDRadius * across;
  m.spots = {
      Eigen::Vector2d(m.baulk_line_x, c.y() - m.d_radius),      // yellow: the D's right corner seen from baulk
      Eigen::Vector2d(m.baulk_line_x, c.y() + m.d_radius),      // green: its left corner
      m.d_centre,                                               // brown: the middle of the baulk line
      c,                                                        // blue: the centre spot
      Eigen::Vector2d((c.x() + top) / 2, c.y()),                // pink: midway between the centre and the top cushion
      Eigen::Vector2d(top - kBlackSpotFromTop * along, c.y()),  // black
  };
  return m;
}

}  // namespace physics
}  // namespace cue_sim

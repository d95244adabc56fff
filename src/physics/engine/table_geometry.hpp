// The table's geometry converted once to the engine's scalar type, each cushion, jaw and pocket
// with the box a ball's centre can be in while it touches it (internal to the physics core).
#pragma once

#include <vector>

#include "cue_sim/physics/table_model.hpp"
#include "cue_sim/physics/types.hpp"

namespace cue_sim
{
namespace physics
{
/// Boxes are widened by a nanometre, so that rounding never dismisses a touching ball.
constexpr double kBoxMargin = 1e-9;

template <typename S>
struct TableGeometry
{
  struct Segment
  {
    Vec2<S> start, direction, normal;
    S length;
    Vec2<S> low, high;  ///< where a ball's centre can be while it touches the segment
  };
  struct Circle
  {
    Vec2<S> centre;
    S radius;
    Vec2<S> low, high;  ///< where a ball's centre can be while it touches the circle
  };
  std::vector<Segment> segments;
  std::vector<Circle> circles;    ///< jaws and cushion end caps
  std::vector<Circle> pockets;    ///< capture circles: `low`, `high` bound where a centre enters
  Vec2<S> cloth_low, cloth_high;  ///< the cloth's rectangle
  /// A box about the cloth's centre that no cushion's, jaw's or pocket's box reaches: a ball
  /// whose centre is in it touches no wall.
  Vec2<S> clear_low, clear_high;
  /// Heights above the cloth [m]: the cushions' (and jaws') nose, the top a flying ball clears,
  /// and the rails' top, where a ball that clears them lands.
  S nose_height, rail_height;
  Vec2<S> edge_low, edge_high;  ///< the table's outer edge: beyond it, the floor
  S widest_post = S(0);         ///< the largest jaw's or end cap's radius [m]

  TableGeometry(const TableModel& table, S ball_radius, S cushion_height);
};

}  // namespace physics
}  // namespace cue_sim

// The rviz picture of the table: cloth, cushions, pockets, and balls in the colours of the table's
// set (pool's numbered balls, carom's three).
#pragma once

#include <visualization_msgs/MarkerArray.h>

#include "cue_sim/physics/table_model.hpp"
#include "cue_sim/physics/table_state.hpp"
#include "cue_sim/scene/ball_colours.hpp"

namespace cue_sim
{
/// A ball's colour (scene/ball_colours.hpp) as a marker colour.
std_msgs::ColorRGBA poolColour(int id, BallSet set = BallSet::Pool);
std_msgs::ColorRGBA rgba(float r, float g, float b, float a = 1.0f);
/// A marker to ADD in `frame`, of `type`, with an identity pose.
visualization_msgs::Marker markerIn(const std::string& frame, const std::string& ns, int id, int type);

struct MarkerFrames
{
  std::string table;        ///< the table frame
  std::string ball_prefix;  ///< ball frames are <ball_prefix><id>
};

/// Starts with DELETEALL, then one namespace per layer (cloth, cushions, jaws, pockets, balls,
/// stripes, labels) with stable ids. Ball markers live in the balls' own tf frames and are
/// frame-locked, so tf alone moves them: the array is published once, latched.
visualization_msgs::MarkerArray tableMarkers(const physics::TableModel& table, const physics::TableState<double>& state,
                                             double ball_radius, double cushion_height, const MarkerFrames& frames);

}  // namespace cue_sim

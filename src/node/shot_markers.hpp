// rviz markers of shots: the cue stick at a strike, and the paths of the last prediction.
#pragma once

#include <visualization_msgs/Marker.h>
#include <visualization_msgs/MarkerArray.h>

#include <string>

#include "cue_sim/physics/cue_aim.hpp"
#include "cue_sim/physics/engine.hpp"

namespace cue_sim
{
/// The cue as a cylinder, its tip end at cue.tip, shown for `lifetime` seconds.
visualization_msgs::Marker cueStickMarker(const physics::CueStick& cue, const std::string& frame,
                                          const ros::Time& stamp, double lifetime);

/// DELETEALL, then one line strip per ball that moves, in its colour, through its positions
/// from the strike to rest (`start` struck by `ball_id` with `strike`; sampled so that no path
/// has more than about 2000 points, and at every event).
visualization_msgs::MarkerArray previewMarkers(const physics::Engine<double>& engine,
                                               const physics::TableState<double>& start, int ball_id,
                                               const physics::CueStrike<double>& strike, const std::string& frame);

/// What takes a preview off the screen: one DELETEALL.
visualization_msgs::MarkerArray clearedPreview();

}  // namespace cue_sim

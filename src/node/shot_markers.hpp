// rviz markers of shots: the cue stick at a strike, and the paths of the last prediction.
#pragma once

#include <visualization_msgs/Marker.h>
#include <visualization_msgs/MarkerArray.h>

#include <string>

#include "cue_sim/physics/cue_aim.hpp"
#include "cue_sim/scene/ball_colours.hpp"
#include "cue_sim/session/shot_preview.hpp"

namespace cue_sim
{
/// The cue as a cylinder, its tip end at cue.tip, shown for `lifetime` seconds.
visualization_msgs::Marker cueStickMarker(const physics::CueStick& cue, const std::string& frame,
                                          const ros::Time& stamp, double lifetime);

/// DELETEALL, then one line strip per path, in its ball's colour in `set` (session::previewPaths:
/// drawn from a prediction's own trajectories, without running the shot again).
visualization_msgs::MarkerArray previewMarkers(const std::vector<session::PreviewPath>& paths, const std::string& frame,
                                               BallSet set);

/// What takes a preview off the screen: one DELETEALL.
visualization_msgs::MarkerArray clearedPreview();

}  // namespace cue_sim

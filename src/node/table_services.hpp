// table_node's light services: strikes and what is on the table and how its time runs. Each
// converts its request, calls the live table under the lock (a tf lookup for ~strike_cue
// happens before, outside it), and converts the answer; what is checked and why a request is
// refused is the live table's.
#pragma once

#include <cue_sim/PlaceBall.h>
#include <cue_sim/Rack.h>
#include <cue_sim/RemoveBall.h>
#include <cue_sim/SetState.h>
#include <cue_sim/Step.h>
#include <cue_sim/Strike.h>
#include <cue_sim/StrikeCue.h>
#include <ros/ros.h>
#include <std_srvs/SetBool.h>
#include <std_srvs/Trigger.h>
#include <visualization_msgs/Marker.h>

#include <optional>
#include <vector>

#include "node/cue_frames.hpp"
#include "node/node_parameters.hpp"
#include "node/shared_table.hpp"

namespace cue_sim
{
class TableServices
{
public:
  TableServices(ros::NodeHandle& private_node, SharedTable& shared, const NodeParameters& parameters);

  /// Strikes the live table, and shows the cue and the shot on ~cue and ~shots. `source` names
  /// who asked on ~shots.
  session::StrikeOutcome strike(const session::Shot& shot, const char* source);
  /// Strikes the ball a cue in the table frame meets at `speed`, at `stamp` (none: now; a followed
  /// cue's touch may be a tf sample ago: session::LiveTable::strike says when that is refused), and
  /// shows it as strike() does with `pose` as given; `aimed` is the shot worked out from the cue.
  session::StrikeOutcome strikeWithCue(const physics::CueStick& cue, double speed, std::optional<ros::Time> stamp,
                                       const char* source, const geometry_msgs::PoseStamped& pose,
                                       session::Shot& aimed);
  /// Shows a marker on ~cue (a cue followed in tf).
  void showCue(const visualization_msgs::Marker& marker) { cue_publisher_.publish(marker); }

private:
  bool onStrike(Strike::Request& request, Strike::Response& response);
  bool onStrikeCue(StrikeCue::Request& request, StrikeCue::Response& response);
  bool onRack(Rack::Request& request, Rack::Response& response);
  bool onReset(std_srvs::Trigger::Request& request, std_srvs::Trigger::Response& response);
  bool onSetState(SetState::Request& request, SetState::Response& response);
  bool onPlaceBall(PlaceBall::Request& request, PlaceBall::Response& response);
  bool onRemoveBall(RemoveBall::Request& request, RemoveBall::Response& response);
  bool onPause(std_srvs::SetBool::Request& request, std_srvs::SetBool::Response& response);
  bool onStep(Step::Request& request, Step::Response& response);
  /// ~cue and ~shots for a strike the table executed.
  void publishStrike(const session::Shot& requested, const session::StrikeOutcome& outcome, const char* source,
                     const geometry_msgs::PoseStamped& cue);

  SharedTable& shared_;
  const NodeParameters& parameters_;
  CueFrames cue_frames_;
  ros::Publisher cue_publisher_, shot_publisher_;
  std::vector<ros::ServiceServer> services_;
};

}  // namespace cue_sim

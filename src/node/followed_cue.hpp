// A robot's cue followed in tf (~cue/frame): the node's adapter around session::CueFollower. It
// keeps a tf buffer of its own, filled from /tf and /tf_static on a thread of its own, and takes a
// sample of the cue in the table frame each time a transform comes that may move it (all but the
// node's own ball frames). A touch strikes the live table at the touch's stamp, through the same
// path as ~strike_cue (TableServices::strikeWithCue, ~shots with source "cue_frame"); every touch,
// struck or not, goes out on ~cue_contacts. The cue is drawn on ~cue (ns "cue_frame") as it moves.
#pragma once

#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <tf2_msgs/TFMessage.h>
#include <tf2_ros/buffer.h>

#include <memory>
#include <string>

#include "cue_sim/CueContact.h"
#include "cue_sim/session/cue_follower.hpp"
#include "node/node_parameters.hpp"
#include "node/shared_table.hpp"
#include "node/table_services.hpp"

namespace cue_sim
{
class FollowedCue
{
public:
  /// Follows parameters.cue.frame (which must not be empty) from now on.
  FollowedCue(ros::NodeHandle& private_node, SharedTable& shared, const NodeParameters& parameters,
              TableServices& services);
  ~FollowedCue();

private:
  void onTf(const tf2_msgs::TFMessage::ConstPtr& message);
  void onTfStatic(const tf2_msgs::TFMessage::ConstPtr& message);
  /// Whether a transform may move the cue: any but this node's own ball frames.
  bool mayMoveTheCue(const geometry_msgs::TransformStamped& transform) const;
  /// Takes the cue's latest pose in the table frame, if it is newer than the last taken.
  void sample();
  /// Strikes (or not) for a touch, and reports it on ~cue_contacts.
  void onContact(const session::CueContact& contact);
  void drawCue(const physics::CueStick& cue, const ros::Time& stamp);

  /// Seconds on the follower's clock: from the epoch, so that doubles keep nanoseconds.
  double secondsOf(const ros::Time& stamp) const { return (stamp - epoch_).toSec(); }
  ros::Time timeOf(double seconds) const { return epoch_ + ros::Duration(seconds); }

  SharedTable& shared_;
  const NodeParameters& parameters_;
  TableServices& services_;
  session::CueFollower follower_;
  ros::Time epoch_;
  ros::Time last_sample_;  ///< the stamp of the last sample taken
  ros::WallTime drawn_;    ///< when the cue was last drawn
  std::string last_note_;  ///< the last note logged (a gap, a jump), logged again only when it changes

  tf2_ros::Buffer buffer_;
  ros::CallbackQueue queue_;
  ros::NodeHandle node_;
  ros::Subscriber tf_subscriber_, tf_static_subscriber_;
  ros::Publisher contact_publisher_;
  std::unique_ptr<ros::AsyncSpinner> spinner_;
};

}  // namespace cue_sim

// The table node: the ROS adapter around the live table (session::LiveTable), run as its own
// process (table_node) or in a nodelet manager (cue_sim/TableNodelet), the same either way: it
// serves everything on callback queues and threads of its own. The thread that calls run()
// publishes tf, ~state, ~events, ~markers, ~game_state and (with use_sim_time) /clock at
// ~publish_rate and does nothing else (but hand the camera a copy of the balls when a frame is
// due); the light services (TableServices, GameServices) and dynamic_reconfigure run on two
// threads of their own, the aim marker on one, predictions (PredictionServices) on another. All
// share the table under one lock, held only while the table itself is touched.
#pragma once

#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>

#include <atomic>
#include <memory>
#include <string>

#include "node/aim_marker.hpp"
#include "node/camera_publisher.hpp"
#include "node/followed_cue.hpp"
#include "node/game_services.hpp"
#include "node/node_parameters.hpp"
#include "node/prediction_services.hpp"
#include "node/reconfigure.hpp"
#include "node/shared_table.hpp"
#include "node/table_services.hpp"

namespace cue_sim
{
class TableNode
{
public:
  /// Reads parameters and the table description; throws std::runtime_error saying which
  /// parameter is wrong and why. `node` is the node's namespace, `private_node` its own (~).
  TableNode(const ros::NodeHandle& node, const ros::NodeHandle& private_node);
  ~TableNode();

  /// Publishes at ~publish_rate until ROS shuts down or stop() is called; services are
  /// answered meanwhile on their own threads.
  void run();
  /// Makes run() return soon (from another thread): a nodelet being unloaded.
  void stop() { stopping_ = true; }

private:
  /// Brings the table up to now and publishes tf, ~state, ~events (and ~markers when the
  /// balls were placed anew, and every second) stamped with it.
  void tick();
  /// Without sim time: the calling (publishing) thread at a real-time priority, where granted.
  void raisePublishingPriority();
  /// With use_sim_time: moves the node's /clock on by its step for `wall` elapsed (simClockStep)
  /// and ticks there; true if the loop should wait a `period` before the next.
  bool advanceSimClock(const ros::WallDuration& wall, const ros::WallDuration& period);
  void publishStaticFrames(const std::string& urdf_xml);
  /// ~markers, from the table as it is (call it holding the lock).
  void publishMarkers(const session::LiveTable& table);
  void startAimMarker();

  /// Whether run() goes on publishing.
  bool running() const { return ros::ok() && !stopping_; }

  /// What the light services, dynamic_reconfigure and the camera's calibration service are
  /// answered from (by spinner_), and the node handles that file them there.
  ros::CallbackQueue queue_;
  ros::NodeHandle node_, private_node_;
  std::atomic<bool> stopping_{false};
  NodeParameters parameters_;
  SharedTable shared_;
  long markers_drawn_ = -1;  ///< the layout version last drawn on ~markers
  long preview_layout_ = 0;  ///< the layout version and strike count the preview may show
  long preview_strikes_ = 0;
  ros::WallTime markers_sent_;  ///< when ~markers last went out
  long aim_placed_at_ = -1;     ///< the layout the aim marker waits on at the cue ball (-1: balls moving)

  tf2_ros::TransformBroadcaster tf_broadcaster_;
  tf2_ros::StaticTransformBroadcaster static_broadcaster_;
  ros::Publisher state_publisher_, marker_publisher_, event_publisher_, clock_publisher_;
  std::unique_ptr<TableServices> services_;
  std::unique_ptr<GameServices> games_;
  std::unique_ptr<PredictionServices> predictions_;
  std::unique_ptr<PhysicsReconfigure> reconfigure_;
  std::unique_ptr<AimMarker> aim_marker_;
  std::unique_ptr<CameraPublisher> camera_;     ///< null with ~camera/enabled false
  std::unique_ptr<ros::AsyncSpinner> spinner_;  ///< the light services' threads
  std::unique_ptr<FollowedCue> followed_cue_;   ///< null without ~cue/frame; strikes through services_
};

}  // namespace cue_sim

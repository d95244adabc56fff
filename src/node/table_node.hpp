// table_node: the ROS adapter around the live table (session::LiveTable). One thread publishes
// tf, ~state and /clock at ~publish_rate and does nothing else; services run on other threads
// and change the table under one lock, held only while the table itself is touched. Heavy
// requests (predictions) run outside the lock on their own queue, and tf lookups for
// ~strike_cue wait at most ~tf_timeout, so that nothing a request does can hold the tick.
#pragma once

#include <cue_sim/PlaceBall.h>
#include <cue_sim/Predict.h>
#include <cue_sim/PredictBatch.h>
#include <cue_sim/Rack.h>
#include <cue_sim/RemoveBall.h>
#include <cue_sim/SetState.h>
#include <cue_sim/Step.h>
#include <cue_sim/Strike.h>
#include <cue_sim/StrikeCue.h>
#include <cue_sim/TableNodeConfig.h>
#include <dynamic_reconfigure/server.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <std_srvs/SetBool.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "cue_sim/physics/thread_pool.hpp"
#include "cue_sim/session/live_table.hpp"
#include "node/aim_marker.hpp"
#include "node/node_parameters.hpp"

namespace cue_sim
{
/// Nice value of the threads that run predictions: below the publishing thread.
constexpr int kHeavyNice = 10;
/// Lowers the calling thread's priority to kHeavyNice.
void lowerThisThreadsPriority();

class TableNode
{
public:
  /// Reads parameters and the table description; throws std::runtime_error saying which
  /// parameter is wrong and why.
  TableNode(ros::NodeHandle& node, ros::NodeHandle& private_node);

  /// Publishes at ~publish_rate until ROS shuts down; services are answered meanwhile on
  /// their own threads.
  void run();

private:
  /// Brings the table up to now and publishes tf, ~state, ~events (and ~markers when the
  /// balls were placed anew) stamped with it.
  void tick();
  /// The time now, under table_mutex_: with use_sim_time the node's own clock (roscpp's copy,
  /// set from /clock messages on the service threads, may lag behind it).
  ros::Time now() const { return sim_time_ ? sim_now_ : ros::Time::now(); }
  /// With use_sim_time: moves the node's /clock on by `by` and ticks there.
  void advanceSimClock(const ros::Duration& by);
  void publishStaticFrames(const std::string& urdf_xml);
  void publishMarkers(const session::LiveTable& table);
  void startAimMarker(ros::NodeHandle& private_node);
  void advertiseServices(ros::NodeHandle& private_node);
  /// Gives the memory heavy requests freed back to the system (on the heavy requests' thread).
  void trimMemory();

  // Services (table_services.cpp): each converts its request, calls the live table under the
  // lock, and converts the answer.
  bool onStrike(Strike::Request& request, Strike::Response& response);
  bool onStrikeCue(StrikeCue::Request& request, StrikeCue::Response& response);
  /// Strikes and publishes the cue and the shot on ~shots.
  session::StrikeOutcome strikeLive(const session::Shot& shot, const char* source);
  bool onPredict(Predict::Request& request, Predict::Response& response);
  bool onPredictBatch(PredictBatch::Request& request, PredictBatch::Response& response);
  bool onRack(Rack::Request& request, Rack::Response& response);
  bool onReset(std_srvs::Trigger::Request& request, std_srvs::Trigger::Response& response);
  bool onSetState(SetState::Request& request, SetState::Response& response);
  bool onPlaceBall(PlaceBall::Request& request, PlaceBall::Response& response);
  bool onRemoveBall(RemoveBall::Request& request, RemoveBall::Response& response);
  bool onPause(std_srvs::SetBool::Request& request, std_srvs::SetBool::Response& response);
  bool onStep(Step::Request& request, Step::Response& response);
  /// The cue pose in the table frame, or why not (an unknown frame, a bad quaternion).
  std::string cueInTableFrame(const geometry_msgs::PoseStamped& pose, physics::CueStick& cue);

  // dynamic_reconfigure (reconfigure.cpp): coefficients and models apply between shots.
  void onReconfigure(TableNodeConfig& config, uint32_t level);
  /// Empty if `config` can be applied (then it is), else why not.
  std::string applyConfig(const TableNodeConfig& config);

  NodeParameters parameters_;
  bool sim_time_ = false;      ///< use_sim_time: this node drives /clock
  double clock_factor_ = 1.0;  ///< sim time: /clock per wall time; 0 as fast as possible

  std::mutex table_mutex_;  ///< guards table_ and what is published from it
  std::optional<session::LiveTable> table_;
  long markers_drawn_ = -1;     ///< the layout version last drawn on ~markers
  ros::WallTime markers_sent_;  ///< when ~markers last went out
  long aim_placed_at_ = -1;     ///< the layout the aim marker waits on at the cue ball (-1: balls moving)
  ros::Time last_stamp_;
  ros::Time sim_now_;  ///< the time it last published on /clock

  std::unique_ptr<physics::ThreadPool> pool_;  ///< ~predict_batch's threads
  ros::CallbackQueue heavy_queue_;             ///< predictions: off the light services' threads
  std::unique_ptr<ros::AsyncSpinner> light_spinner_, heavy_spinner_;
  std::atomic<bool> heavy_done_{false};  ///< a heavy request ran since the last trim
  ros::WallTimer trim_timer_;

  tf2_ros::TransformBroadcaster tf_broadcaster_;
  tf2_ros::StaticTransformBroadcaster static_broadcaster_;
  ros::Publisher state_publisher_, marker_publisher_, event_publisher_, cue_publisher_, preview_publisher_,
      shot_publisher_, clock_publisher_;
  std::unique_ptr<tf2_ros::Buffer> tf_buffer_;
  std::unique_ptr<tf2_ros::TransformListener> tf_listener_;
  std::vector<ros::ServiceServer> services_;
  std::mutex reconfigure_mutex_;
  std::unique_ptr<dynamic_reconfigure::Server<TableNodeConfig>> reconfigure_;
  TableNodeConfig applied_config_;  ///< the last valid configuration
  std::unique_ptr<AimMarker> aim_marker_;
};

}  // namespace cue_sim

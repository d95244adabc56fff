// table_node: the ROS adapter around the physics engine. It owns the live table state,
// advances it to ros::Time at ~publish_rate, and publishes tf, ~state and ~markers; services
// change the state only after validating their request in full.
#pragma once

#include <cue_sim/Predict.h>
#include <cue_sim/PredictBatch.h>
#include <cue_sim/Rack.h>
#include <cue_sim/SetState.h>
#include <cue_sim/Step.h>
#include <cue_sim/Strike.h>
#include <cue_sim/StrikeCue.h>
#include <cue_sim/TableNodeConfig.h>
#include <dynamic_reconfigure/server.h>
#include <geometry_msgs/PoseStamped.h>
#include <ros/ros.h>
#include <std_srvs/SetBool.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>

#include <memory>
#include <optional>
#include <string>

#include "cue_sim/physics/cue_aim.hpp"
#include "cue_sim/physics/engine.hpp"
#include "cue_sim/physics/execution_noise.hpp"
#include "cue_sim/physics/simulation.hpp"
#include "cue_sim/physics/thread_pool.hpp"
#include "node/aim_marker.hpp"
#include "node/physics_clock.hpp"

namespace cue_sim
{
/// Every ball referred to time 0: a table at rest, as at a strike from rest (the node's physics
/// time restarts there, and predictions start there too).
physics::TableState<double> atTimeZero(physics::TableState<double> state);

class TableNode
{
public:
  /// Reads parameters and the table description; throws std::runtime_error saying what is
  /// wrong with them.
  TableNode(ros::NodeHandle& node, ros::NodeHandle& private_node);

  /// Publishes at ~publish_rate and answers services until ROS shuts down. One thread does
  /// both: at 1 kHz a timer thread handing each tick to the spinner costs more than the tick.
  void run();

private:
  struct Config
  {
    double publish_rate = 100.0;
    bool allow_strike_while_moving = false;
    std::string table_frame = "table";
    std::string world_frame = "world";
    std::string ball_frame_prefix = "ball_";
    std::string initial_rack = "eight";
    double rack_gap = 1e-5;
    double real_time_factor = 1.0;  ///< 0: as fast as possible (sim time only)
    bool noise_enabled = false;     ///< execution noise on ~strike
    physics::ExecutionNoise noise;
    int noise_seed = 0;
  };

  void loadTable(ros::NodeHandle& node, ros::NodeHandle& private_node);
  /// Brings the table up to `stamp` and publishes tf and ~state stamped with it.
  void tick(const ros::Time& stamp);
  /// With use_sim_time: moves the node's /clock on by `by` and ticks there.
  void advanceSimClock(const ros::Duration& by);
  void loadNoise(ros::NodeHandle& private_node);
  void startAimMarker(ros::NodeHandle& private_node);
  /// Brings the live state up to `stamp` (processing its events, published on ~events) and
  /// returns the physics time.
  double catchUp(const ros::Time& stamp);
  /// Makes `stamp` physics time 0 for a table at rest: every shot from rest then starts at
  /// time 0, as a prediction does, and gives the prediction's numbers bit for bit.
  void rebaseAtRest(const ros::Time& stamp);
  void setRack(physics::TableState<double> rack, const ros::Time& stamp);
  void publishStaticFrames(const std::string& urdf_xml);
  void publishMarkers();

  // Shots (shot_services.cpp).
  bool onStrike(Strike::Request& request, Strike::Response& response);
  bool onStrikeCue(StrikeCue::Request& request, StrikeCue::Response& response);
  /// Strikes the live table as ~strike does (noise, refusals) and fills the response.
  void strikeLive(const Shot& shot, const ros::Time& stamp, Strike::Response& response);
  /// The cue pose in the table frame, or why not (an unknown frame, a bad quaternion).
  std::string cueInTableFrame(const geometry_msgs::PoseStamped& pose, physics::CueStick& cue);
  bool onPredict(Predict::Request& request, Predict::Response& response);
  bool onPredictBatch(PredictBatch::Request& request, PredictBatch::Response& response);
  /// The table a prediction starts from: the given balls, or the live table if none are given
  /// (which must be at rest); every ball referred to time 0. Empty if it can, else why not.
  std::string predictionStart(const std::vector<BallState>& balls, physics::TableState<double>& start);

  // dynamic_reconfigure (reconfigure.cpp): coefficients and models apply between shots.
  void onReconfigure(TableNodeConfig& config, uint32_t level);
  /// Empty if the coefficients and models of `config` make a valid engine for the balls on the
  /// table, which it then builds into `engine`; else why not.
  std::string engineFor(const TableNodeConfig& config, std::shared_ptr<const physics::Engine<double>>& engine) const;
  void applyPendingPhysics();

  // Simulation control (control_services.cpp).
  bool onPause(std_srvs::SetBool::Request& request, std_srvs::SetBool::Response& response);
  bool onStep(Step::Request& request, Step::Response& response);
  bool onSetState(SetState::Request& request, SetState::Response& response);
  bool onRack(Rack::Request& request, Rack::Response& response);
  bool onReset(std_srvs::Trigger::Request& request, std_srvs::Trigger::Response& response);

  Config config_;
  std::shared_ptr<const physics::TableModel> table_;
  std::shared_ptr<const physics::Engine<double>> engine_;
  /// The live table: its state and the event search kept from tick to tick.
  std::optional<physics::Simulation<double>> live_;
  physics::TableState<double> last_rack_;
  std::vector<physics::Ball<double>> snapshot_;  ///< the balls as last published
  bool snapshot_at_rest_ = false;                ///< and nothing has moved since
  physics::NoisyCue live_cue_;                   ///< ~strike's execution noise
  std::unique_ptr<physics::ThreadPool> pool_;    ///< ~predict_batch's threads
  PhysicsClock clock_;
  bool sim_time_ = false;  ///< use_sim_time: this node drives /clock
  bool paused_ = false;
  ros::Time sim_now_;  ///< the time it last published on /clock
  ros::Time last_stamp_;

  tf2_ros::TransformBroadcaster tf_broadcaster_;
  tf2_ros::StaticTransformBroadcaster static_broadcaster_;
  ros::Publisher state_publisher_;
  ros::Publisher marker_publisher_;
  ros::Publisher event_publisher_;
  ros::Publisher cue_publisher_;      ///< the cue stick at a strike
  ros::Publisher preview_publisher_;  ///< the paths of the last ~predict
  /// Listening to tf starts with the first cue pose in another frame than the table's.
  std::unique_ptr<tf2_ros::Buffer> tf_buffer_;
  std::unique_ptr<tf2_ros::TransformListener> tf_listener_;
  ros::Publisher clock_publisher_;
  std::vector<ros::ServiceServer> services_;
  std::unique_ptr<dynamic_reconfigure::Server<TableNodeConfig>> reconfigure_;
  std::unique_ptr<AimMarker> aim_marker_;                          ///< rviz: aim and fire at the cue ball
  TableNodeConfig applied_config_;                                 ///< the last valid configuration
  std::shared_ptr<const physics::Engine<double>> pending_engine_;  ///< waiting for the balls to rest
};

}  // namespace cue_sim

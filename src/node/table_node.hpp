// table_node: the ROS adapter around the physics engine. It owns the live table state,
// advances it to ros::Time at ~publish_rate, and publishes tf, ~state and ~markers; services
// change the state only after validating their request in full.
#pragma once

#include <cue_sim/Rack.h>
#include <cue_sim/Strike.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>

#include <memory>
#include <string>

#include "cue_sim/physics/engine.hpp"

namespace cue_sim
{
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
  };

  void loadTable(ros::NodeHandle& node, ros::NodeHandle& private_node);
  void tick();
  /// Physics time [s] of a ROS time: seconds since the node started.
  double physicsTime(const ros::Time& stamp) const;
  /// Brings the live state up to `stamp` (processing its events) and returns the physics time.
  double catchUp(const ros::Time& stamp);
  void setRack(physics::TableState<double> rack, double now);
  void publishStaticFrames(const std::string& urdf_xml);
  void publishMarkers();

  bool onStrike(Strike::Request& request, Strike::Response& response);
  bool onRack(Rack::Request& request, Rack::Response& response);
  bool onReset(std_srvs::Trigger::Request& request, std_srvs::Trigger::Response& response);

  Config config_;
  std::shared_ptr<const physics::TableModel> table_;
  std::unique_ptr<physics::Engine<double>> engine_;
  physics::TableState<double> state_;
  physics::TableState<double> last_rack_;
  std::vector<physics::Ball<double>> snapshot_;  ///< the balls as last published
  bool snapshot_at_rest_ = false;                ///< and nothing has moved since
  ros::Time epoch_;
  ros::Time last_stamp_;

  tf2_ros::TransformBroadcaster tf_broadcaster_;
  tf2_ros::StaticTransformBroadcaster static_broadcaster_;
  ros::Publisher state_publisher_;
  ros::Publisher marker_publisher_;
  ros::ServiceServer strike_service_, rack_service_, reset_service_;
};

}  // namespace cue_sim

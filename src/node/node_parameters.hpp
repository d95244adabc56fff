// table_node's parameters (config/table_node.yaml, config/physics.yaml): read once at start,
// each checked with its name, its value and the accepted range.
#pragma once

#include <ros/ros.h>

#include <array>
#include <cmath>
#include <memory>
#include <string>

#include "cue_sim/camera/pinhole_camera.hpp"
#include "cue_sim/physics/collision_models.hpp"
#include "cue_sim/physics/physics_params.hpp"
#include "cue_sim/physics/table_model.hpp"
#include "cue_sim/session/cue_follower.hpp"
#include "cue_sim/session/live_table.hpp"

namespace cue_sim
{
/// The simulated camera (node/camera_publisher.hpp), ~camera/...
struct CameraParameters
{
  bool enabled = true;
  std::string frame = "camera_optical_frame";  ///< its optical frame, looked up in tf from the table frame
  double rate = 30.0;                          ///< [Hz] of stamp time, in (0, 120]
  double exposure = 0.004;                     ///< [s] shutter open, in [0, 0.1]
  double noise = 0.0;                          ///< [8-bit levels] Gaussian sensor noise, in [0, 50]
  /// Images a subscriber may fall behind before its oldest is dropped, in [1, 1000]: few live
  /// (the newest image matters), more for a recording that wants every one (a busy detector).
  int queue_size = 2;
  std::string info_url = "package://cue_sim/config/camera/overhead_1920x1200.yaml";
  int width = 0, height = 0;  ///< [px] the calibrated sensor read out scaled to this size; 0: as calibrated
  /// Broadcast `frame` in /tf_static at `pose`; false: something else (a robot's tf) places it.
  bool publish_frame = true;
  /// The optical frame in the table frame: x, y, z [m], roll, pitch, yaw [rad] (tf's fixed-axis
  /// convention: R = Rz(yaw) Ry(pitch) Rx(roll)). Default: 2.4 m over the centre, looking down.
  std::array<double, 6> pose{0, 0, camera::kOverheadHeight, M_PI, 0, 0};
};

/// A robot's cue followed in tf (node/followed_cue.hpp), ~cue/...
struct CueParameters
{
  /// The cue's frame: its origin the end of the tip on the cue's axis, x along the stroke (butt to
  /// tip), as ~strike_cue takes a pose. Empty: no cue is followed.
  std::string frame;
  /// The rest, ~cue/<name> each, declared with their ranges in session::cueFollowerFields().
  session::CueFollowerSettings follower;
};

struct NodeParameters
{
  double publish_rate = 100.0;  ///< [Hz] tf, ~state, /clock
  std::string table_frame = "table";
  std::string world_frame = "world";
  std::string ball_frame_prefix = "ball_";
  std::string rack = "eight";
  double real_time_factor = 1.0;  ///< 0: as fast as possible (use_sim_time only)
  double tf_timeout = 0.05;       ///< [s] ~strike_cue waits at most this long for tf
  bool aim_marker = true;
  session::LiveTableOptions table;
  physics::PhysicsParams<double> physics;
  physics::ModelChoice models;
  std::shared_ptr<const physics::TableModel> table_model;
  std::string urdf_xml;  ///< the table description, for its static frames
  CameraParameters camera;
  CueParameters cue;
};

/// Longest accepted ~tf_timeout [s]: a lookup holds one service thread at most this long.
constexpr double kMaxTfTimeout = 1.0;
/// Largest accepted ~camera/queue_size: 1000 images of 1920x1200 (6.9 MB each) are 6.9 GB a
/// stalled subscriber could hold in the node; more is a mistake, not a need.
constexpr int kMaxCameraQueue = 1000;

/// Reads and checks every parameter; throws std::runtime_error naming the first one that is
/// wrong, its value and its accepted range.
NodeParameters readNodeParameters(ros::NodeHandle& node, ros::NodeHandle& private_node, bool sim_time);

}  // namespace cue_sim

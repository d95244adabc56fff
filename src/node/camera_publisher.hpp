// The simulated camera in table_node: ~camera/image_raw and ~camera/camera_info (image_transport,
// calibration from camera_info_manager) and ~camera/ground_truth, at ~camera/rate of stamp time.
// It lives in the table node because its motion blur needs the balls' exact trajectories: at a
// frame's time the publishing thread hands it a copy of the live table, and its own thread
// advances the copy across the exposure and renders it (camera::TableCamera), stamped at the
// exposure's middle: a strike that lands inside an exposure shows from the next frame on. Nothing
// is copied or drawn while no one subscribes; a frame that comes due while the last one is still
// drawn is skipped, so tf never waits on the camera.
#pragma once

#include <camera_info_manager/camera_info_manager.h>
#include <image_transport/image_transport.h>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "cue_sim/camera/table_camera.hpp"
#include "cue_sim/session/live_table.hpp"
#include "node/node_parameters.hpp"

namespace cue_sim
{
class CameraPublisher
{
public:
  /// Throws std::runtime_error naming the parameter (the calibration's size, its intrinsics).
  CameraPublisher(ros::NodeHandle& private_node, const CameraParameters& parameters, const std::string& table_frame);
  ~CameraPublisher();

  /// Whether a frame is wanted at `stamp`: someone subscribes, one is due, none is being drawn.
  bool due(const ros::Time& stamp) const;
  /// Hands the camera the table as of `stamp` (call it holding the table's lock; it copies).
  void take(const session::LiveTable& table, const ros::Time& stamp);
  /// The pose ~camera/x ... yaw give the camera's frame in the table frame.
  static camera::Pose poseOf(const CameraParameters& parameters);

private:
  /// What a frame is drawn from: the live table's balls and clock as of `stamp`, copied.
  struct Job
  {
    session::LiveBalls balls;
    session::TableClock clock;
    ros::Time stamp;
  };
  void loop();
  void photograph(Job& job);
  /// Counts the subscribers to the image (any transport), its camera_info and the ground truth,
  /// as roscpp connects and disconnects them (on a service thread). due() reads the count: asking
  /// roscpp (getNumSubscribers) takes locks its network thread holds, and the publishing thread
  /// then waited up to 18 ms behind that normal-priority thread on a busy machine.
  void listenerJoined() { ++listeners_; }
  void listenerLeft() { --listeners_; }
  /// The camera's pose in the table frame: where the node put its frame, else from tf, else (warned
  /// about) the default overhead pose.
  camera::Pose lookUpPose(const physics::TableModel& table);

  /// The renderer for this table and ball size, made anew when the physics changed them.
  camera::TableCamera& cameraFor(const physics::Engine<double>& engine);

  CameraParameters parameters_;
  std::string table_frame_;
  camera::Intrinsics intrinsics_;
  sensor_msgs::CameraInfo info_;
  ros::NodeHandle camera_node_;
  std::unique_ptr<camera_info_manager::CameraInfoManager> info_manager_;
  std::unique_ptr<image_transport::ImageTransport> transport_;
  image_transport::CameraPublisher image_publisher_;
  ros::Publisher truth_publisher_;
  std::atomic<int> listeners_{0};
  std::unique_ptr<tf2_ros::Buffer> tf_buffer_;  ///< only when something else places the frame
  std::unique_ptr<tf2_ros::TransformListener> tf_listener_;
  std::optional<camera::TableCamera> camera_;
  double camera_radius_ = 0, camera_cushion_ = 0;  ///< what camera_ was made for
  /// Images a frame is drawn into and published as a shared pointer: a subscriber in the same
  /// process (a nodelet in the node's manager) gets the pointer, not a copy. An image is drawn
  /// into again once no one else holds it, so its pages are not allocated anew every frame.
  std::vector<sensor_msgs::ImagePtr> images_;
  /// An image no subscriber holds any more, or a new one if all are held (at most kKeptImages kept).
  sensor_msgs::ImagePtr freeImage();

  mutable std::mutex mutex_;  ///< guards job_, busy_, next_due_, stop_
  std::condition_variable wake_;
  std::optional<Job> job_;
  bool busy_ = false, stop_ = false;
  ros::Time next_due_;
  std::thread thread_;
};

}  // namespace cue_sim

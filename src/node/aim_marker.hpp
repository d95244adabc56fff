// An interactive marker to aim and fire from rviz: drag the handle on the cloth to set the
// cue ball's heading (from the ball to the handle) and the cue's speed (the handle's distance
// from the ball, kSpeedPerMetre per metre); right-click it for "Strike" or "Predict".
#pragma once

#include <cue_sim/Shot.h>
#include <interactive_markers/interactive_marker_server.h>
#include <interactive_markers/menu_handler.h>

#include <Eigen/Core>
#include <functional>
#include <mutex>
#include <string>

namespace cue_sim
{
class AimMarker
{
public:
  static constexpr double kSpeedPerMetre = 4.0;  ///< [m/s per m]: 0.5 m of arrow is a 2 m/s cue
  using ShotCallback = std::function<void(const Shot&)>;

  /// Serves the marker on <topic_ns>/update and <topic_ns>/feedback; callbacks run on the
  /// server's own thread. place() may be called from another thread.
  AimMarker(const std::string& topic_ns, const std::string& frame, double ball_radius, ShotCallback strike,
            ShotCallback predict);

  /// Puts the marker at the cue ball, keeping the aim (heading and speed) it had.
  void place(const Eigen::Vector2d& cue_ball);
  /// The shot the marker aims now.
  Shot shot() const;

private:
  Shot shotLocked() const;
  void onFeedback(const visualization_msgs::InteractiveMarkerFeedbackConstPtr& feedback);
  void publish();

  interactive_markers::InteractiveMarkerServer server_;
  interactive_markers::MenuHandler menu_;
  std::string frame_;
  double ball_radius_;
  ShotCallback strike_, predict_;
  mutable std::mutex mutex_;  ///< guards the aim: place() comes from the publishing thread
  Eigen::Vector2d cue_ball_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d aim_ = Eigen::Vector2d(0.5, 0);  ///< handle minus cue ball [m]
};

}  // namespace cue_sim

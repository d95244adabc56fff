#include "node/aim_marker.hpp"

#include <algorithm>
#include <cmath>

namespace cue_sim
{
using visualization_msgs::InteractiveMarker;
using visualization_msgs::InteractiveMarkerControl;
using visualization_msgs::InteractiveMarkerFeedback;
using visualization_msgs::Marker;

namespace
{
const char* const kName = "aim";
}

AimMarker::AimMarker(const std::string& topic_ns, const std::string& frame, double ball_radius, ShotCallback strike,
                     ShotCallback predict)
  : server_(topic_ns, "", true),
    frame_(frame),
    ball_radius_(ball_radius),
    strike_(std::move(strike)),
    predict_(std::move(predict))
{
  menu_.insert("Strike", [this](const visualization_msgs::InteractiveMarkerFeedbackConstPtr&) { strike_(shot()); });
  menu_.insert("Predict", [this](const visualization_msgs::InteractiveMarkerFeedbackConstPtr&) { predict_(shot()); });
}

Shot AimMarker::shot() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return shotLocked();
}

Shot AimMarker::shotLocked() const
{
  Shot s;
  s.ball_id = 0;
  s.phi = std::atan2(aim_.y(), aim_.x());
  s.speed = std::min(12.0, kSpeedPerMetre * aim_.norm());
  return s;
}

void AimMarker::place(const Eigen::Vector2d& cue_ball)
{
  std::lock_guard<std::mutex> lock(mutex_);
  cue_ball_ = cue_ball;
  publish();
}

void AimMarker::onFeedback(const visualization_msgs::InteractiveMarkerFeedbackConstPtr& feedback)
{
  if (feedback->event_type == InteractiveMarkerFeedback::POSE_UPDATE)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const Eigen::Vector2d handle(feedback->pose.position.x, feedback->pose.position.y);
    if ((handle - cue_ball_).norm() > 1e-3)
      aim_ = handle - cue_ball_;
    publish();
  }
  else if (feedback->event_type == InteractiveMarkerFeedback::MOUSE_UP)
    predict_(shot());  // the paths of the shot as aimed
}

void AimMarker::publish()
{
  InteractiveMarker marker;
  marker.header.frame_id = frame_;
  marker.name = kName;
  marker.description = "";
  marker.scale = 0.1;
  marker.pose.position.x = cue_ball_.x() + aim_.x();
  marker.pose.position.y = cue_ball_.y() + aim_.y();
  marker.pose.position.z = ball_radius_;
  marker.pose.orientation.w = 1;

  // The handle, dragged on the cloth, and the arrow from the cue ball to it.
  InteractiveMarkerControl drag;
  drag.name = "aim";
  drag.orientation.w = 1 / std::sqrt(2.0);
  drag.orientation.y = 1 / std::sqrt(2.0);  // the plane's normal (the control's x axis) is z
  drag.interaction_mode = InteractiveMarkerControl::MOVE_PLANE;
  drag.always_visible = true;
  Marker handle;
  handle.type = Marker::SPHERE;
  handle.scale.x = handle.scale.y = handle.scale.z = 0.04;
  handle.color.r = 1.0f;
  handle.color.g = 0.85f;
  handle.color.b = 0.2f;
  handle.color.a = 1.0f;
  drag.markers.push_back(handle);
  Marker arrow;
  arrow.type = Marker::ARROW;
  arrow.scale.x = 0.01;  // shaft diameter
  arrow.scale.y = 0.025;
  arrow.scale.z = 0.04;
  arrow.color = handle.color;
  arrow.color.a = 0.8f;
  geometry_msgs::Point from, to;  // in the marker's frame: from the cue ball to the handle
  from.x = -aim_.x();
  from.y = -aim_.y();
  arrow.points = {from, to};
  drag.markers.push_back(arrow);
  marker.controls.push_back(drag);
  // No MENU control: rviz opens the marker's menu (Strike, Predict) on a right-click of any of its
  // controls, and it would draw a MENU control without markers as a text of the (empty)
  // description, logging an error each time.

  server_.insert(marker, [this](const visualization_msgs::InteractiveMarkerFeedbackConstPtr& f) { onFeedback(f); });
  menu_.apply(server_, kName);
  server_.applyChanges();
}

}  // namespace cue_sim

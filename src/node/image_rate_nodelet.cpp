// cue_sim/ImageRate: a consumer of images that does nothing with them but count them and time
// their arrival, and says so every ~report_period seconds. In the table's nodelet manager it gets
// the camera's images as shared pointers; on its own (nodelet standalone) over TCP.
// scripts/camera_cpu.sh measures what each costs the table node.
#include <nodelet/nodelet.h>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>

#include <mutex>
#include <pluginlib/class_list_macros.hpp>

namespace cue_sim
{
class ImageRate : public nodelet::Nodelet
{
private:
  void onInit() override
  {
    double period = 5.0;
    getPrivateNodeHandle().param("report_period", period, period);
    subscriber_ = getNodeHandle().subscribe("image", 2, &ImageRate::onImage, this);
    timer_ = getNodeHandle().createWallTimer(ros::WallDuration(period), &ImageRate::report, this);
    since_ = ros::WallTime::now();
  }

  void onImage(const sensor_msgs::ImageConstPtr& image)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ++frames_;
    latency_ += (ros::Time::now() - image->header.stamp).toSec();
    bytes_ += image->data.size();
  }

  void report(const ros::WallTimerEvent&)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const ros::WallTime now = ros::WallTime::now();
    const double seconds = (now - since_).toSec();
    NODELET_INFO("image_rate: %ld frames in %.2f s: %.2f Hz, %.1f MB/s, mean latency %.1f ms", frames_, seconds,
                 frames_ / seconds, bytes_ / seconds / 1e6, frames_ > 0 ? 1e3 * latency_ / frames_ : 0.0);
    frames_ = 0;
    bytes_ = 0;
    latency_ = 0;
    since_ = now;
  }

  ros::Subscriber subscriber_;
  ros::WallTimer timer_;
  std::mutex mutex_;
  long frames_ = 0;
  double bytes_ = 0, latency_ = 0;
  ros::WallTime since_;
};

}  // namespace cue_sim

PLUGINLIB_EXPORT_CLASS(cue_sim::ImageRate, nodelet::Nodelet)

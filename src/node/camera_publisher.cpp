#include "node/camera_publisher.hpp"

#include <geometry_msgs/TransformStamped.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/image_encodings.h>

#include "cue_sim/CameraGroundTruth.h"
#include "cue_sim/camera/exposure.hpp"
#include "node/thread_priority.hpp"

namespace cue_sim
{
namespace
{
camera::Intrinsics intrinsicsOf(const sensor_msgs::CameraInfo& info)
{
  camera::Intrinsics k;
  k.width = static_cast<int>(info.width);
  k.height = static_cast<int>(info.height);
  k.fx = info.K[0];
  k.fy = info.K[4];
  k.cx = info.K[2];
  k.cy = info.K[5];
  for (std::size_t i = 0; i < k.distortion.size() && i < info.D.size(); ++i)
    k.distortion[i] = info.D[i];
  return k;
}

/// camera_info for the intrinsics the camera renders with (scaled, when it is).
sensor_msgs::CameraInfo infoOf(const camera::Intrinsics& k, const std::string& frame)
{
  sensor_msgs::CameraInfo info;
  info.header.frame_id = frame;
  info.width = static_cast<std::uint32_t>(k.width);
  info.height = static_cast<std::uint32_t>(k.height);
  info.distortion_model = "plumb_bob";
  info.D.assign(k.distortion.begin(), k.distortion.end());
  info.K = {k.fx, 0, k.cx, 0, k.fy, k.cy, 0, 0, 1};
  info.R = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  info.P = {k.fx, 0, k.cx, 0, 0, k.fy, k.cy, 0, 0, 0, 1, 0};
  return info;
}
}  // namespace

CameraPublisher::CameraPublisher(ros::NodeHandle& private_node, const CameraParameters& parameters,
                                 const std::string& table_frame)
  : parameters_(parameters), table_frame_(table_frame), camera_node_(private_node, "camera")
{
  info_manager_ = std::make_unique<camera_info_manager::CameraInfoManager>(camera_node_, "overhead");
  if (!info_manager_->validateURL(parameters.info_url) || !info_manager_->loadCameraInfo(parameters.info_url) ||
      !info_manager_->isCalibrated())
    throw std::runtime_error("~camera/info_url: cannot load a calibration from '" + parameters.info_url + "'");
  intrinsics_ = intrinsicsOf(info_manager_->getCameraInfo());
  if (parameters.width > 0)  // and height: readNodeParameters takes both or neither
    intrinsics_ = intrinsics_.scaled(parameters.width, parameters.height);
  const std::string why = intrinsics_.whyInvalid();
  if (!why.empty())
    throw std::runtime_error("~camera/info_url '" + parameters.info_url + "': " + why);
  info_ = infoOf(intrinsics_, parameters.frame);
  transport_ = std::make_unique<image_transport::ImageTransport>(camera_node_);
  const auto image_joined = [this](const image_transport::SingleSubscriberPublisher&) { listenerJoined(); };
  const auto image_left = [this](const image_transport::SingleSubscriberPublisher&) { listenerLeft(); };
  const auto joined = [this](const ros::SingleSubscriberPublisher&) { listenerJoined(); };
  const auto left = [this](const ros::SingleSubscriberPublisher&) { listenerLeft(); };
  image_publisher_ = transport_->advertiseCamera("image_raw", static_cast<uint32_t>(parameters.queue_size),
                                                 image_joined, image_left, joined, left);
  truth_publisher_ = camera_node_.advertise<cue_sim::CameraGroundTruth>("ground_truth", 10, joined, left);
  if (!parameters.publish_frame)
  {
    // Something else places the frame (a robot's tf): listen from the start, so that the first
    // frame finds it.
    tf_buffer_ = std::make_unique<tf2_ros::Buffer>();
    tf_listener_ = std::make_unique<tf2_ros::TransformListener>(*tf_buffer_);
  }
  thread_ = std::thread([this] { loop(); });
}

CameraPublisher::~CameraPublisher()
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

bool CameraPublisher::due(const ros::Time& stamp) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (busy_ || job_ || stamp < next_due_)
    return false;
  return listeners_ > 0;
}

void CameraPublisher::take(const session::LiveTable& table, const ros::Time& stamp)
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    // Frames on the rate's grid of stamp time, each at the first tick at or after its time; a
    // time missed while the last frame was drawn is skipped, and no two frames are closer than
    // half a period (a late frame is not followed at once by the next grid time's).
    const double period = 1.0 / parameters_.rate;
    if (next_due_.isZero() || (stamp - next_due_).toSec() >= period)
      next_due_ = stamp;  // the first frame, or after a gap: the grid starts again here
    while (next_due_ <= stamp || (next_due_ - stamp).toSec() < period / 2)
      next_due_ += ros::Duration(period);
    job_.emplace(Job{table.motion(), table.clock(), stamp});
  }
  wake_.notify_one();
}

void CameraPublisher::loop()
{
  lowerThisThreadsPriority();  // rendering never delays tf
  while (true)
  {
    std::optional<Job> job;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [this] { return stop_ || job_; });
      if (stop_)
        return;
      job = std::move(job_);
      job_.reset();
      busy_ = true;
    }
    try
    {
      photograph(*job);
    }
    catch (const std::exception& e)
    {
      ROS_ERROR_THROTTLE(5.0, "cue_sim: camera: %s", e.what());
    }
    std::lock_guard<std::mutex> lock(mutex_);
    busy_ = false;
  }
}

camera::Pose CameraPublisher::poseOf(const CameraParameters& parameters)
{
  const auto& x = parameters.pose;
  camera::Pose pose = camera::Pose::Identity();
  pose.translation() = Eigen::Vector3d(x[0], x[1], x[2]);
  pose.linear() =
      (Eigen::AngleAxisd(x[5], Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(x[4], Eigen::Vector3d::UnitY()) *
       Eigen::AngleAxisd(x[3], Eigen::Vector3d::UnitX()))
          .toRotationMatrix();
  return pose;
}

camera::Pose CameraPublisher::lookUpPose(const physics::TableModel& table)
{
  // The node placed the frame itself: no need to ask tf (and no wait for it).
  if (parameters_.publish_frame)
    return poseOf(parameters_);
  try
  {
    const geometry_msgs::TransformStamped t =
        tf_buffer_->lookupTransform(table_frame_, parameters_.frame, ros::Time(0));
    camera::Pose pose = camera::Pose::Identity();
    pose.translation() =
        Eigen::Vector3d(t.transform.translation.x, t.transform.translation.y, t.transform.translation.z);
    pose.linear() = Eigen::Quaterniond(t.transform.rotation.w, t.transform.rotation.x, t.transform.rotation.y,
                                       t.transform.rotation.z)
                        .normalized()
                        .toRotationMatrix();
    return pose;
  }
  catch (const tf2::TransformException& e)
  {
    ROS_WARN_THROTTLE(10.0,
                      "cue_sim: camera: no transform %s -> %s in tf yet (%s); until there is one, the camera looks "
                      "down from %.1f m over the table's centre",
                      table_frame_.c_str(), parameters_.frame.c_str(), e.what(), camera::kOverheadHeight);
    return camera::overheadPose(table.clothCentre(), camera::kOverheadHeight);
  }
}

camera::TableCamera& CameraPublisher::cameraFor(const physics::Engine<double>& engine)
{
  const auto& p = engine.params();
  if (!camera_ || camera_radius_ != p.ball_radius || camera_cushion_ != p.cushion_height)
  {
    camera::CameraOptions options;
    options.noise_stddev = parameters_.noise;
    camera_.emplace(engine.table(), p.ball_radius, p.cushion_height, intrinsics_, lookUpPose(engine.table()), options);
    camera_radius_ = p.ball_radius;
    camera_cushion_ = p.cushion_height;
  }
  return *camera_;
}

void CameraPublisher::photograph(Job& job)
{
  camera::TableCamera& camera = cameraFor(job.balls.engine());
  camera.setPose(lookUpPose(job.balls.engine().table()));
  const ros::Duration half(parameters_.exposure / 2);
  const session::Stamp start = static_cast<session::Stamp>(job.stamp.toNSec());
  const ros::Time stamp = job.stamp + half;  // the middle of the exposure
  const bool pixels = image_publisher_.getNumSubscribers() > 0;
  camera::Frame frame;
  std::vector<camera::BallPose> middle;
  sensor_msgs::ImagePtr image;
  if (pixels)
  {
    const camera::Exposure exposure = camera::exposureOf(std::move(job.balls), job.clock, start, parameters_.exposure);
    const camera::Intrinsics& k = camera.intrinsics();
    image = freeImage();
    image->data.resize(static_cast<std::size_t>(k.width) * k.height * 3);
    cv::Mat view(k.height, k.width, CV_8UC3, image->data.data());
    frame.balls = camera.render(exposure, view);
    middle = exposure.instants[exposure.instants.size() / 2];
  }
  else
  {
    camera::advanceTo(job.balls, job.clock, static_cast<session::Stamp>(stamp.toNSec()));
    middle = camera::posesOf(job.balls);
    frame.balls = camera.groundTruth(middle);
  }

  cue_sim::CameraGroundTruth truth;
  truth.header.stamp = stamp;
  truth.header.frame_id = parameters_.frame;
  truth.table_frame = table_frame_;
  for (std::size_t i = 0; i < frame.balls.size(); ++i)
  {
    cue_sim::BallPixel b;
    b.id = frame.balls[i].id;
    b.u = frame.balls[i].pixel.x();
    b.v = frame.balls[i].pixel.y();
    b.radius = frame.balls[i].radius;
    b.visible = frame.balls[i].visible;
    b.position.x = middle[i].centre.x();
    b.position.y = middle[i].centre.y();
    b.position.z = middle[i].centre.z();
    truth.balls.push_back(b);
  }
  truth_publisher_.publish(truth);
  if (!pixels)
    return;
  image->header = truth.header;
  image->height = static_cast<std::uint32_t>(intrinsics_.height);
  image->width = static_cast<std::uint32_t>(intrinsics_.width);
  image->encoding = sensor_msgs::image_encodings::BGR8;
  image->step = image->width * 3;
  const sensor_msgs::CameraInfoPtr info = boost::make_shared<sensor_msgs::CameraInfo>(info_);
  info->header = truth.header;
  // As shared pointers: subscribers in this process get them as they are, others a serialised copy.
  image_publisher_.publish(image, info);
}

sensor_msgs::ImagePtr CameraPublisher::freeImage()
{
  // Images a subscriber in this process still holds are not drawn into; a few are kept, so that
  // a slow subscriber costs at most that many images.
  constexpr std::size_t kKeptImages = 4;
  for (const sensor_msgs::ImagePtr& image : images_)
    if (image.use_count() == 1)
      return image;
  auto image = boost::make_shared<sensor_msgs::Image>();
  if (images_.size() < kKeptImages)
    images_.push_back(image);
  return image;
}

}  // namespace cue_sim

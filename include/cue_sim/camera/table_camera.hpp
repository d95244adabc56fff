// A simulated camera over the table: what it would see of the cloth, cushions, rails, pockets
// and balls (colours, stripes, numbers, turned as the balls are), lit simply, with the motion
// blur of its exposure and optional sensor noise, and where each ball's centre lands in the
// image (the ground truth a detector is scored against). No ROS: camera_node publishes it.
//
// Rendering is ray casting per pixel through the calibrated lens (distortion included): the
// table, which never moves, once per camera pose into a background; then each ball over its own
// box in the image, at every instant of the exposure, averaged with what lies behind it.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <opencv2/core.hpp>
#include <random>
#include <string>
#include <vector>

#include "cue_sim/camera/pinhole_camera.hpp"
#include "cue_sim/physics/table_model.hpp"

namespace cue_sim
{
namespace camera
{
/// A ball at one instant.
struct BallPose
{
  int id = 0;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();                 ///< [m] table frame
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< ball frame to table frame
  bool in_play = true;                                              ///< false once pocketed: not drawn
};

/// The balls through one exposure: their poses at the middles of equal slices of it, in time
/// order (one instant when nothing moves). Every instant lists the same balls in the same order.
struct Exposure
{
  std::vector<std::vector<BallPose>> instants;
};

/// Where a ball is in the image at the exposure's middle: the ground truth.
struct BallPixel
{
  int id = 0;
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();  ///< [px] its centre's image, lens distortion included
  double radius = 0;                                ///< [px] its apparent radius (focal length x R / depth)
  bool visible = false;                             ///< in play, in front of the camera and its centre inside the image
};

struct Frame
{
  cv::Mat image;  ///< 8-bit BGR, intrinsics' width x height
  std::vector<BallPixel> balls;
};

struct CameraOptions
{
  double noise_stddev = 0;  ///< [8-bit levels] Gaussian sensor noise per pixel and channel, in [0, 50]
  std::uint64_t noise_seed = 0;

  /// Empty if every option is in its range, else which one is not and why.
  std::string whyInvalid() const;
};

class TableCamera
{
public:
  /// The camera at `pose`. Throws std::invalid_argument naming the intrinsics' or option's problem.
  TableCamera(const physics::TableModel& table, double ball_radius, double cushion_height, const Intrinsics& intrinsics,
              const Pose& pose, const CameraOptions& options = {});
  ~TableCamera();
  TableCamera(TableCamera&&) noexcept;

  const Intrinsics& intrinsics() const { return intrinsics_; }
  /// Places the camera (its optical frame in the table frame); the background is drawn again
  /// only when the pose changes.
  void setPose(const Pose& pose);
  const Pose& pose() const { return pose_; }
  /// The picture of one exposure, and each ball's ground truth at its middle instant.
  Frame render(const Exposure& exposure);
  /// The same into `image` (8-bit BGR, reallocated only if it is not the image's size): a caller
  /// that keeps its buffer (a message's) draws each frame without allocating it again.
  std::vector<BallPixel> render(const Exposure& exposure, cv::Mat& image);
  /// The ground truth alone (cheap: no pixels drawn).
  std::vector<BallPixel> groundTruth(const std::vector<BallPose>& balls) const;

private:
  class Scene;
  /// The table (everything but the balls) from pose_, once per pose.
  void drawBackground();
  /// Each ball over its box, at every instant of the exposure, averaged with what lies behind.
  void drawBalls(const Exposure& exposure, cv::Mat& image);
  Intrinsics intrinsics_;
  CameraOptions options_;
  Pose pose_;
  double ball_radius_;
  double cushion_height_ = 0;
  std::unique_ptr<Scene> scene_;
  cv::Mat background_;
  cv::Mat noise_;  ///< kept between frames, as the image's buffer is
  std::mt19937_64 noise_rng_;
};

}  // namespace camera
}  // namespace cue_sim

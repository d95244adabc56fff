// A pinhole camera with plumb-bob lens distortion, as ROS's sensor_msgs/CameraInfo and
// OpenCV describe it (Brown-Conrady: radial k1, k2, k3 and tangential p1, p2), in its optical
// frame (REP 103: z forward, x right, y down in the image).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <string>

namespace cue_sim
{
namespace camera
{
struct Intrinsics
{
  int width = 1920, height = 1200;     ///< [px]
  double fx = 1365, fy = 1365;         ///< focal lengths [px]
  double cx = 959.5, cy = 599.5;       ///< principal point [px]
  std::array<double, 5> distortion{};  ///< plumb_bob: k1, k2, p1, p2, k3

  /// The same lens on a sensor read out at width x height (binned or scaled): focal lengths and
  /// principal point scaled with the image.
  Intrinsics scaled(int new_width, int new_height) const;
  /// Empty if usable, else which field is wrong and why.
  std::string whyInvalid() const;
  bool distorted() const;
};

/// Where the camera is: its optical frame in the table frame.
using Pose = Eigen::Isometry3d;

/// The default camera's height over the cloth [m]: an 8 mm lens on the default sensor sees a 9 ft
/// table and its rails from there (config/camera/overhead_1920x1200.yaml).
constexpr double kOverheadHeight = 2.4;

/// The camera above the table's centre at `height` [m], looking straight down, the image's x along
/// the table's x and its y along the table's -y (the head end on the left).
Pose overheadPose(const Eigen::Vector2d& centre, double height);

/// The pixel (with distortion) a point in the camera's optical frame lands on; false if it is
/// behind the camera.
bool project(const Intrinsics& k, const Eigen::Vector3d& point, Eigen::Vector2d& pixel);
/// The undistorted normalised coordinates (x/z, y/z) of a pixel (iterative inverse of the
/// distortion, to 1e-12).
Eigen::Vector2d normalisedOf(const Intrinsics& k, const Eigen::Vector2d& pixel);

}  // namespace camera
}  // namespace cue_sim

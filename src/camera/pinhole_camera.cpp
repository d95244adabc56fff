#include "cue_sim/camera/pinhole_camera.hpp"

#include <cmath>

namespace cue_sim
{
namespace camera
{
namespace
{
/// The plumb-bob model: distorted normalised coordinates of undistorted ones.
Eigen::Vector2d distort(const std::array<double, 5>& d, const Eigen::Vector2d& x)
{
  const double r2 = x.squaredNorm();
  const double radial = 1 + r2 * (d[0] + r2 * (d[1] + r2 * d[4]));
  const double xy = x.x() * x.y();
  return {x.x() * radial + 2 * d[2] * xy + d[3] * (r2 + 2 * x.x() * x.x()),
          x.y() * radial + d[2] * (r2 + 2 * x.y() * x.y()) + 2 * d[3] * xy};
}

/// Fixed-point iterations of the inverse distortion; the lenses of a table camera converge in
/// a few (|distortion| well below 1 across the image).
constexpr int kUndistortIterations = 50;
constexpr double kUndistortTolerance = 1e-12;
}  // namespace

Intrinsics Intrinsics::scaled(int new_width, int new_height) const
{
  Intrinsics s = *this;
  const double sx = double(new_width) / width, sy = double(new_height) / height;
  s.width = new_width;
  s.height = new_height;
  s.fx = fx * sx;
  s.fy = fy * sy;
  // Pixel centres: the centre of pixel 0 is at 0, its left edge at -0.5.
  s.cx = (cx + 0.5) * sx - 0.5;
  s.cy = (cy + 0.5) * sy - 0.5;
  return s;
}

std::string Intrinsics::whyInvalid() const
{
  if (width < 16 || width > 8192 || height < 16 || height > 8192)
    return "image size " + std::to_string(width) + "x" + std::to_string(height) + " is not in [16, 8192] each way";
  if (!(fx > 0) || !(fy > 0) || !std::isfinite(fx) || !std::isfinite(fy))
    return "focal lengths fx " + std::to_string(fx) + ", fy " + std::to_string(fy) + " must be positive";
  if (!std::isfinite(cx) || !std::isfinite(cy))
    return "principal point is not finite";
  for (const double c : distortion)
    if (!std::isfinite(c) || std::abs(c) > 10)
      return "a distortion coefficient is " + std::to_string(c) + ", not in [-10, 10]";
  return "";
}

bool Intrinsics::distorted() const
{
  for (const double c : distortion)
    if (c != 0)
      return true;
  return false;
}

Pose overheadPose(const Eigen::Vector2d& centre, double height)
{
  Pose pose = Pose::Identity();
  pose.translation() = Eigen::Vector3d(centre.x(), centre.y(), height);
  // Optical x along table x, optical y along table -y, optical z (forward) along table -z.
  pose.linear() = Eigen::Vector3d(1, -1, -1).asDiagonal();
  return pose;
}

bool project(const Intrinsics& k, const Eigen::Vector3d& point, Eigen::Vector2d& pixel)
{
  if (!(point.z() > 0))
    return false;
  const Eigen::Vector2d d = distort(k.distortion, point.head<2>() / point.z());
  pixel = {k.fx * d.x() + k.cx, k.fy * d.y() + k.cy};
  return true;
}

Eigen::Vector2d normalisedOf(const Intrinsics& k, const Eigen::Vector2d& pixel)
{
  const Eigen::Vector2d target((pixel.x() - k.cx) / k.fx, (pixel.y() - k.cy) / k.fy);
  if (!k.distorted())
    return target;
  Eigen::Vector2d x = target;
  for (int i = 0; i < kUndistortIterations; ++i)
  {
    const Eigen::Vector2d next = x + (target - distort(k.distortion, x));
    if ((next - x).norm() < kUndistortTolerance)
      return next;
    x = next;
  }
  return x;
}

}  // namespace camera
}  // namespace cue_sim

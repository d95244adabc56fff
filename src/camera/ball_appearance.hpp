// What a ball's surface looks like, in the ball's own frame, matching rviz's markers: a solid
// colour, or a white ball with a coloured band round its equator (|z| < R/2); its number in black
// on a white disc at each pole (+z and -z), readable from outside. Private to the camera.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "camera/table_texture.hpp"

namespace cue_sim
{
namespace camera
{
class BallAppearance
{
public:
  explicit BallAppearance(int id);
  /// The colour at the point of the surface in unit direction `n` of the ball's own frame.
  Bgr colourAt(const Eigen::Vector3f& n) const;

private:
  Bgr colour_;
  bool striped_;
  cv::Mat number_;  ///< the number disc, 8-bit grey, empty for the cue ball
};

}  // namespace camera
}  // namespace cue_sim

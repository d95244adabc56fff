// What a ball's surface looks like, in the ball's own frame, matching rviz's markers: a solid
// colour, or a white ball with a coloured band round its equator (|z| < R/2); a pool ball's number
// in black on a white disc at each pole (+z and -z), readable from outside. Private to the camera.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "camera/table_texture.hpp"
#include "cue_sim/scene/ball_colours.hpp"

namespace cue_sim
{
namespace camera
{
class BallAppearance
{
public:
  BallAppearance(int id, BallSet set);
  /// The colour at the point of the surface in unit direction `n` of the ball's own frame.
  Bgr colourAt(const Eigen::Vector3f& n) const;

private:
  Bgr colour_;
  bool striped_;
  cv::Mat number_;  ///< the number disc, 8-bit grey, empty for a ball without (the cue ball, carom's)
};

}  // namespace camera
}  // namespace cue_sim

// Pixel observations: the simulated overhead camera (camera/table_camera.hpp) at a learner's
// resolution, an undistorted lens framing the cloth and its cushions, drawn from the exact state
// at rest (one instant, no blur, no sensor noise).
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>

#include "cue_sim/camera/table_camera.hpp"
#include "cue_sim/physics/engine.hpp"

namespace cue_sim
{
namespace learning
{
/// What the picture shows beyond the cloth on each side [m]: the cushions and the pockets' mouths
/// (a cushion is some 5 cm wide; the pockets' jaws reach a little further).
constexpr double kPixelFrameMargin = 0.08;

class PixelRenderer
{
public:
  PixelRenderer(const physics::Engine<double>& engine, int width, int height);
  /// The balls of `state` at its time, RGB row by row into `rgb` (height x width x 3 bytes).
  void render(const physics::TableState<double>& state, std::uint8_t* rgb);
  int width() const { return width_; }
  int height() const { return height_; }

private:
  const physics::Engine<double>* engine_;
  int width_, height_;
  camera::TableCamera camera_;
  cv::Mat bgr_;
};

}  // namespace learning
}  // namespace cue_sim

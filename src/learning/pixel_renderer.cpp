#include "learning/pixel_renderer.hpp"

#include <algorithm>
#include <opencv2/imgproc.hpp>

namespace cue_sim
{
namespace learning
{
namespace
{
/// A lens with no distortion whose picture holds the cloth and kPixelFrameMargin around it from
/// the default overhead height, the table's length along the image's width.
camera::Intrinsics framing(const physics::TableModel& table, double ball_radius, int width, int height)
{
  const double depth = camera::kOverheadHeight - ball_radius;
  const double seen_x = table.clothLength() + 2 * kPixelFrameMargin;
  const double seen_y = table.clothWidth() + 2 * kPixelFrameMargin;
  const double f = std::min(width / seen_x, height / seen_y) * depth;
  camera::Intrinsics k;
  k.width = width;
  k.height = height;
  k.fx = k.fy = f;
  k.cx = (width - 1) / 2.0;
  k.cy = (height - 1) / 2.0;
  k.distortion.fill(0);
  return k;
}
}  // namespace

PixelRenderer::PixelRenderer(const physics::Engine<double>& engine, int width, int height)
  : engine_(&engine),
    width_(width),
    height_(height),
    camera_(engine.table(), engine.params().ball_radius, engine.params().cushion_height,
            framing(engine.table(), engine.params().ball_radius, width, height),
            camera::overheadPose(engine.table().clothCentre(), camera::kOverheadHeight))
{
}

void PixelRenderer::render(const physics::TableState<double>& state, std::uint8_t* rgb)
{
  camera::Exposure exposure;
  exposure.instants.emplace_back();
  for (const auto& ball : engine_->snapshot(state))
  {
    camera::BallPose pose;
    pose.id = ball.id;
    pose.centre = ball.r;
    pose.in_play = ball.inPlay();
    exposure.instants.back().push_back(pose);
  }
  camera_.render(exposure, bgr_);
  cv::Mat out(height_, width_, CV_8UC3, rgb);
  cv::cvtColor(bgr_, out, cv::COLOR_BGR2RGB);
}

}  // namespace learning
}  // namespace cue_sim

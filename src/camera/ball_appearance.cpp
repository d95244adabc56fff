#include "camera/ball_appearance.hpp"

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <string>

#include "cue_sim/scene/ball_colours.hpp"

namespace cue_sim
{
namespace camera
{
namespace
{
/// The number disc's angular radius seen from the ball's centre [rad]: a disc of 0.6 R across,
/// larger than a real ball's (about 0.45 R) so that a camera 2.4 m up resolves the digits.
const float kDiscSine = 0.3f;
const float kDiscCosine = std::sqrt(1 - kDiscSine * kDiscSine);
/// The stripe: |z| below this on the unit sphere (rviz draws a band R tall).
constexpr float kStripeHalfHeight = 0.5f;
/// The number disc's texture, square [px].
constexpr int kDiscTexture = 64;

cv::Mat numberDisc(int id)
{
  cv::Mat disc(kDiscTexture, kDiscTexture, CV_8UC1, cv::Scalar(255));
  const std::string text = std::to_string(id);
  const int font = cv::FONT_HERSHEY_DUPLEX;
  const double scale = text.size() == 1 ? 1.6 : 1.2;
  const int thickness = 3;
  int baseline = 0;
  const cv::Size size = cv::getTextSize(text, font, scale, thickness, &baseline);
  const cv::Point at((kDiscTexture - size.width) / 2, (kDiscTexture + size.height) / 2);
  cv::putText(disc, text, at, font, scale, cv::Scalar(0), thickness, cv::LINE_AA);
  return disc;
}

Bgr bgrOf(const Rgb& c)
{
  return {c.b, c.g, c.r};
}
}  // namespace

BallAppearance::BallAppearance(int id, BallSet set)
  : colour_(bgrOf(ballColour(id, set))),
    striped_(isStriped(id, set)),
    number_(isNumbered(id, set) ? numberDisc(id) : cv::Mat())
{
}

Bgr BallAppearance::colourAt(const Eigen::Vector3f& n) const
{
  if (!number_.empty() && std::abs(n.z()) > kDiscCosine)
  {
    // Seen from outside the +z pole, x is to the right and y up; from outside -z, x is mirrored.
    const float u = (n.z() > 0 ? n.x() : -n.x()) / kDiscSine;
    const float v = n.y() / kDiscSine;
    const int column = std::min(kDiscTexture - 1, std::max(0, static_cast<int>((u + 1) / 2 * kDiscTexture)));
    const int row = std::min(kDiscTexture - 1, std::max(0, static_cast<int>((1 - v) / 2 * kDiscTexture)));
    const float grey = number_.at<std::uint8_t>(row, column) / 255.0f;
    return {grey, grey, grey};
  }
  if (striped_ && std::abs(n.z()) >= kStripeHalfHeight)
    return bgrOf(ballColour(0));
  return colour_;
}

}  // namespace camera
}  // namespace cue_sim

#include "cue_sim/camera/table_camera.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "camera/ball_appearance.hpp"
#include "camera/table_texture.hpp"

namespace cue_sim
{
namespace camera
{
namespace
{
/// Simple lighting: a light above the table, towards the foot and the +y side (so that the
/// highlights fall beside the numbers of balls seen from above), an ambient share, and a
/// highlight on the balls (Blinn-Phong). Ambient and diffuse add to under 1 at most, so that
/// white balls keep their shading.
const Eigen::Vector3d kLightDirection = Eigen::Vector3d(0.5, 0.35, 1.0).normalized();
constexpr float kAmbient = 0.30f;
constexpr float kDiffuse = 0.65f;
constexpr float kSpecular = 0.30f;
constexpr float kShininess = 60.0f;
/// The table's horizontal surfaces take the same light everywhere: the texture's colours as they are.
constexpr float kFlatLight = 1.0f;
/// A ball's box in the image is its projected radius times this, plus a pixel, each way: room
/// for a lens that magnifies locally (pincushion) by up to 15 %.
constexpr double kBoxMargin = 1.15;
/// Largest Gaussian noise accepted [8-bit levels].
constexpr double kMaxNoise = 50.0;

std::uint8_t toByte(float value)
{
  return static_cast<std::uint8_t>(std::min(255.0f, std::max(0.0f, value)) + 0.5f);
}

/// One ball at one instant, in the camera's optical frame.
struct BallInstant
{
  Eigen::Vector3f centre;
  float centre_squared = 0;
  Eigen::Matrix3f to_ball;  ///< camera frame to the ball's own frame
};

/// Box of pixels, inclusive.
struct PixelBox
{
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
  bool empty() const { return x1 < x0 || y1 < y0; }
};
}  // namespace

std::string CameraOptions::whyInvalid() const
{
  if (!(noise_stddev >= 0 && noise_stddev <= kMaxNoise))
    return "noise_stddev " + std::to_string(noise_stddev) + " is not in [0, 50] (8-bit levels)";
  return "";
}

/// What stays between frames: each pixel's ray, the table's texture, the balls' looks.
class TableCamera::Scene
{
public:
  Scene(const physics::TableModel& table, const Intrinsics& k)
    : texture(table, ballSetFor(table) == BallSet::Snooker), set(ballSetFor(table))
  {
    rays.resize(static_cast<std::size_t>(k.width) * k.height);
    for (int y = 0; y < k.height; ++y)
      for (int x = 0; x < k.width; ++x)
      {
        const Eigen::Vector2d n = normalisedOf(k, Eigen::Vector2d(x, y));
        rays[static_cast<std::size_t>(y) * k.width + x] = Eigen::Vector3d(n.x(), n.y(), 1).normalized().cast<float>();
      }
  }

  const BallAppearance& appearance(int id)
  {
    auto it = looks.find(id);
    if (it == looks.end())
      it = looks.emplace(id, BallAppearance(id, set)).first;
    return it->second;
  }

  TableTexture texture;
  BallSet set;                        ///< the table's (carom's on a table without pockets)
  std::vector<Eigen::Vector3f> rays;  ///< unit, camera frame, row by row
  std::map<int, BallAppearance> looks;
};

TableCamera::TableCamera(const physics::TableModel& table, double ball_radius, double cushion_height,
                         const Intrinsics& intrinsics, const Pose& pose, const CameraOptions& options)
  : intrinsics_(intrinsics), options_(options), pose_(pose), ball_radius_(ball_radius), noise_rng_(options.noise_seed)
{
  std::string why = intrinsics.whyInvalid();
  if (why.empty())
    why = options.whyInvalid();
  if (!why.empty())
    throw std::invalid_argument(why);
  if (!(ball_radius > 0) || !(cushion_height >= 0))
    throw std::invalid_argument("ball radius and cushion height must be positive");
  cushion_height_ = cushion_height;
  scene_ = std::make_unique<Scene>(table, intrinsics);
  drawBackground();
}

TableCamera::~TableCamera() = default;
TableCamera::TableCamera(TableCamera&&) noexcept = default;

void TableCamera::setPose(const Pose& pose)
{
  if (pose.isApprox(pose_, 1e-12))
    return;
  pose_ = pose;
  drawBackground();
}

void TableCamera::drawBackground()
{
  const Intrinsics& k = intrinsics_;
  const Pose& pose = pose_;
  background_.create(k.height, k.width, CV_8UC3);
  const Eigen::Matrix3d rotation = pose.linear();
  const Eigen::Vector3d origin = pose.translation();
  for (int y = 0; y < k.height; ++y)
  {
    auto* row = background_.ptr<std::uint8_t>(y);
    for (int x = 0; x < k.width; ++x)
    {
      const Eigen::Vector3d d = rotation * scene_->rays[static_cast<std::size_t>(y) * k.width + x].cast<double>();
      Bgr c{0.22f, 0.22f, 0.24f};  // looking level or up: the room
      if (d.z() < 0)
      {
        // The raised surfaces' tops first, then the cloth's level.
        const Eigen::Vector2d top = (origin + d * ((cushion_height_ - origin.z()) / d.z())).head<2>();
        const Eigen::Vector2d low = (origin + d * (-origin.z() / d.z())).head<2>();
        const bool above_top = origin.z() > cushion_height_;
        c = above_top && TableTexture::raised(scene_->texture.surfaceAt(top)) ? scene_->texture.colourAt(top)
                                                                              : scene_->texture.colourAt(low);
        c = {c.b * kFlatLight, c.g * kFlatLight, c.r * kFlatLight};
      }
      row[3 * x] = toByte(255 * c.b);
      row[3 * x + 1] = toByte(255 * c.g);
      row[3 * x + 2] = toByte(255 * c.r);
    }
  }
}

std::vector<BallPixel> TableCamera::groundTruth(const std::vector<BallPose>& balls) const
{
  const Pose to_camera = pose_.inverse();
  std::vector<BallPixel> truth;
  truth.reserve(balls.size());
  for (const auto& b : balls)
  {
    BallPixel p;
    p.id = b.id;
    const Eigen::Vector3d c = to_camera * b.centre;
    const bool in_front = project(intrinsics_, c, p.pixel);
    if (in_front)
      p.radius = intrinsics_.fx * ball_radius_ / c.z();
    p.visible = b.in_play && in_front && p.pixel.x() >= -0.5 && p.pixel.y() >= -0.5 &&
                p.pixel.x() < intrinsics_.width - 0.5 && p.pixel.y() < intrinsics_.height - 0.5;
    truth.push_back(p);
  }
  return truth;
}

Frame TableCamera::render(const Exposure& exposure)
{
  Frame frame;
  frame.balls = render(exposure, frame.image);
  return frame;
}

std::vector<BallPixel> TableCamera::render(const Exposure& exposure, cv::Mat& image)
{
  background_.copyTo(image);
  std::vector<BallPixel> truth;
  if (!exposure.instants.empty())
  {
    truth = groundTruth(exposure.instants[exposure.instants.size() / 2]);
    drawBalls(exposure, image);
  }
  if (options_.noise_stddev > 0)
  {
    noise_.create(image.size(), CV_16SC3);
    cv::RNG rng(noise_rng_());
    rng.fill(noise_, cv::RNG::NORMAL, 0, options_.noise_stddev);
    cv::add(image, noise_, image, cv::noArray(), CV_8UC3);
  }
  return truth;
}

void TableCamera::drawBalls(const Exposure& exposure, cv::Mat& image)
{
  const std::size_t middle = exposure.instants.size() / 2;

  const Intrinsics& k = intrinsics_;
  const Pose to_camera = pose_.inverse();
  const Eigen::Matrix3d camera_to_table = pose_.linear();
  const Eigen::Vector3f light = (camera_to_table.transpose() * kLightDirection).cast<float>();
  const float r = static_cast<float>(ball_radius_);
  const std::size_t balls = exposure.instants[middle].size();

  // Far balls first: a nearer one is drawn over them.
  std::vector<std::size_t> order(balls);
  for (std::size_t i = 0; i < balls; ++i)
    order[i] = i;
  std::vector<double> depth(balls);
  for (std::size_t i = 0; i < balls; ++i)
    depth[i] = (to_camera * exposure.instants[middle][i].centre).norm();
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return depth[a] > depth[b]; });

  std::vector<BallInstant> instants;
  for (const std::size_t i : order)
  {
    const BallPose& mid = exposure.instants[middle][i];
    if (!mid.in_play)
      continue;
    // A ball still through the exposure is drawn once.
    bool moves = false;
    for (const auto& instant : exposure.instants)
      moves = moves || !instant[i].centre.isApprox(mid.centre, 1e-9) ||
              !instant[i].orientation.isApprox(mid.orientation, 1e-9);
    instants.clear();
    PixelBox box{k.width, k.height, -1, -1};
    for (std::size_t s = 0; s < exposure.instants.size(); ++s)
    {
      if (!moves && s != middle)
        continue;
      const BallPose& pose = exposure.instants[s][i];
      BallInstant b;
      const Eigen::Vector3d c = to_camera * pose.centre;
      b.centre = c.cast<float>();
      b.centre_squared = b.centre.squaredNorm() - r * r;
      b.to_ball = (pose.orientation.toRotationMatrix().transpose() * camera_to_table).cast<float>();
      instants.push_back(b);
      Eigen::Vector2d pixel;
      if (!pose.in_play || !project(k, c, pixel))
        continue;
      const double radius = kBoxMargin * k.fx * ball_radius_ / c.z() + 1;
      box.x0 = std::min(box.x0, static_cast<int>(std::floor(pixel.x() - radius)));
      box.y0 = std::min(box.y0, static_cast<int>(std::floor(pixel.y() - radius)));
      box.x1 = std::max(box.x1, static_cast<int>(std::ceil(pixel.x() + radius)));
      box.y1 = std::max(box.y1, static_cast<int>(std::ceil(pixel.y() + radius)));
    }
    box = {std::max(box.x0, 0), std::max(box.y0, 0), std::min(box.x1, k.width - 1), std::min(box.y1, k.height - 1)};
    if (box.empty())
      continue;
    const BallAppearance& look = scene_->appearance(mid.id);
    const float count = static_cast<float>(instants.size());
    for (int y = box.y0; y <= box.y1; ++y)
    {
      auto* row = image.ptr<std::uint8_t>(y);
      for (int x = box.x0; x <= box.x1; ++x)
      {
        const Eigen::Vector3f& d = scene_->rays[static_cast<std::size_t>(y) * k.width + x];
        float sum_b = 0, sum_g = 0, sum_r = 0;
        int hits = 0;
        for (const auto& b : instants)
        {
          const float along = d.dot(b.centre);
          const float discriminant = along * along - b.centre_squared;
          if (discriminant <= 0)
            continue;
          const float t = along - std::sqrt(discriminant);
          if (t <= 0)
            continue;
          const Eigen::Vector3f normal = (t * d - b.centre) / r;
          const Bgr c = look.colourAt(b.to_ball * normal);
          const float diffuse = kAmbient + kDiffuse * std::max(0.0f, normal.dot(light));
          const Eigen::Vector3f half = (light - d).normalized();
          const float highlight = kSpecular * std::pow(std::max(0.0f, normal.dot(half)), kShininess);
          sum_b += c.b * diffuse + highlight;
          sum_g += c.g * diffuse + highlight;
          sum_r += c.r * diffuse + highlight;
          ++hits;
        }
        if (hits == 0)
          continue;
        const float behind = count - hits;
        std::uint8_t* p = row + 3 * x;
        p[0] = toByte((255 * sum_b + behind * p[0]) / count);
        p[1] = toByte((255 * sum_g + behind * p[1]) / count);
        p[2] = toByte((255 * sum_r + behind * p[2]) / count);
      }
    }
  }
}

}  // namespace camera
}  // namespace cue_sim

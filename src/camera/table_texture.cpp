#include "camera/table_texture.hpp"

#include <cmath>

namespace cue_sim
{
namespace camera
{
namespace
{
/// The texture's resolution: 2 mm a texel, under a pixel of the default camera (about 2.4 mm
/// on the cloth from 2.4 m) and a fifth of a ball's diameter's error budget for edges.
constexpr double kTexel = 0.002;
/// Cushion rubber behind the nose line, as rviz's markers draw it [m].
constexpr double kRubber = 0.03;
/// The wooden rail around the cushions [m] (a typical pool table's rail, 12 to 15 cm).
constexpr double kRail = 0.14;

const Bgr kCloth{0.22f, 0.50f, 0.05f};
const Bgr kChalk{0.85f, 0.88f, 0.85f};
/// A snooker table's chalk lines' half-width and its spots' radius [m], as urdf/'s markings.
constexpr double kChalkHalfWidth = 0.0015, kSpotRadius = 0.004;
const Bgr kCushion{0.15f, 0.36f, 0.02f};
const Bgr kRailWood{0.10f, 0.22f, 0.42f};
const Bgr kPocket{0.02f, 0.02f, 0.02f};
const Bgr kFloor{0.22f, 0.22f, 0.24f};

bool behindSegment(const physics::CushionSegment& s, const Eigen::Vector2d& p)
{
  const Eigen::Vector2d d = p - s.start;
  const double along = d.dot(s.direction);
  const double depth = -d.dot(s.normal);
  return along >= 0 && along <= s.length && depth >= 0 && depth <= kRubber;
}

/// Whether p is on a marking: the baulk line, the D's arc, or a spot.
bool onMarking(const physics::SnookerMarkings& m, const Eigen::Vector2d& p)
{
  if (std::abs(p.x() - m.baulk_line_x) <= kChalkHalfWidth)
    return true;
  if (p.x() <= m.baulk_line_x && std::abs((p - m.d_centre).norm() - m.d_radius) <= kChalkHalfWidth)
    return true;
  for (const Eigen::Vector2d& spot : m.spots)
    if ((p - spot).norm() <= kSpotRadius)
      return true;
  return false;
}
}  // namespace

TableTexture::TableTexture(const physics::TableModel& table, bool snooker_markings)
{
  if (snooker_markings)
    markings_ = physics::snookerMarkings(table);
  const Eigen::Vector2d half(table.clothLength() / 2, table.clothWidth() / 2);
  cloth_low_ = table.clothCentre() - half;
  cloth_high_ = table.clothCentre() + half;
  const Eigen::Vector2d margin = Eigen::Vector2d::Constant(kRubber + kRail);
  origin_ = cloth_low_ - margin;
  const Eigen::Vector2d size = cloth_high_ + margin - origin_;
  columns_ = static_cast<int>(std::ceil(size.x() / kTexel));
  rows_ = static_cast<int>(std::ceil(size.y() / kTexel));
  texels_.resize(static_cast<std::size_t>(columns_) * rows_);
  for (int row = 0; row < rows_; ++row)
    for (int column = 0; column < columns_; ++column)
      texels_[static_cast<std::size_t>(row) * columns_ + column] =
          classify(table, origin_ + kTexel * Eigen::Vector2d(column + 0.5, row + 0.5));
}

Surface TableTexture::classify(const physics::TableModel& table, const Eigen::Vector2d& p) const
{
  const Eigen::Vector2d rubber = Eigen::Vector2d::Constant(kRubber);
  const bool within_rubber =
      (p.array() >= (cloth_low_ - rubber).array()).all() && (p.array() <= (cloth_high_ + rubber).array()).all();
  if (!within_rubber)
    return Surface::Rail;
  for (const auto& c : table.circles())
    if (c.radius > 0 && (p - c.centre).norm() <= c.radius)
      return Surface::Cushion;
  for (const auto& s : table.segments())
    if (behindSegment(s, p))
      return Surface::Cushion;
  for (const auto& pocket : table.pockets())
    if ((p - pocket.centre).norm() <= pocket.radius)
      return Surface::Pocket;
  const bool on_cloth = (p.array() >= cloth_low_.array()).all() && (p.array() <= cloth_high_.array()).all();
  if (on_cloth && markings_ && onMarking(*markings_, p))
    return Surface::Chalk;
  return on_cloth ? Surface::Cloth : Surface::Cushion;
}

int TableTexture::index(const Eigen::Vector2d& p) const
{
  const Eigen::Vector2d t = (p - origin_) / kTexel;
  if (!(t.x() >= 0 && t.y() >= 0 && t.x() < columns_ && t.y() < rows_))
    return -1;
  return static_cast<int>(t.y()) * columns_ + static_cast<int>(t.x());
}

Surface TableTexture::surfaceAt(const Eigen::Vector2d& p) const
{
  const int i = index(p);
  return i < 0 ? Surface::Floor : texels_[static_cast<std::size_t>(i)];
}

Bgr TableTexture::colourAt(const Eigen::Vector2d& p) const
{
  switch (surfaceAt(p))
  {
    case Surface::Cloth:
      return kCloth;
    case Surface::Chalk:
      return kChalk;
    case Surface::Pocket:
      return kPocket;
    case Surface::Cushion:
      return kCushion;
    case Surface::Rail:
      return kRailWood;
    case Surface::Floor:
      break;
  }
  return kFloor;
}

}  // namespace camera
}  // namespace cue_sim

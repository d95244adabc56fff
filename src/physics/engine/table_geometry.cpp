#include "physics/engine/table_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace cue_sim
{
namespace physics
{
template <typename S>
TableGeometry<S>::TableGeometry(const TableModel& table, S R, S cushion_height)
  : nose_height(cushion_height),
    rail_height(std::isnan(table.edge().rail_height) ? cushion_height : S(table.edge().rail_height)),
    edge_low(table.edge().low.cast<S>()),
    edge_high(table.edge().high.cast<S>())
{
  const S margin = S(kBoxMargin);
  const Vec2<S> spread(R + margin, R + margin);
  for (const auto& s : table.segments())
  {
    const Vec2<S> a = s.start.cast<S>(), b = s.end.cast<S>();
    segments.push_back(
        {a, s.direction.cast<S>(), s.normal.cast<S>(), S(s.length), a.cwiseMin(b) - spread, a.cwiseMax(b) + spread});
  }
  for (const auto& c : table.circles())
  {
    const Vec2<S> centre = c.centre.cast<S>(), reach = Vec2<S>::Constant(R + S(c.radius) + margin);
    circles.push_back({centre, S(c.radius), centre - reach, centre + reach});
    widest_post = std::max(widest_post, S(c.radius));
  }
  for (const auto& p : table.pockets())
  {
    const Vec2<S> centre = p.centre.cast<S>(), reach = Vec2<S>::Constant(S(p.radius) + margin);
    pockets.push_back({centre, S(p.radius), centre - reach, centre + reach});
  }
  const Vec2<S> half(S(table.clothLength() / 2), S(table.clothWidth() / 2));
  cloth_low = table.clothCentre().cast<S>() - half;
  cloth_high = table.clothCentre().cast<S>() + half;
  // The clear box: the cloth, cut back on each side past every obstacle's box that reaches into
  // it (the side it reaches in from is the one nearest the box).
  clear_low = cloth_low;
  clear_high = cloth_high;
  const Vec2<S> centre = table.clothCentre().cast<S>();
  const auto cutBack = [&](const Vec2<S>& low, const Vec2<S>& high) {
    if ((low.array() > clear_high.array()).any() || (high.array() < clear_low.array()).any())
      return;
    // How far the clear box would shrink on each of its four sides to leave the box outside.
    const S cuts[4] = {high.x() - clear_low.x(), clear_high.x() - low.x(), high.y() - clear_low.y(),
                       clear_high.y() - low.y()};
    const int side = static_cast<int>(std::min_element(cuts, cuts + 4) - cuts);
    if (side == 0)
      clear_low.x() = std::min(high.x(), centre.x());
    else if (side == 1)
      clear_high.x() = std::max(low.x(), centre.x());
    else if (side == 2)
      clear_low.y() = std::min(high.y(), centre.y());
    else
      clear_high.y() = std::max(low.y(), centre.y());
  };
  for (const auto& s : segments)
    cutBack(s.low, s.high);
  for (const auto& c : circles)
    cutBack(c.low, c.high);
}

template struct TableGeometry<double>;
template struct TableGeometry<long double>;

}  // namespace physics
}  // namespace cue_sim

#include "physics/engine/table_departure.hpp"

#include <algorithm>
#include <cmath>

#include "physics/models/flight.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
template <typename S>
bool inside(const Vec2<S>& point, const Vec2<S>& low, const Vec2<S>& high)
{
  return (point.array() >= low.array()).all() && (point.array() <= high.array()).all();
}

/// The first time in [0, T] at which x0 + v tau leaves the box [low, high] (x0 inside it).
template <typename S>
S timeToLeave(const Vec2<S>& x0, const Vec2<S>& v, const Vec2<S>& low, const Vec2<S>& high, S T)
{
  S tau = T;
  for (int axis = 0; axis < 2; ++axis)
  {
    if (v[axis] > S(0))
      tau = std::min(tau, (high[axis] - x0[axis]) / v[axis]);
    else if (v[axis] < S(0))
      tau = std::min(tau, (low[axis] - x0[axis]) / v[axis]);
  }
  return std::max(tau, S(0));
}
}  // namespace

template <typename S>
Departure<S> departureOf(const Ball<S>& ball, const TableGeometry<S>& geometry, const PhysicsParams<S>& p)
{
  const S R = p.ball_radius;
  const S landing_height = geometry.rail_height + R;
  S tau = timeToHeight(ball.r.z(), ball.v.z(), landing_height, p.gravity);
  if (!std::isfinite(static_cast<double>(tau)))
    tau = S(0);  // below the rails' top already: it lands where it is
  const Vec3<S> landing = flightPosition(ball.r, ball.v, tau, p.gravity);
  const Vec2<S> spot = landing.template head<2>();
  Departure<S> out;
  if (inside<S>(spot, geometry.edge_low, geometry.edge_high))
  {
    for (std::size_t k = 0; k < geometry.pockets.size(); ++k)
      if ((spot - geometry.pockets[k].centre).norm() < geometry.pockets[k].radius)
      {
        out.kind = EventKind::Pocketed;
        out.obstacle = static_cast<int>(k);
        return out;
      }
    out.obstacle = kLandsOnRail;
    out.where = Vec3<S>(spot.x(), spot.y(), landing_height);
    return out;
  }
  // Over the edge before it comes down to the rails' top: where its centre crossed the edge.
  const Vec2<S> now = ball.r.template head<2>();
  const S crossing = inside<S>(now, geometry.edge_low, geometry.edge_high)
                         ? timeToLeave<S>(now, ball.v.template head<2>(), geometry.edge_low, geometry.edge_high, tau)
                         : S(0);
  out.obstacle = kLandsOffTable;
  out.where = flightPosition(ball.r, ball.v, crossing, p.gravity);
  return out;
}

template Departure<double> departureOf(const Ball<double>&, const TableGeometry<double>&, const PhysicsParams<double>&);
template Departure<long double> departureOf(const Ball<long double>&, const TableGeometry<long double>&,
                                            const PhysicsParams<long double>&);

}  // namespace physics
}  // namespace cue_sim

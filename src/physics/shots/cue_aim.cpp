#include "cue_sim/physics/cue_aim.hpp"

#include <cmath>
#include <limits>
#include <sstream>

namespace cue_sim
{
namespace physics
{
bool isCue(const CueStick& cue)
{
  return isFinite(cue.tip) && isFinite(cue.axis) && cue.axis.norm() > 0;
}

std::string aimCue(const std::vector<Ball<double>>& balls, const PhysicsParams<double>& params, const CueStick& cue,
                   double speed, CueAim& out)
{
  out = CueAim();
  std::ostringstream why;
  if (!isCue(cue))
    return "the cue's tip and axis must be finite, with a non-zero axis";
  const Vec3<double> u = cue.axis.normalized();
  if (u.z() > 1e-12)
  {
    why << "the cue points upwards (axis z = " << u.z() << " > 0): it can only strike level or down";
    return why.str();
  }
  const double R = params.ball_radius;
  // Along the stroke, the first ball the tip's end or the shaft's rim reaches; behind the
  // tip, any ball the shaft passes through.
  int first = -1;
  double first_travel = std::numeric_limits<double>::infinity(), first_offset = 0;
  Vec3<double> first_axis_offset = Vec3<double>::Zero();
  double nearest_miss = std::numeric_limits<double>::infinity();
  int nearest_miss_id = -1;
  for (const auto& b : balls)
  {
    if (!b.inPlay())
      continue;
    const Vec3<double> w = b.r - cue.tip;
    if (w.norm() < R)
    {
      why << "the cue's tip is inside ball " << b.id;
      return why.str();
    }
    const double along = w.dot(u);
    const Vec3<double> axis_offset = u * along - w;  // from the centre to the axis
    const double offset = axis_offset.norm();
    const double reach = R + cue.shaft_radius;
    if (offset < reach && along < 0 && along > -cue.length - R)
    {
      why << "the cue's shaft passes through ball " << b.id << " (its axis passes " << offset << " m from the centre)";
      return why.str();
    }
    if (along <= 0)
      continue;
    if (offset >= reach)
    {
      if (offset - R < nearest_miss)
      {
        nearest_miss = offset - R;
        nearest_miss_id = b.id;
      }
      continue;
    }
    // The tip's end touches where the axis enters the sphere; the rim where the shaft's edge
    // does (a cylinder of the shaft's radius against a sphere: at most this far along).
    const double touch = offset < R ? std::sqrt(R * R - offset * offset) : std::sqrt(reach * reach - offset * offset);
    const double travel = along - touch;
    if (travel < first_travel)
    {
      first = b.id;
      first_travel = travel;
      first_offset = offset;
      first_axis_offset = axis_offset;
    }
  }
  if (first < 0)
  {
    why << "the cue meets no ball";
    if (nearest_miss_id >= 0)
      why << ": its axis passes " << nearest_miss << " m outside ball " << nearest_miss_id;
    return why.str();
  }
  if (first_offset >= R)
  {
    why << "the side of the cue's tip would meet ball " << first << " first (its axis passes " << first_offset
        << " m from the centre, more than R = " << R << " m)";
    return why.str();
  }
  // The shooter's right and up, seen along the stroke.
  Vec3<double> right = u.cross(Vec3<double>::UnitZ());
  if (right.norm() < 1e-12)
    right = -Vec3<double>::UnitY();  // a vertical cue: right is -y, as for a cue along +x
  right.normalize();
  const Vec3<double> up = right.cross(u);
  CueStrike<double> strike;
  strike.speed = speed;
  strike.phi = std::hypot(u.x(), u.y()) > 1e-12 ? std::atan2(u.y(), u.x()) : 0.0;
  strike.theta = std::max(0.0, std::asin(std::min(1.0, -u.z())));  // never -0 for a level cue
  strike.a = contactOffset(first_axis_offset.dot(right) / R, params);
  strike.b = contactOffset(first_axis_offset.dot(up) / R, params);
  const double tip_offset = std::hypot(strike.a, strike.b);
  if (tip_offset > CueLimits::max_offset)
  {
    why << "the tip would touch ball " << first << " " << tip_offset << " R from its centre, outside the allowed "
        << CueLimits::max_offset << " R (a miscue)";
    return why.str();
  }
  const std::string invalid = validateStrike(strike);
  if (!invalid.empty())
    return invalid;
  out.ball_id = first;
  out.strike = strike;
  out.travel = first_travel;
  return "";
}

CueStick cueStickFor(const Ball<double>& ball, const CueStrike<double>& strike, const PhysicsParams<double>& params,
                     double gap)
{
  const Vec3<double> u(std::cos(strike.theta) * std::cos(strike.phi), std::cos(strike.theta) * std::sin(strike.phi),
                       -std::sin(strike.theta));
  Vec3<double> right = u.cross(Vec3<double>::UnitZ());
  right = right.norm() < 1e-12 ? Vec3<double>(-Vec3<double>::UnitY()) : Vec3<double>(right.normalized());
  const Vec3<double> up = right.cross(u);
  const double R = params.ball_radius;
  const double axis_per_contact = 1 + params.cue_tip_radius / R;  // contactOffset inverted
  const Vec3<double> offset = R * axis_per_contact * (strike.a * right + strike.b * up);
  const double along = std::sqrt(std::max(0.0, R * R - offset.squaredNorm()));
  CueStick cue;
  cue.tip = ball.r + offset - u * (along + gap);
  cue.axis = u;
  return cue;
}

}  // namespace physics
}  // namespace cue_sim

#include "cue_sim/physics/cue_strike.hpp"

#include <cmath>
#include <sstream>

namespace cue_sim
{
namespace physics
{
template <typename S>
std::string validateStrike(const CueStrike<S>& s)
{
  const auto bad = [](S x) { return !std::isfinite(static_cast<double>(x)); };
  const bool good_speed = !bad(s.speed) && s.speed > S(0) && s.speed <= S(CueLimits::max_speed);
  const bool good_theta = !bad(s.theta) && s.theta >= S(0) && s.theta <= S(CueLimits::max_elevation);
  const bool good_tip =
      !bad(s.a) && !bad(s.b) && std::hypot(static_cast<double>(s.a), static_cast<double>(s.b)) <= CueLimits::max_offset;
  if (good_speed && !bad(s.phi) && good_theta && good_tip)
    return {};  // every strike played comes here: no stream is made for it
  std::ostringstream why;
  if (bad(s.speed) || !(s.speed > S(0)) || s.speed > S(CueLimits::max_speed))
    why << "speed must be in (0, " << CueLimits::max_speed << "] m/s, got " << static_cast<double>(s.speed);
  else if (bad(s.phi))
    why << "phi must be a finite angle in rad, got " << static_cast<double>(s.phi);
  else if (bad(s.theta) || s.theta < S(0) || s.theta > S(CueLimits::max_elevation))
    why << "theta must be in [0, " << CueLimits::max_elevation << "] rad, got " << static_cast<double>(s.theta);
  else if (bad(s.a) || bad(s.b) ||
           std::hypot(static_cast<double>(s.a), static_cast<double>(s.b)) > CueLimits::max_offset)
    why << "a and b must be finite with sqrt(a^2 + b^2) <= " << CueLimits::max_offset
        << " (units of R), got a = " << static_cast<double>(s.a) << ", b = " << static_cast<double>(s.b);
  return why.str();
}

template <typename S>
S squirtAngle(S a, const PhysicsParams<S>& p)
{
  const S a2 = a * a;
  return std::atan(S(2.5) * a * std::sqrt(S(1) - a2) / (S(1) + p.ball_mass / p.cue_end_mass + S(2.5) * (S(1) - a2)));
}

template <typename S>
void cueImpulse(Ball<S>& ball, const CueStrike<S>& s, const PhysicsParams<S>& p)
{
  const S R = p.ball_radius;
  // Table-frame axes of the shot: h along the heading, side to the shooter's right, z up.
  const Vec3<S> h(std::cos(s.phi), std::sin(s.phi), S(0));
  const Vec3<S> side(h.y(), -h.x(), S(0));
  const Vec3<S> z = Vec3<S>::UnitZ();
  const S A = s.a * R, B = s.b * R;
  const S sin_t = std::sin(s.theta), cos_t = std::cos(s.theta);
  // The offsets lie on the ball's face seen along the cue (pooltool's convention since 2025):
  // a along the cue's right (side), b along its up, u = sin(theta) h + cos(theta) z. The cue
  // pushes along d = cos(theta) h - sin(theta) z, and the tip meets the ball at
  // P - C = A side + B u - sqrt(R^2 - A^2 - B^2) d. The angular impulse per unit linear impulse
  // is (P - C) x d = A u - B side: a = b = 0 is a centre hit with no spin at any elevation, and
  // the lever's length is sqrt(A^2 + B^2) whatever theta is.
  const Vec3<S> lever = (A * sin_t) * h + (A * cos_t) * z - B * side;
  const S speed = S(2) * s.speed / (S(1) + p.ball_mass / p.cue_mass + (A * A + B * B) / (S(0.4) * R * R));
  // Squirt (Alciatore TP A-31): the cue's end mass m_e is pushed aside with the ball, which
  // leaves away from the side struck, turned by alpha in the horizontal plane.
  const S heading = s.phi + squirtAngle(s.a, p);
  ball.v = speed * cos_t * Vec3<S>(std::cos(heading), std::sin(heading), S(0));  // along the cue: level part...
  ball.v.z() = -speed * sin_t;                                                 // ...and down into the slate
  ball.w = (speed / (S(0.4) * R * R)) * lever;
  ball.r.z() = R;
}

template <typename S>
void applyCueStrike(Ball<S>& ball, const CueStrike<S>& s, const PhysicsParams<S>& p)
{
  cueImpulse(ball, s, p);
  ball.v.z() = S(0);  // the vertical part goes into the cloth
}

template std::string validateStrike(const CueStrike<double>&);
template std::string validateStrike(const CueStrike<long double>&);
template double squirtAngle(double, const PhysicsParams<double>&);
template long double squirtAngle(long double, const PhysicsParams<long double>&);
template void cueImpulse(Ball<double>&, const CueStrike<double>&, const PhysicsParams<double>&);
template void cueImpulse(Ball<long double>&, const CueStrike<long double>&, const PhysicsParams<long double>&);
template void applyCueStrike(Ball<double>&, const CueStrike<double>&, const PhysicsParams<double>&);
template void applyCueStrike(Ball<long double>&, const CueStrike<long double>&, const PhysicsParams<long double>&);

}  // namespace physics
}  // namespace cue_sim

#include "cue_sim/physics/motion.hpp"

#include <algorithm>
#include <cmath>

#include "physics/models/flight.hpp"

namespace cue_sim
{
namespace physics
{
const char* motionName(Motion motion)
{
  switch (motion)
  {
    case Motion::Stationary:
      return "stationary";
    case Motion::Spinning:
      return "spinning";
    case Motion::Sliding:
      return "sliding";
    case Motion::Rolling:
      return "rolling";
    case Motion::Pocketed:
      return "pocketed";
    case Motion::Airborne:
      return "airborne";
    case Motion::OffTable:
      return "off_table";
    case Motion::Held:
      return "held";
    case Motion::Supported:
      return "supported";
    case Motion::Bearing:
      return "bearing";
  }
  return "unknown";
}

template <typename S>
Vec3<S> slipVelocity(const Vec3<S>& v, const Vec3<S>& w, S radius)
{
  // u = v + w x (-R z) = (v_x - R w_y, v_y + R w_x, 0)
  return Vec3<S>(v.x() - radius * w.y(), v.y() + radius * w.x(), S(0));
}

template <typename S>
Motion classifyMotion(const Vec3<S>& v, const Vec3<S>& w, S radius)
{
  if (slipVelocity(v, w, radius).norm() > zeroSpeed<S>())
    return Motion::Sliding;
  if (v.norm() > zeroSpeed<S>())
    return Motion::Rolling;
  if (std::abs(w.z()) > zeroSpeed<S>())
    return Motion::Spinning;
  return Motion::Stationary;
}

template <typename S>
void settleMotion(Ball<S>& ball, S radius)
{
  if (!ball.inPlay() || (ball.held() && ball.v == Vec3<S>::Zero() && ball.w == Vec3<S>::Zero()))
    return;
  ball.piece = SupportPiece<S>();  // a free motion: the contact equations no longer move it
  if (ball.r.z() - radius > onClothHeight(radius) || ball.v.z() > zeroSpeed<S>())
  {
    ball.motion = Motion::Airborne;
    return;
  }
  ball.v.z() = S(0);
  ball.r.z() = radius;
  ball.motion = classifyMotion(ball.v, ball.w, radius);
  switch (ball.motion)
  {
    case Motion::Rolling:
      ball.w.x() = -ball.v.y() / radius;
      ball.w.y() = ball.v.x() / radius;
      break;
    case Motion::Spinning:
      ball.v.setZero();
      ball.w.x() = ball.w.y() = S(0);
      break;
    case Motion::Stationary:
      ball.v.setZero();
      ball.w.setZero();
      break;
    default:
      break;
  }
}

template <typename S>
S timeToTransition(const Ball<S>& ball, const PhysicsParams<S>& p)
{
  S rate = S(0), amount = S(0);
  switch (ball.motion)
  {
    case Motion::Sliding:  // |u| falls at 7/2 mu_s g
      rate = S(3.5) * p.slideDecel();
      amount = slipVelocity(ball.v, ball.w, p.ball_radius).norm();
      break;
    case Motion::Rolling:
      rate = p.rollDecel();
      amount = ball.v.norm();
      break;
    case Motion::Spinning:
      rate = p.spinDecel();
      amount = std::abs(ball.w.z());
      break;
    case Motion::Airborne:
      return timeToHeight(ball.r.z(), ball.v.z(), p.ball_radius, p.gravity);
    case Motion::Supported:
    case Motion::Bearing:
      return std::max(ball.piece.until - ball.time, S(0));  // the piece's end
    default:
      return infinity<S>();
  }
  return rate > S(0) ? amount / rate : infinity<S>();
}

namespace
{
/// z-spin falls linearly to zero in every state (Alciatore TP 4.1, the spin decay).
template <typename S>
S decayedSpin(S w_z, S dt, const PhysicsParams<S>& p)
{
  const S left = std::max(std::abs(w_z) - p.spinDecel() * dt, S(0));
  return std::copysign(left, w_z);
}
}  // namespace

template <typename S>
Ball<S> evolve(const Ball<S>& ball, S t, const PhysicsParams<S>& p)
{
  Ball<S> out = ball;
  if (!ball.moving() || !(t > ball.time))
  {
    if (ball.inPlay())
      out.time = std::max(t, ball.time);
    return out;
  }
  const S dt = std::min(t - ball.time, timeToTransition(ball, p));
  const S R = p.ball_radius;
  out.time = t;
  if (ball.motion == Motion::Airborne)
  {
    // In the air the spin is carried unchanged (no drag: flight.hpp says why).
    out.r = flightPosition(ball.r, ball.v, dt, p.gravity);
    out.v = flightVelocity(ball.v, dt, p.gravity);
    return out;
  }
  if (ball.supported())
  {
    // Along the piece the contact equations gave it (SupportPiece).
    out.r = ball.r + dt * (ball.v + S(0.5) * dt * ball.piece.a);
    out.v = ball.v + dt * ball.piece.a;
    out.w = ball.w + dt * ball.piece.alpha;
    return out;
  }
  out.w.z() = decayedSpin(ball.w.z(), dt, p);
  if (ball.motion == Motion::Sliding)
  {
    const Vec3<S> u_hat = slipVelocity(ball.v, ball.w, R).normalized();
    const S decel = p.slideDecel();
    out.r += ball.v * dt - S(0.5) * decel * dt * dt * u_hat;
    out.v -= decel * dt * u_hat;
    // Friction's torque turns w_xy towards z x u_hat at 5 mu_s g / (2R).
    const S spin_rate = S(2.5) * decel / R * dt;
    out.w.x() += -u_hat.y() * spin_rate;
    out.w.y() += u_hat.x() * spin_rate;
  }
  else if (ball.motion == Motion::Rolling)
  {
    const Vec3<S> v_hat = ball.v.normalized();
    const S decel = p.rollDecel();
    out.r += ball.v * dt - S(0.5) * decel * dt * dt * v_hat;
    out.v -= decel * dt * v_hat;
    out.w.x() = -out.v.y() / R;
    out.w.y() = out.v.x() / R;
  }
  return out;
}

template <typename S>
Trajectory<S> trajectoryFrom(const Ball<S>& ball, S t_base, const PhysicsParams<S>& p)
{
  const Ball<S> now = evolve(ball, t_base, p);
  Trajectory<S> traj;
  traj.c0 = now.r.template head<2>();
  traj.c1 = Vec2<S>::Zero();
  traj.c2 = Vec2<S>::Zero();
  if (now.motion == Motion::Sliding)
  {
    traj.c1 = now.v.template head<2>();
    traj.c2 = S(-0.5) * p.slideDecel() * slipVelocity(now.v, now.w, p.ball_radius).template head<2>().normalized();
  }
  else if (now.motion == Motion::Rolling)
  {
    traj.c1 = now.v.template head<2>();
    traj.c2 = S(-0.5) * p.rollDecel() * traj.c1.normalized();
  }
  else if (now.motion == Motion::Airborne)
  {
    traj.c1 = now.v.template head<2>();
    traj.h0 = now.r.z() - p.ball_radius;
    traj.h1 = now.v.z();
    traj.h2 = S(-0.5) * p.gravity;
  }
  else if (now.motion == Motion::Held)
    traj.h0 = now.r.z() - p.ball_radius;
  else if (now.supported())
  {
    traj.c1 = now.v.template head<2>();
    traj.c2 = S(0.5) * now.piece.a.template head<2>();
    traj.h0 = now.r.z() - p.ball_radius;
    traj.h1 = now.v.z();
    traj.h2 = S(0.5) * now.piece.a.z();
  }
  return traj;
}

template <typename S>
EventKind applyTransition(Ball<S>& ball, const PhysicsParams<S>& p)
{
  const S R = p.ball_radius;
  switch (ball.motion)
  {
    case Motion::Sliding: {
      // The slip has reached zero, to within the rounding of the time it does so at: a slip of
      // ulp(t) times its deceleration 7/2 mu_s g, which stiff friction late in a long shot makes
      // far larger than the rounding of the speeds. That remainder is removed as the cloth's
      // friction removes slip, by the impulse -(2/7) m u at the contact point (the slip changes by
      // 7/2 of J/m on a solid sphere): it ends the slip, and it cannot add energy.
      const Vec3<S> u = slipVelocity(ball.v, ball.w, R);
      ball.v -= (S(2) / S(7)) * u;
      ball.w += (S(5) / (S(7) * R)) * Vec3<S>::UnitZ().cross(u);
      // The ball rolls with the velocity it has.
      const bool translating = ball.v.norm() > zeroSpeed<S>();
      if (translating)
      {
        ball.w.x() = -ball.v.y() / R;
        ball.w.y() = ball.v.x() / R;
        ball.motion = Motion::Rolling;
        return EventKind::SlideToRoll;
      }
      ball.v.setZero();
      ball.w.x() = ball.w.y() = S(0);
      ball.motion = ball.w.z() != S(0) ? Motion::Spinning : Motion::Stationary;
      return ball.motion == Motion::Spinning ? EventKind::SlideToSpin : EventKind::SlideToStop;
    }
    case Motion::Rolling:
      ball.v.setZero();
      ball.w.x() = ball.w.y() = S(0);
      ball.motion = std::abs(ball.w.z()) > zeroSpeed<S>() ? Motion::Spinning : Motion::Stationary;
      if (ball.motion == Motion::Stationary)
        ball.w.z() = S(0);
      return ball.motion == Motion::Spinning ? EventKind::RollToSpin : EventKind::RollToStop;
    case Motion::Spinning:
      ball.w.setZero();
      ball.motion = Motion::Stationary;
      return EventKind::SpinToStop;
    case Motion::Airborne:
      return EventKind::BallSlate;  // the engine's ball-table model resolves it
    default:
      return EventKind::None;
  }
}

template <typename S>
S kineticEnergy(const Ball<S>& ball, const PhysicsParams<S>& p)
{
  const S inertia = S(0.4) * p.ball_mass * p.ball_radius * p.ball_radius;
  return S(0.5) * p.ball_mass * ball.v.squaredNorm() + S(0.5) * inertia * ball.w.squaredNorm();
}

template <typename S>
S mechanicalEnergy(const Ball<S>& ball, const PhysicsParams<S>& p)
{
  const S kinetic = kineticEnergy(ball, p);
  return ball.airborne() ? kinetic + p.ball_mass * p.gravity * (ball.r.z() - p.ball_radius) : kinetic;
}

#define CUE_SIM_INSTANTIATE_MOTION(S)                                                                                  \
  template Vec3<S> slipVelocity(const Vec3<S>&, const Vec3<S>&, S);                                                    \
  template Motion classifyMotion(const Vec3<S>&, const Vec3<S>&, S);                                                   \
  template void settleMotion(Ball<S>&, S);                                                                             \
  template S timeToTransition(const Ball<S>&, const PhysicsParams<S>&);                                                \
  template Ball<S> evolve(const Ball<S>&, S, const PhysicsParams<S>&);                                                 \
  template Trajectory<S> trajectoryFrom(const Ball<S>&, S, const PhysicsParams<S>&);                                   \
  template EventKind applyTransition(Ball<S>&, const PhysicsParams<S>&);                                               \
  template S kineticEnergy(const Ball<S>&, const PhysicsParams<S>&);                                                   \
  template S mechanicalEnergy(const Ball<S>&, const PhysicsParams<S>&);
CUE_SIM_INSTANTIATE_MOTION(double)
CUE_SIM_INSTANTIATE_MOTION(long double)

}  // namespace physics
}  // namespace cue_sim

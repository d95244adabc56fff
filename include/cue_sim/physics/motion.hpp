// The closed-form motion of a ball between events: sliding, rolling, spinning (Leckie and
// Greenspan 2005; Alciatore, "Pool and Billiards Physics Principles", TP 4.1; the derivation
// is in README.md), and flight under gravity off the cloth. Nothing here integrates: every state
// at every time is a formula.
#pragma once

#include "cue_sim/physics/ball.hpp"
#include "cue_sim/physics/event.hpp"
#include "cue_sim/physics/physics_params.hpp"

namespace cue_sim
{
namespace physics
{
/// Velocity of the ball's contact point with the cloth, u = v + w x (-R z); its z part is 0.
template <typename S>
Vec3<S> slipVelocity(const Vec3<S>& v, const Vec3<S>& w, S radius);

/// Motion state implied by v and w (Sliding, Rolling, Spinning or Stationary).
template <typename S>
Motion classifyMotion(const Vec3<S>& v, const Vec3<S>& w, S radius);

/// Gives the ball the motion its r, v and w imply, snapping to exact rolling/rest when the slip
/// or speed is below zeroSpeed() so that no spurious transition follows. A ball above the cloth
/// (by more than kOnClothHeight) or rising off it (v_z > zeroSpeed()) is Airborne and keeps its
/// r and v (a ball held in the air stays held while it is at rest); any other is put on the cloth: z = R, and v_z = 0
/// (a ball pressed into the cloth by a collision meets the slate first: the engine resolves that before it settles the
/// ball).
template <typename S>
void settleMotion(Ball<S>& ball, S radius);

/// A centre this little above R [m] is on the cloth: 64 ulps of R, the rounding of a flight's
/// height at its landing.
template <typename S>
S onClothHeight(S radius)
{
  return S(64) * std::numeric_limits<S>::epsilon() * radius;
}

/// Duration [s] of the ball's current motion state from ball.time; +inf if it never ends. A ball
/// in the air ends its flight when its centre comes down to R (the slate).
template <typename S>
S timeToTransition(const Ball<S>& ball, const PhysicsParams<S>& p);

/// The ball at time t >= ball.time, t no later than its transition: pure, closed form.
template <typename S>
Ball<S> evolve(const Ball<S>& ball, S t, const PhysicsParams<S>& p);

/// Position in the current motion state as a quadratic in tau = t - t_base:
/// r(tau) = c0 + c1 tau + c2 tau^2 (xy; valid until the ball's next transition), and the centre's
/// height above R, h(tau) = h0 + h1 tau + h2 tau^2 (all zero on the cloth; in flight h2 = -g/2
/// and c2 = 0).
template <typename S>
struct Trajectory
{
  Vec2<S> c0, c1, c2;
  S h0 = S(0), h1 = S(0), h2 = S(0);
  Vec2<S> at(S tau) const { return c0 + tau * (c1 + tau * c2); }
  Vec2<S> velocityAt(S tau) const { return c1 + S(2) * tau * c2; }
  S heightAt(S tau) const { return h0 + tau * (h1 + tau * h2); }
};

template <typename S>
Trajectory<S> trajectoryFrom(const Ball<S>& ball, S t_base, const PhysicsParams<S>& p);

/// Applies the transition that ends the ball's current motion state on the cloth (the ball must
/// be at its transition time) and returns which it was. A flight's end is the slate's impact,
/// which the engine's ball-table model resolves: EventKind::BallSlate, the ball unchanged.
template <typename S>
EventKind applyTransition(Ball<S>& ball, const PhysicsParams<S>& p);

/// Kinetic energy [J] of translation and rotation (solid sphere, I = 2/5 m R^2).
template <typename S>
S kineticEnergy(const Ball<S>& ball, const PhysicsParams<S>& p);

/// Kinetic energy [J], and for a ball in the air (flying or held) the potential of its height
/// above the cloth, m g (z - R): a falling ball gains speed, not energy.
template <typename S>
S mechanicalEnergy(const Ball<S>& ball, const PhysicsParams<S>& p);

}  // namespace physics
}  // namespace cue_sim

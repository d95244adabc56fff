// A ball in the air left on a rounded support (another ball, a cushion's nose, a post's rim) and
// pressed on by gravity or by the support itself: the rolling or sliding round the support that
// follows has no closed form, so it is followed in hops (doc/physics.md, "Balls in the air").
// Internal to the physics core.
#pragma once

#include "cue_sim/physics/ball.hpp"

namespace cue_sim
{
namespace physics
{
/// A fixed support (a nose's edge, a rim): the ball, leaving it slower than kSettleSpeed along
/// the normal `n` (from the support to the ball), is sent on round it with kSettleSpeed along `n`
/// and the rest of its speed along the support. Its speed is unchanged. False if it had less than
/// kSettleSpeed to hop with (all of it is then along `n`).
template <typename S>
bool hopOffFixedSupport(Ball<S>& ball, const Vec3<S>& n);

/// A support on the cloth (a ball, whose vertical impulse the slate takes): the flying ball,
/// leaving it slower than kSettleSpeed along `n` (from the support to the flying ball), is pushed
/// off by an impulse between the two (horizontal momentum kept) that gives them kSettleSpeed
/// apart along `n`. It is paid for by the sliding between them, as friction would take it, so no
/// energy is made. The hop tried first is `most`; when their sliding cannot pay for it, it is
/// halved, down to `least`. False, and the balls unchanged, if even that cannot be paid.
template <typename S>
bool hopOffBallOnCloth(Ball<S>& flying, Ball<S>& support, const Vec3<S>& n, S most, S least);

/// A ball in the air closing on its support slower than this [m/s] is pressed on it by gravity
/// between hops (the hops are kSettleSpeed): a sustained contact, in which no impact loses energy.
/// The impact is elastic and frictionless. Real spheres' restitution tends to 1 at such speeds
/// (viscoelastic impact: 1 - e grows as the fifth root of the speed, Kuwabara and Kono 1987), and
/// a hop that lost a part would have to be paid again from the ball's sliding down its support,
/// which would stop it there (doc/physics.md, "Resting on a rounded support").
constexpr double kSustainedContactSpeed = 4e-3;

/// A landing on a support on the cloth slower than kSustainedContactSpeed: the flying ball and
/// the support part along `n` (from the support to the flying ball) as fast as they closed, by an
/// impulse along `n` whose vertical part the slate takes. No friction, energy kept (to rounding,
/// never gained). False, and the balls unchanged, if they are not closing so slowly.
template <typename S>
bool bounceOffBallOnCloth(Ball<S>& flying, Ball<S>& support, const Vec3<S>& n);

/// The same off a fixed support (a nose's edge, a rim): the normal velocity is reversed.
template <typename S>
bool bounceOffFixedSupport(Ball<S>& ball, const Vec3<S>& n);

/// The smallest hop off a support [m/s]: below it, gravity brings the ball back within a few
/// nanoseconds, and the ball is taken to be at rest on it.
constexpr double kSmallestHop = 1e-9;

}  // namespace physics
}  // namespace cue_sim

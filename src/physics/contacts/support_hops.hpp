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

/// The smallest hop off a support [m/s]: below it, gravity brings the ball back within a few
/// nanoseconds, and the ball is taken to be at rest on it.
constexpr double kSmallestHop = 1e-9;

}  // namespace physics
}  // namespace cue_sim

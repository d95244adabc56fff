// A ball coming down onto the slate (after a jump, a hop off a cushion or a jaw, a drop): a rigid
// impact at the contact point -R z with normal restitution e_t and Coulomb friction mu_t, and the
// whole sequence of bounces that follows it in closed form. The two parameters are those of
// pooltool's ball-table model (normal restitution, and Coulomb friction at the contact); mu_t = 0
// is the frictionless variant. Private to the motion models.
//
// One impact. The slate gives back e_t of the normal speed: a normal impulse (1 + e_t) m |v_z|.
// Friction acts against the contact point's slip u = v + w x (-R z) (its xy part), at most mu_t
// times the normal impulse. Per unit mass a tangential impulse J against u changes v by -J u_hat
// and w by (5 J / 2R)(z x u_hat), and so the slip by -(7/2) J u_hat (a solid sphere, I = 2/5 m R^2):
// the slip keeps its direction, and friction that could stop it stops it exactly (J = 2/7 |u|)
// and does no more (Coulomb: the contact then sticks). Both impulses act at the contact point, so
// the angular momentum about it is kept; the z-spin is not touched.
//
// The bounces. After an impact with incoming normal speed U_k the ball flies for 2 e_t U_k / g
// and comes down at U_{k+1} = e_t U_k: the impacts and their times form geometric series, and
// so does the friction each can give, mu_t (1 + e_t) U_k. The sequence has infinitely many
// impacts in a finite time (a Zeno sequence) and ends with the ball on the cloth:
//   the time from the first impact to the end, 2 e_t U_0 / (g (1 - e_t));
//   the impact that stops the slip, the first K with (7/2) mu_t (1 + e_t) sum_{j <= K} U_j >= |u_0|,
//   or none (the ball ends the sequence still sliding, with (7/2) mu_t (1+e_t) U_0 / (1 - e_t)
//   less slip);
//   the way the centre goes meanwhile, each flight's horizontal velocity times its time, summed in
//   closed form (bounceSeries, slate_bounce.cpp).
// Nothing here is approximate: the sums are exact for the impact law above.
#pragma once

#include "cue_sim/physics/ball.hpp"

namespace cue_sim
{
namespace physics
{
/// The slate's contact: normal restitution e_t in [0, 1) and Coulomb friction mu_t >= 0.
template <typename S>
struct SlateContact
{
  S restitution = S(0.5);
  S friction = S(0.2);
};

/// The ball just after one impact on the slate: only its v and w change. `in` must be coming down
/// (v.z < 0), or it is returned as it is.
template <typename S>
Ball<S> slateImpact(const Ball<S>& in, const SlateContact<S>& contact, S radius);

/// The whole bounce sequence after a first impact met with `in` (v.z < 0, at the slate).
template <typename S>
struct BounceSeries
{
  /// On the cloth when the bounces end: its time, its centre moved by every flight's way, its
  /// motion settled (sliding, rolling, spinning or at rest).
  Ball<S> end;
  int slip_stopped_at = -1;  ///< the impact (0 the first) whose friction stopped the slip; -1 none
  S first_rebound = S(0);    ///< the centre's rise after the first impact [m]
};

template <typename S>
BounceSeries<S> bounceSeries(const Ball<S>& in, const SlateContact<S>& contact, S radius, S gravity);

}  // namespace physics
}  // namespace cue_sim

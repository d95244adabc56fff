// Stronge's compliant frictional impact along one tangent (W. J. Stronge, Impact Mechanics, 2nd
// ed., Cambridge 2018, tangential compliance; after Maw, Barber and Fawcett 1976). Private to the
// cushion models.
//
// The contact is two springs: a normal one, stiff k_n in compression and k_n/e^2 in restitution
// (so the normal velocity comes back times e), and a tangential one whose far end sticks to the
// other surface until its force reaches mu times the normal force, then slides (Coulomb). In the
// phase tau = omega_n t the normal force is m v_n sin(psi), with psi = tau in compression and
// psi = pi/2 + (tau - pi/2)/e in restitution; the tangential spring vibrates at eta = omega_t /
// omega_n = sqrt((beta_t / beta_n)(k_t / k_n)), beta the inverse masses at the contact in units
// of 1/m. In those units the outcome depends on eta, mu, e and beta_t only: the stiffness sets
// the impact's duration, not its result.
//
// If the tangential slip starts along one direction it stays along it (both springs start
// relaxed), so one tangent carries the whole problem. Between transitions it has a closed form:
// sliding, the slip falls by mu beta_t times the normal impulse; stuck, the spring vibrates
// freely. A slide ends where the slip the spring passes on meets the spring's own rate, which is
// linear in cos(psi); a stick ends where the spring's force reaches the friction limit, found by
// bracketing on a grid finer than both oscillations and bisecting.
#pragma once

namespace cue_sim
{
namespace physics
{
/// The slip velocity of the contact along its initial direction after the impact (negative: it
/// turned round), starting at `slip` >= 0 with the bodies closing at `approach` > 0.
/// `beta_t`: tangential inverse mass at the contact in units of the normal one (7/2 for a ball on
/// a rigid wall); `eta`: the frequency ratio omega_t / omega_n > 0; `e` in [0, 1]; `mu` >= 0.
template <typename S>
S slipAfterCompliantImpact(S slip, S approach, S mu, S beta_t, S e, S eta);

}  // namespace physics
}  // namespace cue_sim

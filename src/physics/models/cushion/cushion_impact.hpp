// A ball-cushion impact followed through the normal impulse at the nose (Mathavan, Jackson and
// Parkin 2010): the ball's state as the impulse grows, the slips at the nose and at the cloth,
// and the integration over compression and restitution. Private to the cushion models.
#pragma once

#include "cue_sim/physics/ball.hpp"
#include "cue_sim/physics/physics_params.hpp"

namespace cue_sim
{
namespace physics
{
template <typename S>
class CushionImpact
{
public:
  /// `normal`: the cushion's unit xy normal into play. The nose touches the ball
  /// alpha = asin(cushion_height/R - 1) above its equator.
  CushionImpact(const Ball<S>& ball, const Vec3<S>& normal, const PhysicsParams<S>& p);

  /// The closing speed of the ball on the nose, along the contact normal (> 0 while closing).
  S approach() const { return approachOf(state_); }

  /// Compression until the ball stops closing on the nose, then restitution until the normal
  /// force has given back e_work^2 of the compression's work. The normal impulse grows in
  /// `steps` equal parts of its frictionless total (1 + e) m approach / cos^2(alpha); each part
  /// is one midpoint step, the friction at each contact capped by the impulse that would stop
  /// its slip. At most 8 steps + 8 per phase: a ball friction keeps pressing on (mu_nose beyond
  /// cot(alpha)) leaves with its remaining normal velocity reversed and scaled by e_work.
  void integrate(S e_work, S mu_nose, S mu_cloth, int steps);

  const Vec3<S>& velocity() const { return state_.v; }
  const Vec3<S>& spin() const { return state_.w; }
  /// The normal impulse at the nose so far [N s].
  S normalImpulse() const { return impulse_; }

private:
  struct State
  {
    Vec3<S> v, w;
  };

  /// Sweeps over the two frictions per step: each sweep takes the other's from the last.
  static constexpr int kFrictionSweeps = 3;

  S approachOf(const State& s) const { return -s.v.dot(contact_normal_); }
  Vec3<S> noseSlip(const State& s) const;
  Vec3<S> clothSlip(const State& s) const;
  /// Coulomb friction at a contact whose slip would end the step at `slip_without` with no
  /// friction there: the impulse that stops it if it is at most `limit`, else `limit` against
  /// `sliding_direction`.
  Vec3<S> friction(const Vec3<S>& slip_without, const Vec3<S>& sliding_direction, S limit, bool& sticks) const;
  /// The state after normal impulse dp at the nose, with the frictions it brings.
  State pushed(const State& from, const State& sliding, S dp) const;
  /// The state after normal impulse dp at the nose and the two friction impulses.
  State applied(const State& from, S dp, const Vec3<S>& at_nose, const Vec3<S>& at_cloth) const;
  /// One midpoint step of normal impulse dp.
  State step(const State& from, S dp) const;
  void leaveWithRestitution(S e_work);

  S mass_, radius_, inverse_mass_, inverse_inertia_;
  Vec3<S> nose_;            ///< from the centre to the nose's contact
  Vec3<S> cloth_;           ///< from the centre to the cloth's contact
  Vec3<S> contact_normal_;  ///< nose -> centre
  Vec3<S> normal_;          ///< the cushion's xy normal into play
  S mu_nose_ = 0, mu_cloth_ = 0;
  State state_;
  S impulse_ = 0;
};

}  // namespace physics
}  // namespace cue_sim

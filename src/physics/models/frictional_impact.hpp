// A rigid-body impact with Coulomb friction at several point contacts, followed through the
// normal impulse P at its main contact (Mathavan, Jackson and Parkin 2010 for a cushion, 2014
// for two balls on the cloth). Private to the contact models.
//
// Rigid bodies make every velocity during the impact linear in the impulses so far: P and two
// tangential friction components per contact. Those are the state; the contacts' slips and the
// main contact's closing speed are fixed linear maps of it, which the model sets up once per
// impact (cushion_impact.hpp, ball_pair_impact.hpp). Contact 0 is the main one, pressed by P;
// every other contact is pressed by what the impulses it takes from the rest push into it (the
// cloth under a ball pressed down by friction), never pulled.
#pragma once

#include <Eigen/Dense>
#include <array>

#include "cue_sim/physics/types.hpp"

namespace cue_sim
{
namespace physics
{
template <typename S, int Contacts, int Bodies>
class FrictionalImpact
{
public:
  static constexpr int kImpulses = 1 + 2 * Contacts;
  using Impulses = Eigen::Matrix<S, kImpulses, 1>;  ///< P, then each contact's friction (2)
  using Slips = Eigen::Matrix<S, 2 * Contacts, 1>;  ///< each contact's slip in its tangent plane
  using Motion = Eigen::Matrix<S, 3 * Bodies, 1>;   ///< each body's velocity, or spin, stacked
  using Vec2 = Eigen::Matrix<S, 2, 1>;

  /// What the impact's geometry makes of each unit impulse (column k for impulse k).
  struct Setup
  {
    Motion velocity0, spin0;
    Eigen::Matrix<S, 3 * Bodies, kImpulses> velocity_per_impulse, spin_per_impulse;
    Slips slip0;
    Eigen::Matrix<S, 2 * Contacts, kImpulses> slip_per_impulse;
    S approach0 = 0;  ///< the main contact's closing speed (> 0 while closing)
    Eigen::Matrix<S, 1, kImpulses> approach_per_impulse;
    /// Contact c's normal impulse over a step is max(0, load.row(c) times the step's impulses);
    /// row 0 is (1, 0, ...): the main contact's is P.
    Eigen::Matrix<S, Contacts, kImpulses> load;
    std::array<S, Contacts> mu{};  ///< each contact's Coulomb friction coefficient
    S radius = 1;                  ///< the spin's lever in the error: R |dw| beside |dv|
  };

  explicit FrictionalImpact(const Setup& setup);

  /// The main contact's closing speed now.
  S approach() const { return approachAt(impulses_); }

  /// Compression until the main contact stops closing, then restitution until its normal force
  /// has given back e_work^2 of the compression's work (Stronge's energetic coefficient). P grows
  /// in midpoint steps whose error, one step against two half steps, stays within `tolerance` of
  /// the impact's speed scale (|v| + R |w|); a step also ends where a slip turns, and is halved
  /// where a friction would work with its slip. A contact whose slip friction can stop and hold
  /// sticks (Coulomb); one that keeps slipping slides against its slip half way through the
  /// step. The impact is jammed when its closing speed stops changing for kJammedSteps steps
  /// (friction pressing it on as fast as P pushes it apart, or contacts held so that it cannot
  /// part), or when compression has taken kJammedImpulse times the frictionless impulse. Jammed,
  /// or after kMaxSteps, the remaining closing speed is reversed and scaled by e_work with P.
  void integrate(S e_work, S tolerance);

  Motion velocities() const { return velocity0_ + velocity_per_impulse_ * impulses_; }
  Motion spins() const { return spin0_ + spin_per_impulse_ * impulses_; }

private:
  /// A compression that has taken this many times the frictionless impulse is jammed: friction
  /// at a cushion's nose can slow the normal push by (cos(alpha) - mu sin(alpha)) / cos(alpha),
  /// which is above 1/16 unless mu is within 6 % of cot(alpha).
  static constexpr double kJammedImpulse = 16;
  /// Steps in a row whose closing speed falls slower than kJammedRate of the frictionless rate
  /// that mark a jam sooner.
  static constexpr int kJammedSteps = 4;
  static constexpr double kJammedRate = 1e-3;
  /// Halvings of a step before it is taken whatever its error (frictionless if a friction would
  /// work with its slip): 2^-12 of a step.
  static constexpr int kMaxHalvings = 12;
  /// Gauss-Seidel sweeps over the frictions of a step at most, and the relative change at which
  /// they have settled (a sticking contact's impulse is linear in the others': the sweeps
  /// contract). A weak coupling settles in a sweep or two; a strong one (mu_cushion 2 and mu_slide
  /// 4 at a nose: tens of sweeps) is found sooner contact by contact from the last step's
  /// assignment, a 4x4 or 6x6 solve: 64 sweeps took an impact there 0.4 ms, 4 take it 0.08 ms.
  static constexpr int kMaxFrictionSweeps = 4;
  static constexpr double kSweepSettled = 1e-15;
  /// A linear solution of a step agrees with Coulomb's law when friction() gives back each of
  /// its frictions within this share of the step's impulses (rounding of a small solve).
  static constexpr double kCoulombAgreement = 1e-12;
  /// The first step: this share of the frictionless impulse.
  static constexpr int kFirstSteps = 16;
  /// A halved step's error falls by 8 at second order; one that falls by less than this is
  /// first order: a switch inside the step. Below this share of the frictionless impulse a step
  /// with such a switch is taken as it is (see controlledStep).
  static constexpr double kSecondOrderFall = 4;
  static constexpr double kSlidingModeStep = 1.0 / 1024;
  /// Steps an impact may take.
  static constexpr int kMaxSteps = 16384;
  /// A friction's work within rounding of none, per unit impulse and unit of the impact's speed
  /// scale (|v| + R |w| before it): a sticking contact's slip is rounding of that scale.
  static constexpr double kWorkRounding = 1e-12;
  /// The shortest step to a slip's turning, as a fraction of the step: a slip that turns at the
  /// step's very start turns within rounding of it.
  static constexpr double kShortestReversalStep = 1e-3;
  /// A sliding direction from a slip below this share of the slip the step would end with
  /// without friction is taken from the latter: the slip has only begun.
  static constexpr double kUnsettledSlip = 1e-2;

  /// A slip below this has no direction: within rounding of zeroSpeed, or of the impact's own
  /// speed scale when that is itself near rounding (a ball pressed on a cushion at 1e-12 m/s).
  S slipFloor() const { return std::min(zeroSpeed<S>(), S(kWorkRounding) * speed_scale_); }
  Slips slipsAt(const Impulses& y) const { return slip0_ + slip_per_impulse_ * y; }
  S approachAt(const Impulses& y) const { return approach0_ + approach_per_impulse_.dot(y); }
  /// The main contact's closing speed falls by this per unit P without friction.
  S frictionlessRate() const { return -approach_per_impulse_(0); }
  /// The impulses one step of normal impulse dp adds, the frictions sliding against `sliding`.
  Impulses pushed(const Impulses& from, S dp, const Slips& sliding) const;
  /// What a contact's friction does over a step, as solvedContactByContact tries them.
  enum class ContactDoes
  {
    kStick,
    kSlide,
    kUnloaded
  };
  /// The step's impulses found exactly when the Gauss-Seidel sweeps of pushed() do not settle:
  /// each assignment of sticking, sliding and unloaded contacts is solved as a linear system and
  /// kept if friction() agrees with it at every contact. False if none does.
  bool solvedContactByContact(const Slips& start, S dp, const Slips& sliding, Impulses& solved) const;
  /// Whether friction() gives back `add`'s frictions at every contact, within kCoulombAgreement.
  bool isCoulomb(const Slips& start, const Impulses& add, const Slips& sliding) const;
  /// Contact c's Coulomb friction (friction()) over a step that starts from slips `start` and
  /// takes impulses `add`, with the other contacts' frictions as `add` has them.
  Vec2 frictionAt(int c, const Slips& start, const Impulses& add, const Slips& sliding, bool& sticks) const;
  /// One midpoint step.
  Impulses step(const Impulses& from, S dp) const;
  /// Whether no friction does positive work on the straight way from `from` to `to`.
  bool frictionWorksAgainstTheSlips(const Impulses& from, const Impulses& to) const;
  /// The fraction of the step from `from` to `to` at which a contact's slip, passing through
  /// zero, turns; 1 if none does.
  S reversalFraction(const Impulses& from, const Impulses& to) const;
  /// One step of at most dp within the tolerance (see integrate); dp is set to the step taken
  /// and `error` to its estimated error.
  Impulses controlledStep(const Impulses& from, S& dp, S tolerance, S& error) const;
  /// Coulomb friction at one contact over a step that starts with `slip_from` and would end with
  /// `slip_without` with no friction there: the impulse that stops the slip if friction within
  /// `limit` can stop it and then hold it, else `limit` against `sliding`. Sets `sticks`.
  Vec2 friction(const Eigen::Matrix<S, 2, 2>& stop_per_slip, const Vec2& slip_from, const Vec2& slip_without,
                const Vec2& sliding, S limit, bool& sticks) const;
  /// Whether the closing speed, from `before` to `after` over normal impulse dp, fell slower than
  /// kJammedRate of its frictionless rate.
  bool closingStalls(S before, S after, S dp) const;
  void leaveWithRestitution(S e_work);

  Motion velocity0_, spin0_;
  Eigen::Matrix<S, 3 * Bodies, kImpulses> velocity_per_impulse_, spin_per_impulse_;
  Slips slip0_;
  Eigen::Matrix<S, 2 * Contacts, kImpulses> slip_per_impulse_;
  S approach0_;
  Eigen::Matrix<S, 1, kImpulses> approach_per_impulse_;
  Eigen::Matrix<S, Contacts, kImpulses> load_;
  std::array<S, Contacts> mu_;
  std::array<Eigen::Matrix<S, 2, 2>, Contacts> stop_;  ///< friction impulse per unit slip that stops it
  S radius_, speed_scale_;
  S total_ = 0;  ///< the frictionless impulse of the impact being integrated
  Impulses impulses_ = Impulses::Zero();
  /// Where solvedContactByContact starts: the assignment it found last.
  mutable int assignment_hint_ = 0;
};

}  // namespace physics
}  // namespace cue_sim

// The parts of resolving one event (internal to src/physics/contacts/): an impact of a touching
// group (impact_group.cpp), sustained contact of balls and walls on the cloth (sustained_contact.cpp),
// groups of balls in sustained contact in the air moved by the contact equations (support_groups.cpp),
// and the event itself, pocketing and neighbours (event_resolution.cpp).
#pragma once

#include <algorithm>
#include <vector>

#include "cue_sim/physics/engine.hpp"
#include "physics/contacts/event_resolution.hpp"
#include "physics/engine/table_geometry.hpp"
#include "physics/models/ball_table/slate_landing.hpp"
#include "physics/supports/contact_geometry.hpp"

namespace cue_sim
{
namespace physics
{
/// A speed [m/s] a few ulps above the rounding of speeds of this size: the least change that
/// an event's tests are sure to see.
template <typename S>
S roundingSpeed(S speed)
{
  return S(2) * zeroSpeed<S>() * (S(1) + speed);
}

/// Speed [m/s] at which a is closing on b along their line of centres (negative: parting).
template <typename S>
S closingSpeed(const Ball<S>& a, const Ball<S>& b)
{
  const Vec2<S> n = (b.r - a.r).template head<2>().normalized();
  return (a.v - b.v).template head<2>().dot(n);
}

/// Takes out what is left of two balls' closing along their line of centres, as a perfectly
/// inelastic, frictionless impulse would (equal masses: each loses half); spins are untouched.
template <typename S>
bool stopClosing(Ball<S>& a, Ball<S>& b)
{
  const Vec2<S> n = (b.r - a.r).template head<2>().normalized();
  const S closing = (a.v - b.v).template head<2>().dot(n);
  if (!(closing > zeroSpeed<S>()))
    return false;
  a.v.template head<2>() -= S(0.5) * closing * n;
  b.v.template head<2>() += S(0.5) * closing * n;
  return true;
}

/// Takes out a ball's motion into a wall, as a perfectly inelastic, frictionless wall would.
template <typename S>
bool stopClosing(Ball<S>& ball, const Vec3<S>& normal)
{
  const S into = ball.v.dot(normal);
  if (!(into < -zeroSpeed<S>()))
    return false;
  ball.v -= into * normal;
  return true;
}

/// Two balls (or a ball and a wall) whose centres are this much further apart than touching
/// [m] still touch: a contact resolved at an event leaves them at the contact distance within
/// rounding.
constexpr double kTouchingSlack = 1e-12;

/// Two walls' normals are parallel within this (1 - |cos|). Opposed, the walls face each other
/// across the table (the long cushions); alike, a ball touching both touches one surface (a jaw
/// where the cushion tangent to it ends: within a micrometre of the tangent point, since it
/// touches both within kTouchingSlack).
constexpr double kParallelWalls = 1e-6;

/// Impulses of the cushion model one wall contact may take before the wall stops what is left of
/// the ball's motion into it: each removes a share (1 + e) cos^2(theta) of it, so 64 leave less
/// than 1e-4 of it unless that share is under 14 % (a nose within 3 % of R of the ball's top).
constexpr int kMaxWallImpulses = 64;

/// Sweeps of the model's impulses over an impact group (or a lone pair) before what still
/// closes is taken out by frictionless, perfectly inelastic impulses. The groups of 300 soak
/// shots need at most 713 sweeps, most of them under 10; a group still closing after 2000 is
/// circling in rounding. Soak seed 1 shot 305 has one: a ball driven into a corner by another
/// (e_ball 0.04, Mathavan 2014 and Stronge's cushion), whose friction at ball and cushion turns
/// spin into closing speeds of 4e-13 m/s that the next sweep turns back, in a cycle of 30 000
/// sweeps; each of its events took 3 s at the former cap of 100 000 sweeps, 257 of them at one
/// instant until EngineLimits::collapse_events joined the pair.
constexpr int kImpactSweeps = 2000;
/// Sweeps of the frictionless, perfectly inelastic impulses that end such a group: a few
/// multiplications per contact each, with no spin to turn back into closing speed.
constexpr int kInelasticSweeps = 100000;

/// Events closer together than this [s] (plus kSameInstantPerSecond of the time itself, for the
/// rounding of a large clock) count as one instant for EngineLimits::collapse_events. A ball
/// wedged between a wall and balls held by the facing wall can be found at the wall and at the
/// ball in turn, each a few dozen ulps of time after the last, without end: an inelastic collapse
/// at distinct but indistinguishable times. No two real impacts are resolved this closely: at the
/// fastest cue speed (12 m/s) a ball moves 1.2e-11 m in it, well below the 1e-9 m the engine keeps
/// balls apart by.
constexpr double kSameInstant = 1e-12;
constexpr double kSameInstantPerSecond = 1e-13;

template <typename S>
class ContactSystem;
template <typename S>
struct SupportStep;
template <typename S>
struct SupportGroup;
struct Membership;

template <typename S>
class EventResolver
{
public:
  EventResolver(const Engine<S>& engine, TableState<S>& state, const EventContext<S>& context)
    : engine_(engine),
      params_(engine.params()),
      geometry_(engine.geometry()),
      state_(state),
      context_(context),
      changed_from_(context.changed ? context.changed->size() : 0)
  {
  }

  void resolve(const Event<S>& event);
  /// Lets fall every ball held in the air that a ball this event changed touches.
  void wakeHeldBalls(S time);
  /// Takes the next step now of every group in sustained contact touching a ball this event changed.
  void restepTouchedGroups(S time);

private:
  void resolveBallBall(const Event<S>& event);
  /// A pair of which at least one ball is in the air or moved by the contact equations: slower than
  /// kSettleSpeed, a sustained contact (their group's next step); else an impact, then any ball
  /// driven into the slate lands on it.
  void resolvePairOffTheCloth(const Event<S>& event);
  /// The model's impulse along the line of centres `n` (from a to b) in three dimensions, a ball
  /// on the cloth kept on it.
  void impactInAir(Ball<S>& a, Ball<S>& b, const Vec3<S>& n);
  void resolveWall(Ball<S>& ball, const Event<S>& event);
  /// A ball in the air above the wall's top meets its nose's edge or its post's rim: true if so
  /// (and resolved).
  bool resolveWallTop(Ball<S>& ball, const Event<S>& event);
  /// A ball in the air past the cushions lands on the rail, the floor or in a pocket.
  void leaveTable(Ball<S>& ball);
  /// The cushion model's impulses on a ball closing on a wall (`normal` into play), until it no
  /// longer closes; what kMaxWallImpulses of them leave of its motion into the wall, the wall
  /// stops.
  void wallImpact(Ball<S>& ball, const Vec3<S>& normal) const;
  /// After a wall's impact, a ball on the cloth that touches another wall too meets them all as
  /// one impact (see the definition).
  void cornerImpact(Ball<S>& ball) const;
  void pocketBall(Ball<S>& ball, int pocket);
  bool heldHere(int index) const { return std::find(held_here_.begin(), held_here_.end(), index) != held_here_.end(); }
  void changed(int index) { (context_.changed ? *context_.changed : changed_here_).push_back(index); }
  /// The balls in play that may be within `distance` of `point`, ascending.
  void nearBalls(const Vec2<S>& point, S distance, std::vector<int>& out) const;
  /// True if the ball cannot be within `distance` of `point` (xy) at `time`: a cheap bound.
  bool cannotReach(const Ball<S>& ball, const Vec3<S>& point, S distance, S time) const;

public:
  // support_groups.cpp: balls in sustained contact (doc/physics.md, "Resting contact")
  /// The group of ball `seed` takes its next step from `time` (its piece ends then, or an event
  /// changed it): the balls touching it are gathered, what of them still closes is stopped, the
  /// contact equations' modes are chosen, and the balls they press on move by the next integrated
  /// step, come to rest (Held in the air, Stationary on the cloth), or go back to their own
  /// closed-form motion.
  void stepGroup(S time, int seed);

private:
  /// A ball's state at `time` as a step starts from it: along its path, and at the end of a piece
  /// the velocity the contact equations gave it there.
  Ball<S> stateAt(int index, S time) const;
  /// The balls moved by the contact equations touching ball `index` or each other, transitively,
  /// at `time` (ball `index` first, if it is one).
  std::vector<int> supportedGroupOf(int index, S time);
  /// Brings the group of ball `index` to `time` along its pieces (an event within them changes it).
  void cutGroup(int index, S time);
  /// Every ball of the group of ball `index` back to its own closed-form motion at `time` (an impact
  /// among them, a pocket, a ball leaving the table).
  void dissolveGroup(int index, S time);
  /// The step's group: the balls, their contacts and the bodies the contact equations move.
  SupportGroup<S> gatherGroup(S time, int seed);
  /// Impacts within the group (faster than a sustained contact), then what still closes stopped.
  void meetWithinGroup(const ContactSystem<S>& system, SupportGroup<S>& group);
  /// The contacts' modes at the step's start, the drift off the pressed ones taken out.
  void decideGroupModes(const ContactSystem<S>& system, SupportGroup<S>& group);
  /// Ball k of the group back to its own closed-form motion (or held, if it was and is still).
  void writeFree(const SupportGroup<S>& group, std::size_t k, S time);
  /// Ball k of the group at rest where it is: Held in the air, Stationary on the cloth.
  void holdAtRest(const SupportGroup<S>& group, std::size_t k, bool on_slate, S time);
  /// The group's members given the pieces the step integrated.
  void writePieces(const SupportGroup<S>& group, const Membership& who, const SupportStep<S>& step, S time);
  /// Whether two bodies meet slowly enough for a sustained contact: the contact lasts (about 0.2 ms
  /// for billiard balls) longer than a bounce at kSettleSpeed would (Luding and McNamara's TC model).
  static bool meetSlowly(S closing) { return closing < S(kSettleSpeed); }

  // impact_group.cpp
  /// Resolves a ball-ball impact together with every ball touching the pair, and the cushions
  /// those balls touch: one impact. Returns whether the pair's velocities changed.
  bool resolveImpactGroup(S time, int first, int second);
  /// The balls touching the pair (or the ball alone, `second` -1), transitively, at `time`
  /// (brought to it), the pair first.
  std::vector<int> touchingGroup(S time, int first, int second);
  bool resolveLonePair(int first, int second);
  /// A ball on the cloth (`support`) just struck from the air by `flying` and driven into the
  /// balls it touches: their group's impact (and the walls it then still drives it into), then
  /// the flying ball's on it again, in turn until neither closes (kImpactSweeps); what the
  /// flying ball still closes then, it loses.
  void passImpactOnThroughCloth(S time, int flying, int support);

  // sustained_contact.cpp
  bool inSustainedContact(const Ball<S>& a, const Ball<S>& b) const;
  /// Gives the pair, and every ball pressed against them in sustained contact, the mean of
  /// their velocities and spins (EngineLimits::sustained_contact_speed).
  void joinPressedCluster(S time, int first, int second);
  /// Grows the cluster by one ball that touches it and that the joined velocity `v` leaves
  /// closing on it slower than the sustained-contact speed; false if there is none.
  bool growCluster(S time, const Vec3<S>& v, std::vector<int>& cluster);
  /// Gives every ball of the cluster the joined motion, held by the walls they touch.
  void moveAsOne(Ball<S>& joined, const std::vector<int>& cluster);
  /// Ends an inelastic collapse (EngineLimits::collapse_events): every ball touching the event's
  /// balls (`second` -1 for a wall event) moves as one body, or stops.
  void collapse(S time, int first, int second, bool stop);
  /// Unit normals (into play) of the cushions and jaws the ball touches; a jaw parallel to a
  /// cushion it touches too (where the cushion ends) is that cushion's surface, not another wall.
  std::vector<Vec3<S>> touchingWalls(const Ball<S>& ball) const;
  /// A sliding ball left on a wall with (almost) no normal speed while its slip drives it back
  /// in stays on the wall: the normal speed is removed and the slip's part into the wall is
  /// turned into spin by the cloth friction the wall balances.
  void holdAgainstWall(Ball<S>& ball, const Vec3<S>& normal) const;
  /// Whether a wall among `walls` faces the one with this normal across the table.
  static bool facedAcross(const Vec3<S>& normal, const std::vector<Vec3<S>>& walls);
  /// A cluster touching walls that face each other across it: its motion and slip across them
  /// are taken out.
  void holdAcross(Ball<S>& joined, const Vec3<S>& normal) const;

private:
  const Engine<S>& engine_;
  const PhysicsParams<S>& params_;
  const TableGeometry<S>& geometry_;
  TableState<S>& state_;
  const EventContext<S>& context_;
  /// The balls this resolver changed: context_.changed from changed_from_ on, else changed_here_.
  std::size_t changed_from_;
  std::vector<int> changed_here_;
  /// The balls a group held at rest in this event: judged with the balls touching them as they now
  /// move, they are not let fall by them (wakeHeldBalls), or each would fall and be held again at
  /// the same instant for ever.
  std::vector<int> held_here_;
};

template <typename S>
inline void EventResolver<S>::nearBalls(const Vec2<S>& point, S distance, std::vector<int>& out) const
{
  if (context_.neighbours)
  {
    context_.neighbours->near(point, distance, out);
    return;
  }
  out.clear();
  for (std::size_t j = 0; j < state_.balls.size(); ++j)
    if (state_.balls[j].inPlay())
      out.push_back(static_cast<int>(j));
}

template <typename S>
inline bool EventResolver<S>::cannotReach(const Ball<S>& ball, const Vec3<S>& point, S distance, S time) const
{
  // No ball speeds up by more than the sliding deceleration, so by `time` it has moved at most
  // |v| dt + a dt^2 / 2 (with a nanometre for rounding): a bound that spares evolving it.
  const S dt = time - ball.time;
  const S travel = ball.moving() ? dt * (ball.v.norm() + S(0.5) * params_.slideDecel() * dt) : S(0);
  const S reach = distance + travel + S(kBoxMargin);
  return (ball.r - point).template head<2>().squaredNorm() > reach * reach;
}

}  // namespace physics
}  // namespace cue_sim

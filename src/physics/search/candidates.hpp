// Candidate events and what the search knows of each ball (internal to the event search). Every
// candidate of a ball (its transition, a cushion, jaw or pocket) or of a pair of balls is a pure
// function of those balls' own states, so candidates can be kept between events and found again
// only for the balls an event changed, or all found afresh, with bit-identical results.
#pragma once

#include <vector>

#include "cue_sim/physics/engine.hpp"
#include "cue_sim/physics/motion.hpp"
#include "physics/engine/table_geometry.hpp"
#include "physics/supports/contact_geometry.hpp"

namespace cue_sim
{
namespace physics
{
/// Candidates at the same instant rank as a scan would meet them: transitions first (by ball),
/// then each ball's cushions, jaws, pockets and partners, ball by ball.
template <typename S>
struct Candidate
{
  enum Rank : int
  {
    /// not an event: the piece of a ball in sustained contact ends, and its group takes its next step
    Step = -3,
    Unsolved = -2,  ///< not yet an event: a pair that cannot meet before `time`, solved when that comes up
    Renewal = -1,   ///< not an event: the ball's box has run out and is drawn further
    Transition = 0,
    Segment = 1,
    Circle = 2,
    Pocket = 3,
    Pair = 4,
    Overboard = 5,  ///< a ball in the air passes over a cushion's nose (airborne_walls.hpp)
  };
  S time = infinity<S>();
  Rank rank = Transition;
  int ball = -1;   ///< index of the ball whose scan finds it
  int other = -1;  ///< index of the other ball (Pair), else -1
  int obstacle = -1;

  bool isEvent() const { return rank >= Transition; }
  bool before(const Candidate& c) const
  {
    if (time != c.time)
      return time < c.time;
    // Renewals and unsolved pairs come first, so that what they find is queued before anything
    // at their time; neither is an event, so their order among themselves changes nothing.
    const int group = rank < Transition ? 0 : rank == Transition ? 1 : 2;
    const int c_group = c.rank < Transition ? 0 : c.rank == Transition ? 1 : 2;
    if (group != c_group)
      return group < c_group;
    if (ball != c.ball)
      return ball < c.ball;
    if (rank != c.rank)
      return rank < c.rank;
    return rank == Pair ? other < c.other : obstacle < c.obstacle;
  }
};

/// What the search knows of one ball, computed once per change of the ball: laid out so that a
/// pair test on the cloth reads two cache lines of each ball and nothing else. Every field is set by
/// CandidateFinder::restingPath or computePath before it is read.
template <typename S>
struct alignas(64) BallRecord
{
  /// The box the ball's centre stays in until `window` (at most `first`), widened by R: balls
  /// whose boxes are apart cannot meet before one of the windows ends. A window shorter than
  /// the path keeps the box small on a large table; it is drawn further when it ends.
  Vec2<S> low, high;
  S time;  ///< the ball's reference time
  S window;
  /// The ball's earliest event of its own (transition, cushion, jaw, pocket): the ball
  /// changes then, so nothing of it later than this needs finding yet.
  Candidate<S> first;
  bool in_play, translating, airborne;
  bool supported;  ///< moved by the contact equations: what it touches is its group's to follow
  /// About the ball's own reference time. Last, so that a pair on the cloth reads the first two
  /// cache lines only: the heights, read for a ball in the air, lie in the third.
  Trajectory<S> path;
};

template <typename S>
using BallRecords = std::vector<BallRecord<S>>;

/// Where ball j is seen from ball i: both paths about the later of their reference times (a
/// function of the pair alone), and the horizon of the pair's search from then.
template <typename S>
struct PairMotion
{
  S base;
  Vec2<S> c0, c1, c2;  ///< relative position c0 + c1 tau + c2 tau^2, tau from base
  /// Relative height h0 + h1 tau + h2 tau^2: all zero unless a ball is in the air.
  S h0 = S(0), h1 = S(0), h2 = S(0);
  bool airborne = false;
  bool supported = false;  ///< a ball of the pair is moved by the contact equations
  /// Nothing later than either ball's own next event needs finding: that event changes it.
  S limit;

  static PairMotion of(const BallRecords<S>& records, int i, int j);
};

/// Finds the candidates of balls and pairs on one engine's table.
template <typename S>
class CandidateFinder
{
public:
  explicit CandidateFinder(const Engine<S>& engine)
    : params_(engine.params()),
      geometry_(engine.geometry()),
      margin_(engine.params().ball_radius + S(kBoxMargin)),
      touch_(supportTouch(engine.params()))
  {
  }

  /// A ball at rest: nothing of its own to find, and a box of one ball until it changes.
  void restingPath(const Ball<S>& ball, int index, BallRecord<S>& record) const;
  /// The ball's path, its own next event, and its box from `from` over `travel` of its path.
  void computePath(const Ball<S>& ball, int index, BallRecord<S>& record, S from, S travel) const;
  /// The box the ball's centre stays in from `from` (absolute) while it travels `travel` [m] (all
  /// of its path if infinite), until its next event at the latest.
  void drawBox(const Ball<S>& ball, BallRecord<S>& record, S from, S travel) const;

  /// A pair's contact is found in two steps, so that a pair whose balls change before they
  /// could meet need not be solved: whether they may meet before either's box window ends, and
  /// their relative motion if so (the pair then as an unsolved candidate)...
  bool pairMayMeet(int a, int b, const BallRecords<S>& records, Candidate<S>& pair, PairMotion<S>& motion) const;
  /// ...then the contact itself: false if not before either ball's next event.
  bool solvePair(const PairMotion<S>& motion, Candidate<S>& pair) const;
  /// Both steps at once.
  bool pairCandidate(int a, int b, const BallRecords<S>& records, Candidate<S>& out) const;

  /// The event a candidate stands for, in the state where it was found.
  Event<S> eventOf(const TableState<S>& state, const Candidate<S>& candidate) const;

private:
  /// A ball in the air past the cushions or over a pocket's mouth: the event says where it goes.
  void departing(const Ball<S>& ball, const Candidate<S>& candidate, Event<S>& event) const;
  void computeOwnEvent(const Ball<S>& ball, int index, BallRecord<S>& record) const;

  const PhysicsParams<S>& params_;
  const TableGeometry<S>& geometry_;
  S margin_;  ///< R and a nanometre: the boxes' widening
  S touch_;   ///< surfaces this close touch, for balls in sustained contact (supportTouch)
};

}  // namespace physics
}  // namespace cue_sim

// Finding events: every candidate event of a ball (its transition, a cushion, jaw or pocket)
// or of a pair of balls is a pure function of those balls' own states, so the candidates can
// be kept between events and recomputed only for the balls an event changed (advance), or all
// found afresh (nextEvent), with bit-identical results.
#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "cue_sim/physics/engine.hpp"
#include "cue_sim/physics/motion.hpp"
#include "physics/search/ball_grid.hpp"
#include "physics/search/engine_geometry.hpp"
#include "physics/search/event_queue.hpp"

namespace cue_sim
{
namespace physics
{
using namespace engine_detail;

/// Candidates at the same instant rank as a scan would meet them: transitions first (by ball),
/// then each ball's cushions, jaws, pockets and partners, ball by ball.
template <typename S>
struct Engine<S>::Candidate
{
  enum Rank : int
  {
    Unsolved = -2,  ///< not yet an event: a pair that cannot meet before `time`, solved when that comes up
    Renewal = -1,   ///< not an event: the ball's box has run out and is drawn further
    Transition = 0,
    Segment = 1,
    Circle = 2,
    Pocket = 3,
    Pair = 4,
  };
  S time = infinity<S>();
  Rank rank = Transition;
  int ball = -1;   ///< index of the ball whose scan finds it
  int other = -1;  ///< index of the other ball (Pair), else -1
  int obstacle = -1;

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

/// What the event search knows of each ball: one record per ball, laid out so that a pair test
/// reads two cache lines of each ball and nothing else.
template <typename S>
struct Engine<S>::Paths
{
  /// Every field is set by restingPath or computePath before it is read.
  struct alignas(64) Record
  {
    /// The box the ball's centre stays in until `window` (at most `first`), widened by R: balls
    /// whose boxes are apart cannot meet before one of the windows ends. A window shorter than
    /// the path keeps the box small on a large table; it is drawn further when it ends.
    Vec2<S> low, high;
    Trajectory<S> path;  ///< about the ball's own reference time
    S time;              ///< the ball's reference time
    S window;
    /// The ball's earliest event of its own (transition, cushion, jaw, pocket): the ball
    /// changes then, so nothing of it later than this needs finding yet.
    Candidate first;
    bool in_play, translating;
  };
  std::vector<Record> of;
  explicit Paths(std::size_t n) : of(n) {}
  Record& operator[](std::size_t i) { return of[i]; }
  const Record& operator[](std::size_t i) const { return of[i]; }
};

namespace
{
/// The search horizon from `base` for a motion that ends at `end` (absolute).
template <typename S>
S horizon(S end, S base)
{
  return std::isfinite(static_cast<double>(end)) ? end - base : kEndlessHorizon<S>;
}

/// The path re-expanded about a time `delta` after its own base.
template <typename S>
Trajectory<S> shifted(const Trajectory<S>& path, S delta)
{
  if (delta == S(0))
    return path;
  Trajectory<S> out;
  out.c0 = path.at(delta);
  out.c1 = path.velocityAt(delta);
  out.c2 = path.c2;
  return out;
}
}  // namespace

/// Where ball j is seen from ball i: both paths about the later of their reference times (a
/// function of the pair alone), and the horizon of the pair's search from then.
template <typename S>
struct Engine<S>::PairMotion
{
  S base;
  Vec2<S> c0, c1, c2;  ///< relative position c0 + c1 tau + c2 tau^2, tau from base
  /// Nothing later than either ball's own next event needs finding: that event changes it.
  S limit;
};

template <typename S>
typename Engine<S>::PairMotion Engine<S>::pairMotion(const Paths& paths, int i, int j)
{
  const auto& ri = paths[i];
  const auto& rj = paths[j];
  PairMotion m;
  m.base = std::max(ri.time, rj.time);
  const Trajectory<S> pi = shifted(ri.path, m.base - ri.time);
  const Trajectory<S> pj = shifted(rj.path, m.base - rj.time);
  m.c0 = pi.c0 - pj.c0;
  m.c1 = pi.c1 - pj.c1;
  m.c2 = pi.c2 - pj.c2;
  m.limit = horizon(std::min(ri.first.time, rj.first.time), m.base);
  return m;
}

namespace
{
/// Smallest and largest value of c0 + c1 tau + c2 tau^2 over tau in [T0, T] (T may be +inf).
template <typename S>
void quadraticRange(S c0, S c1, S c2, S T0, S T, S& low, S& high)
{
  low = high = T0 == S(0) ? c0 : c0 + T0 * (c1 + T0 * c2);
  const auto include = [&](S x) {
    low = std::min(low, x);
    high = std::max(high, x);
  };
  if (std::isfinite(static_cast<double>(T)))
    include(c0 + T * (c1 + T * c2));
  else if (c2 != S(0) || c1 != S(0))
    include((c2 > S(0) || (c2 == S(0) && c1 > S(0))) ? infinity<S>() : -infinity<S>());
  if (c2 != S(0))
  {
    const S vertex = -c1 / (S(2) * c2);
    if (vertex > T0 && vertex < T)
      include(c0 + vertex * (c1 + vertex * c2));
  }
}
}  // namespace

template <typename S>
inline void Engine<S>::restingPath(const Ball<S>& ball, std::size_t index, Paths& paths) const
{
  // A ball at rest has nothing of its own to find and a box of one ball: it costs almost
  // nothing until something reaches it.
  auto& record = paths[index];
  record.path.c0 = ball.r.template head<2>();
  record.path.c1.setZero();
  record.path.c2.setZero();
  record.time = ball.time;
  record.first = Candidate();
  record.first.ball = static_cast<int>(index);
  record.window = infinity<S>();
  record.in_play = true;
  record.translating = false;
  const Vec2<S> margin = Vec2<S>::Constant(params_.ball_radius + S(1e-9));
  record.low = record.path.c0 - margin;
  record.high = record.path.c0 + margin;
}

template <typename S>
void Engine<S>::computePath(const Ball<S>& ball, std::size_t index, Paths& paths, S window) const
{
  if (ball.motion == Motion::Stationary)
  {
    restingPath(ball, index, paths);
    return;
  }
  computeOwnEvent(ball, index, paths);
  drawBox(ball, index, paths, ball.time, window);
}

template <typename S>
void Engine<S>::drawBox(const Ball<S>& ball, std::size_t index, Paths& paths, S from, S window) const
{
  auto& record = paths[index];
  // A ball that does not translate stays in its box until it changes: drawn once, never renewed.
  record.window = ball.translating() ? std::min(window, record.first.time) : record.first.time;
  // A nanometre more than R, so that rounding never parts boxes of balls that touch.
  const S margin = params_.ball_radius + S(1e-9);
  const Trajectory<S>& p = record.path;
  const S T = ball.translating() ? record.window - ball.time : S(0);
  const S T0 = ball.translating() ? std::min(from - ball.time, T) : S(0);
  for (int axis = 0; axis < 2; ++axis)
  {
    S low, high;
    quadraticRange(p.c0[axis], p.c1[axis], p.c2[axis], T0, T, low, high);
    record.low[axis] = low - margin;
    record.high[axis] = high + margin;
  }
}

template <typename S>
void Engine<S>::computeOwnEvent(const Ball<S>& ball, std::size_t index, Paths& paths) const
{
  auto& record = paths[index];
  record.path = trajectoryFrom(ball, ball.time, params_);
  record.time = ball.time;
  record.in_play = ball.inPlay();
  record.translating = ball.translating();
  const S end = ball.moving() ? ball.time + timeToTransition(ball, params_) : infinity<S>();
  Candidate& first = record.first;
  first = Candidate();
  first.ball = static_cast<int>(index);
  if (!ball.inPlay())
    return;
  first.time = end;  // the transition, or never
  if (!ball.translating())
    return;
  // Each contact is searched only up to the earliest found so far: the horizon shrinks, and
  // cushions, jaws and pockets out of reach are dismissed by a bound, not solved.
  const S R = params_.ball_radius;
  const S base = ball.time;
  const Trajectory<S>& p = record.path;
  // The box the centre sweeps until the earliest contact found so far: an obstacle whose own
  // box it misses is out of reach.
  Vec2<S> low, high;
  const auto sweep = [&] {
    const S T = first.time - base;
    for (int axis = 0; axis < 2; ++axis)
      quadraticRange(p.c0[axis], p.c1[axis], p.c2[axis], S(0), T, low[axis], high[axis]);
  };
  const auto outOfReach = [&](const auto& obstacle) {
    return (low.array() > obstacle.high.array()).any() || (obstacle.low.array() > high.array()).any();
  };
  sweep();
  const auto keep = [&](S tau, typename Candidate::Rank rank, std::size_t k) {
    Candidate c;
    c.time = base + tau;
    c.rank = rank;
    c.ball = static_cast<int>(index);
    c.obstacle = static_cast<int>(k);
    if (c.before(first))
    {
      first = c;
      sweep();
    }
  };
  for (std::size_t k = 0; k < obstacles_->segments.size(); ++k)
  {
    const auto& seg = obstacles_->segments[k];
    if (outOfReach(seg))
      continue;
    const S limit = horizon(first.time, base);
    const Poly4<S> gap = {seg.normal.dot(p.c0 - seg.start) - R, seg.normal.dot(p.c1), seg.normal.dot(p.c2), S(0), S(0)};
    // Only a ball beside the segment can be touching it now. One beyond its ends may be within R
    // of its line (in a pocket's mouth); it meets the segment only by crossing that line again
    // beside it.
    const S along_now = seg.direction.dot(p.c0 - seg.start);
    const bool beside = along_now >= S(0) && along_now <= seg.length;
    const S tau = beside ? contactTime(gap, limit, -zeroSpeed<S>(), touchTolerance(R), true)
                         : firstDownCrossing(gap, S(0), limit);
    if (tau <= limit)
    {
      const S along = seg.direction.dot(p.at(tau) - seg.start);
      if (along >= S(0) && along <= seg.length)
        keep(tau, Candidate::Segment, k);
    }
  }
  // A jaw or cushion end (a contact when pressed into it, as for a straight cushion) and a
  // pocket (the centre crossing the capture circle) are both circles around a centre.
  const auto circleContact = [&](const auto& obstacle, S reach, S approach_slope, bool pressing,
                                 typename Candidate::Rank rank, std::size_t k) {
    if (outOfReach(obstacle))
      return;
    const S limit = horizon(first.time, base);
    if (cannotMeet<S>(p.c0 - obstacle.centre, p.c1, p.c2, reach, limit))
      return;
    const S tau = contactTime(distanceGap<S>(p.c0 - obstacle.centre, p.c1, p.c2, reach), limit, approach_slope,
                              touchTolerance(reach * reach), pressing);
    if (tau <= limit)
      keep(tau, rank, k);
  };
  for (std::size_t k = 0; k < obstacles_->circles.size(); ++k)
  {
    const S reach = R + obstacles_->circles[k].radius;
    circleContact(obstacles_->circles[k], reach, -S(2) * reach * zeroSpeed<S>(), true, Candidate::Circle, k);
  }
  for (std::size_t k = 0; k < obstacles_->pockets.size(); ++k)
    circleContact(obstacles_->pockets[k], obstacles_->pockets[k].radius, S(0), false, Candidate::Pocket, k);
}

template <typename S>
bool Engine<S>::pairMayMeet(int a, int b, const Paths& paths, Candidate& pair, PairMotion& motion) const
{
  const auto& ra = paths[a];
  const auto& rb = paths[b];
  if (!ra.in_play || !rb.in_play || (!ra.translating && !rb.translating) || (ra.low.array() > rb.high.array()).any() ||
      (rb.low.array() > ra.high.array()).any())
    return false;
  // The pair belongs to the scan of its translating ball, the lower index if both translate.
  int i = a, j = b;
  if (!ra.translating || (rb.translating && b < a))
    std::swap(i, j);
  motion = pairMotion(paths, i, j);
  // Dismissed if they cannot meet before a window ends (a contact after that is looked for
  // again when the window is drawn further).
  if (cannotMeet<S>(motion.c0, motion.c1, motion.c2, S(2) * params_.ball_radius,
                    horizon(std::min(paths[i].window, paths[j].window), motion.base)))
    return false;
  pair.rank = Candidate::Unsolved;
  pair.ball = i;
  pair.other = j;
  pair.obstacle = -1;
  return true;
}

template <typename S>
bool Engine<S>::solvePair(const PairMotion& motion, Candidate& pair) const
{
  // Solved over the whole horizon, so the result never depends on the windows.
  const S R = params_.ball_radius;
  const S tau = contactTime(distanceGap<S>(motion.c0, motion.c1, motion.c2, S(2) * R), motion.limit,
                            -S(4) * R * zeroSpeed<S>(), touchTolerance(S(4) * R * R), true);
  if (!(tau <= motion.limit))
    return false;
  pair.time = motion.base + tau;
  pair.rank = Candidate::Pair;
  return true;
}

template <typename S>
bool Engine<S>::pairCandidate(int a, int b, const Paths& paths, Candidate& out) const
{
  PairMotion motion;
  return pairMayMeet(a, b, paths, out, motion) && solvePair(motion, out);
}

template <typename S>
Event<S> Engine<S>::eventOf(const TableState<S>& state, const Candidate& c) const
{
  Event<S> e;
  e.time = c.time;
  e.ball = state.balls[c.ball].id;
  switch (c.rank)
  {
    case Candidate::Unsolved:
    case Candidate::Renewal:
      break;
    case Candidate::Transition: {
      // Which transition it is follows from applying it to a copy.
      Ball<S> copy = evolve(state.balls[c.ball], c.time, params_);
      e.kind = applyTransition(copy, params_);
      break;
    }
    case Candidate::Segment:
      e.kind = EventKind::BallCushion;
      e.obstacle = c.obstacle;
      break;
    case Candidate::Circle:
      e.kind = EventKind::BallCircle;
      e.obstacle = c.obstacle;
      break;
    case Candidate::Pocket:
      e.kind = EventKind::Pocketed;
      e.obstacle = c.obstacle;
      break;
    case Candidate::Pair:
      e.kind = EventKind::BallBall;
      e.other = state.balls[c.other].id;
      break;
  }
  return e;
}

template <typename S>
Event<S> Engine<S>::nextEvent(const TableState<S>& state) const
{
  const std::size_t n = state.balls.size();
  Paths paths(n);
  for (std::size_t i = 0; i < n; ++i)
    computePath(state.balls[i], i, paths, infinity<S>());
  Candidate best;
  bool found = false;
  const auto keep = [&](const Candidate& c) {
    if (!found || c.before(best))
    {
      best = c;
      found = true;
    }
  };
  for (std::size_t i = 0; i < n; ++i)
    if (std::isfinite(static_cast<double>(paths[i].first.time)))
      keep(paths[i].first);
  Candidate pair;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if (pairCandidate(static_cast<int>(i), static_cast<int>(j), paths, pair))
        keep(pair);
  return found ? eventOf(state, best) : Event<S>();
}

template <typename S>
void Engine<S>::advance(TableState<S>& state, S t_end, std::vector<Event<S>>* events) const
{
  const std::size_t n = state.balls.size();
  Paths paths(n);
  EventQueue<Candidate> queue(n);
  const Vec2<S> centre = table_->clothCentre().template cast<S>();
  const Vec2<S> half(S(table_->clothLength() / 2), S(table_->clothWidth() / 2));
  // A few balls are simply all looked at; beyond that a grid keeps each look local.
  std::optional<BallGrid<S>> grid;
  if (n > kGridFrom)
    grid.emplace(centre - half, centre + half, n, params_.ball_radius);
  const auto list = [&](std::size_t i) {
    if (!grid)
      return;
    if (state.balls[i].inPlay())
      grid->place(static_cast<int>(i), paths[i].low, paths[i].high);
    else
      grid->remove(static_cast<int>(i));
  };
  /// Calls visit(o) for every other ball whose box meets ball k's (through the grid, may meet it):
  /// the balls it may meet.
  const auto visitNear = [&](int k, const auto& visit) {
    if (grid)
    {
      for (int o : grid->near(k, paths[k].low, paths[k].high))
        visit(o);
      return;
    }
    const S x0 = paths[k].low.x(), y0 = paths[k].low.y(), x1 = paths[k].high.x(), y1 = paths[k].high.y();
    for (int o = 0; o < static_cast<int>(n); ++o)
    {
      const Vec2<S>& low = paths[o].low;
      const Vec2<S>& high = paths[o].high;
      if (o != k && !(low.x() > x1 || x0 > high.x() || low.y() > y1 || y0 > high.y()))  // NaN never culls
        visit(o);
    }
  };
  // A ball's box covers about two cells of its travel; then it is drawn further.
  const auto windowFrom = [&](std::size_t i, S from) {
    return grid ? from + S(2) * grid->cell() / (state.balls[i].v.norm() + S(0.1)) : infinity<S>();
  };
  for (std::size_t i = 0; i < n; ++i)
  {
    const Ball<S>& b = state.balls[i];
    if (b.motion == Motion::Stationary)
      restingPath(b, i, paths);  // the common case of a rack, kept out of a call
    else
      computePath(b, i, paths, windowFrom(i, std::max(b.time, state.event_time)));
    if (grid)
      list(i);
  }
  /// Queues the ball's box renewal, if its window ends before its own next event.
  const auto fileRenewal = [&](std::size_t i) {
    if (state.balls[i].translating() && paths[i].window < paths[i].first.time)
    {
      Candidate renewal;
      renewal.time = paths[i].window;
      renewal.rank = Candidate::Renewal;
      renewal.ball = static_cast<int>(i);
      queue.file(static_cast<int>(i), renewal);
    }
  };
  const auto fileOwn = [&](std::size_t i) {
    if (std::isfinite(static_cast<double>(paths[i].first.time)))
      queue.file(static_cast<int>(i), paths[i].first);
    fileRenewal(i);
  };
  /// Files the pairs ball k may meet, among the balls near it that `skip` leaves (the pairs
  /// already filed from the other ball). A pair is left unsolved, at a time before which they
  /// cannot meet, if that is later than a contact of k's found earlier in this look (`soonest`):
  /// that contact will most likely change k first, and the pair is then never solved. Else it is
  /// solved now, since a pair left unsolved that does come up costs a round of the queue, more
  /// than most solves.
  const auto filePairsOf = [&](int k, const auto& skip) {
    S soonest = infinity<S>();
    Candidate pair;
    PairMotion motion;
    visitNear(k, [&](int o) {
      if (skip(o) || !pairMayMeet(k, o, paths, pair, motion))
        return;
      if (soonest < infinity<S>())
      {
        const S tau = earliestMeeting<S>(motion.c0, motion.c1, motion.c2, S(2) * params_.ball_radius);
        if (tau > motion.limit)
          return;  // they cannot meet before either ball's next event
        pair.time = motion.base + tau;
        if (pair.time > soonest)
        {
          queue.file(k, pair);
          return;
        }
      }
      if (solvePair(motion, pair))
      {
        queue.file(k, pair);
        soonest = std::min(soonest, pair.time);
      }
    });
  };
  for (std::size_t i = 0; i < n; ++i)
    if (state.balls[i].moving())
      fileOwn(i);
  // Pairs need a translating ball: each is found from it (from the lower index if both are).
  for (std::size_t i = 0; i < n; ++i)
    if (state.balls[i].translating())
      filePairsOf(static_cast<int>(i), [&](int o) { return state.balls[o].translating() && o < static_cast<int>(i); });

  // During an event, the balls near a point are those whose boxes reach it: looked for in the
  // cells around it if there is a grid, else among all balls, by comparisons alone.
  class PathNeighbours : public Neighbours
  {
  public:
    PathNeighbours(const BallGrid<S>* grid, const TableState<S>& state, const Paths& paths)
      : grid_(grid), state_(state), paths_(paths)
    {
    }
    void near(const Vec2<S>& point, S distance, std::vector<int>& out) const override
    {
      out.clear();
      const Vec2<S> reach = Vec2<S>::Constant(distance + S(1e-9));
      const Vec2<S> low = point - reach, high = point + reach;
      if (grid_)
      {
        for (int o : grid_->inBox(low, high))
          if (state_.balls[o].inPlay())
            out.push_back(o);
        std::sort(out.begin(), out.end());
        return;
      }
      for (int o = 0; o < static_cast<int>(state_.balls.size()); ++o)
        if (state_.balls[o].inPlay() && !(paths_[o].low.array() > high.array()).any() &&
            !(low.array() > paths_[o].high.array()).any())
          out.push_back(o);
    }

  private:
    const BallGrid<S>* grid_;
    const TableState<S>& state_;
    const Paths& paths_;
  };
  const PathNeighbours neighbours(grid ? &*grid : nullptr, state, paths);
  std::vector<int> scratch;

  std::vector<int> changed;
  std::vector<char> is_changed(n, 0);
  long processed = 0;
  for (;;)
  {
    const Candidate* top = queue.top();
    if (!top || top->time > t_end)
      break;
    const Candidate next = *top;
    queue.pop();
    if (next.rank == Candidate::Unsolved)
    {
      // Neither ball has changed since the pair was found, so solving it now gives what solving
      // it then would have: it is filed at its contact, if they meet before either's next event.
      Candidate solved = next;
      if (solvePair(pairMotion(paths, next.ball, next.other), solved))
        queue.file(solved.ball, solved);
      continue;
    }
    if (next.rank == Candidate::Renewal)
    {
      // Not an event: the ball's box is drawn over its next stretch, and the balls it now
      // reaches are looked at.
      const int k = next.ball;
      // Only what is still ahead: the new box starts where the old window ends (nothing is
      // tested against a time before it any more).
      drawBox(state.balls[k], k, paths, paths[k].window, windowFrom(k, paths[k].window));
      list(k);
      fileRenewal(k);
      filePairsOf(k, [](int) { return false; });
      continue;
    }
    const Event<S> event = eventOf(state, next);
    if (++processed > limits_.max_events)
    {
      std::ostringstream why;
      why << "event limit reached: more than " << limits_.max_events
          << " events before t = " << static_cast<double>(event.time) << " s (EngineLimits::max_events)";
      throw EventLimitError(why.str());
    }
    changed.clear();
    EventContext context;
    context.index = next.ball;
    context.other_index = next.other;
    context.changed = &changed;
    context.neighbours = &neighbours;
    context.scratch = &scratch;
    processEvent(state, event, context);
    if (events)
    {
      Event<S> record = event;
      record.speed = state.balls[next.ball].v.norm();
      if (next.other >= 0)
        record.other_speed = state.balls[next.other].v.norm();
      events->push_back(record);
    }
    // Only the balls the event changed get new candidates; every other candidate stands.
    std::sort(changed.begin(), changed.end());
    changed.erase(std::unique(changed.begin(), changed.end()), changed.end());
    for (int k : changed)
    {
      queue.changed(k);
      is_changed[k] = 1;
      computePath(state.balls[k], k, paths, windowFrom(k, event.time));
      list(k);
    }
    for (int k : changed)
    {
      fileOwn(k);
      if (state.balls[k].inPlay())
        filePairsOf(k, [&](int o) { return is_changed[o] && o < k; });
    }
    for (int k : changed)
      is_changed[k] = 0;
  }
  state.time = std::max(state.time, t_end);
}

template Event<double> Engine<double>::nextEvent(const TableState<double>&) const;
template Event<long double> Engine<long double>::nextEvent(const TableState<long double>&) const;
template void Engine<double>::advance(TableState<double>&, double, std::vector<Event<double>>*) const;
template void Engine<long double>::advance(TableState<long double>&, long double,
                                           std::vector<Event<long double>>*) const;

}  // namespace physics
}  // namespace cue_sim

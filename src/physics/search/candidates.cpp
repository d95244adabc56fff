#include "physics/search/candidates.hpp"

#include <algorithm>
#include <cmath>

#include "physics/engine/table_departure.hpp"
#include "physics/search/airborne_walls.hpp"
#include "physics/search/contact_times.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
/// The search horizon from `base` for a motion that ends at `end` (absolute).
template <typename S>
S horizon(S end, S base)
{
  return std::isfinite(static_cast<double>(end)) ? end - base : kEndlessHorizon<S>;
}

/// The path's position and velocity terms re-expanded about a time `delta` after its own base
/// (its acceleration term is the same about any time).
template <typename S>
void shifted(const Trajectory<S>& path, S delta, Vec2<S>& c0, Vec2<S>& c1)
{
  if (delta == S(0))
  {
    c0 = path.c0;
    c1 = path.c1;
    return;
  }
  c0 = path.at(delta);
  c1 = path.velocityAt(delta);
}

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

/// A ball that comes beside a cushion no deeper than this behind its line [m] is at the cushion's
/// end, touching it: it started there, a hair off, or drifted in within rounding. One deeper is
/// elsewhere (beyond the end of a cushion whose line crosses the table, or past a jaw, whose
/// circle it meets first); taken for a contact, it would be struck by a wall it never reached.
constexpr double kEnteringDepth = 1e-9;

/// The search for one translating ball's own next event: each contact is searched only up to
/// the earliest found so far, so the horizon shrinks, and cushions, jaws and pockets out of
/// reach are dismissed by a box, not solved.
template <typename S>
class OwnEventSearch
{
public:
  /// `touching`: the walls a ball in sustained contact touches, its group's to follow (or null).
  OwnEventSearch(const Trajectory<S>& path, S base, Candidate<S>& first, const std::vector<WallTouch>* touching)
    : path_(path), base_(base), first_(first), touching_(touching)
  {
    sweep();
  }

  void segment(const typename TableGeometry<S>::Segment& seg, std::size_t k, S R)
  {
    if (outOfReach(seg) || touches(k, false))
      return;
    const S limit = horizon(first_.time, base_);
    const Trajectory<S>& p = path_;
    const Poly4<S> gap = {seg.normal.dot(p.c0 - seg.start) - R, seg.normal.dot(p.c1), seg.normal.dot(p.c2), S(0), S(0)};
    // Only a ball beside the segment can be touching it now. One beyond its ends may be within R
    // of its line (in a pocket's mouth); it meets the segment by crossing that line beside it,
    // or by coming beside it while within R of the line.
    const S along_now = seg.direction.dot(p.c0 - seg.start);
    const S touch = touchTolerance(R);
    if (along_now >= S(0) && along_now <= seg.length)
    {
      const S tau = contactTime(gap, limit, -zeroSpeed<S>(), touch, true);
      if (tau <= limit && isBeside(seg, tau))
        keep(tau, Candidate<S>::Segment, k);
      return;
    }
    const S crossing = firstDownCrossing(gap, S(0), limit);
    if (crossing <= limit && isBeside(seg, crossing))
    {
      keep(crossing, Candidate<S>::Segment, k);
      return;
    }
    if (gap[0] <= touch || crossing <= limit)
      enteringWithinReach(seg, gap, limit, touch, k);
  }

  /// A jaw or cushion end (a contact when pressed into it, as for a straight cushion) or a
  /// pocket (the centre crossing the capture circle): both circles around a centre.
  void circle(const typename TableGeometry<S>::Circle& obstacle, S reach, S approach_slope, bool pressing,
              typename Candidate<S>::Rank rank, std::size_t k)
  {
    if (outOfReach(obstacle) || (rank == Candidate<S>::Circle && touches(k, true)))
      return;
    const S limit = horizon(first_.time, base_);
    const Trajectory<S>& p = path_;
    if (cannotMeet<S>(p.c0 - obstacle.centre, p.c1, p.c2, reach, limit))
      return;
    const S tau = contactTime(distanceGap<S>(p.c0 - obstacle.centre, p.c1, p.c2, reach), limit, approach_slope,
                              touchTolerance(reach * reach), pressing);
    if (tau <= limit)
      keep(tau, rank, k);
  }

private:
  /// Whether the ball touches this cushion (or post), which its group follows.
  bool touches(std::size_t k, bool post) const
  {
    if (!touching_)
      return false;
    return std::any_of(touching_->begin(), touching_->end(), [&](const WallTouch& w) {
      const bool is_post = w.surface == Surface::PostSide || w.surface == Surface::Rim;
      return is_post == post && w.index == static_cast<int>(k);
    });
  }

  /// Whether the centre is beside the segment at tau (within `slack` of its ends).
  bool isBeside(const typename TableGeometry<S>::Segment& seg, S tau, S slack = S(0)) const
  {
    const S along = seg.direction.dot(path_.at(tau) - seg.start);
    return along >= -slack && along <= seg.length + slack;
  }

  /// A ball beyond an end of the segment and within R of its line (it touched the segment's end,
  /// or crossed the line in the pocket's mouth) that comes beside the segment is in contact with
  /// it from that moment if it then closes on it or is pressed into it: a ball frozen to a
  /// cushion's very end and drifting back along it meets the cushion as it comes beside, not when
  /// its path next changes, already deep.
  void enteringWithinReach(const typename TableGeometry<S>::Segment& seg, const Poly4<S>& gap, S limit, S touch,
                           std::size_t k)
  {
    const Trajectory<S>& p = path_;
    const S a0 = seg.direction.dot(p.c0 - seg.start), a1 = seg.direction.dot(p.c1), a2 = seg.direction.dot(p.c2);
    // The first moment along(tau) passes into [0, length]: from below through 0, or from above
    // through the length.
    const Poly4<S> outside =
        a0 < S(0) ? Poly4<S>{-a0, -a1, -a2, S(0), S(0)} : Poly4<S>{a0 - seg.length, a1, a2, S(0), S(0)};
    const S enter = firstDownCrossing(outside, S(0), limit);
    // At that moment the ball is at the end within the rounding of positions on the table.
    if (!(enter <= limit) || !isBeside(seg, enter, touchTolerance(p.c0.norm() + seg.start.norm() + seg.length)))
      return;
    const Poly4<S> from_enter = {gap[0] + enter * (gap[1] + enter * gap[2]), gap[1] + S(2) * enter * gap[2], gap[2],
                                 S(0), S(0)};
    if (from_enter[0] > touch)
      return;  // clear of the line as it comes beside: a crossing beside it is found from there
    if (from_enter[0] < -S(kEnteringDepth))
      return;  // far behind the line: elsewhere on the table, where other walls come first
    const S tau = contactTime(from_enter, limit - enter, -zeroSpeed<S>(), touch, true);
    if (tau == S(0))
      keep(enter, Candidate<S>::Segment, k);
    else if (tau <= limit - enter && isBeside(seg, enter + tau))
      keep(enter + tau, Candidate<S>::Segment, k);
  }

  /// The box the centre sweeps until the earliest contact found so far.
  void sweep()
  {
    const S T = first_.time - base_;
    for (int axis = 0; axis < 2; ++axis)
      quadraticRange(path_.c0[axis], path_.c1[axis], path_.c2[axis], S(0), T, low_[axis], high_[axis]);
  }
  /// An obstacle whose own box the swept box misses is out of reach.
  template <typename Obstacle>
  bool outOfReach(const Obstacle& obstacle) const
  {
    return (low_.array() > obstacle.high.array()).any() || (obstacle.low.array() > high_.array()).any();
  }
  void keep(S tau, typename Candidate<S>::Rank rank, std::size_t k)
  {
    Candidate<S> c;
    c.time = base_ + tau;
    c.rank = rank;
    c.ball = first_.ball;
    c.obstacle = static_cast<int>(k);
    if (c.before(first_))
    {
      first_ = c;
      sweep();
    }
  }

  const Trajectory<S>& path_;
  const S base_;
  Candidate<S>& first_;
  const std::vector<WallTouch>* touching_;
  Vec2<S> low_, high_;
};
}  // namespace

template <typename S>
PairMotion<S> PairMotion<S>::of(const BallRecords<S>& records, int i, int j)
{
  const auto& ri = records[i];
  const auto& rj = records[j];
  PairMotion m;
  m.base = std::max(ri.time, rj.time);
  const S di = m.base - ri.time, dj = m.base - rj.time;
  Vec2<S> c0i, c1i, c0j, c1j;
  shifted(ri.path, di, c0i, c1i);
  shifted(rj.path, dj, c0j, c1j);
  m.c0 = c0i - c0j;
  m.c1 = c1i - c1j;
  m.c2 = ri.path.c2 - rj.path.c2;
  m.airborne = ri.airborne || rj.airborne;
  m.supported = ri.supported || rj.supported;
  if (m.airborne)  // on the cloth every height term is zero
  {
    const Trajectory<S>&pi = ri.path, &pj = rj.path;
    m.h0 = pi.heightAt(di) - pj.heightAt(dj);
    m.h1 = (pi.h1 + S(2) * di * pi.h2) - (pj.h1 + S(2) * dj * pj.h2);
    m.h2 = pi.h2 - pj.h2;
  }
  m.limit = horizon(std::min(ri.first.time, rj.first.time), m.base);
  return m;
}

template <typename S>
void CandidateFinder<S>::restingPath(const Ball<S>& ball, int index, BallRecord<S>& record) const
{
  // A ball at rest costs almost nothing until something reaches it.
  record.path.c0 = ball.r.template head<2>();
  record.path.c1.setZero();
  record.path.c2.setZero();
  // On the cloth: no height terms (a record kept from the ball's last flight must not lend it one).
  record.path.h0 = record.path.h1 = record.path.h2 = S(0);
  record.time = ball.time;
  record.first = Candidate<S>();
  record.first.ball = index;
  record.window = infinity<S>();
  record.in_play = true;
  record.translating = false;
  record.airborne = false;
  record.supported = false;
  record.low = record.path.c0 - Vec2<S>::Constant(margin_);
  record.high = record.path.c0 + Vec2<S>::Constant(margin_);
}

template <typename S>
void CandidateFinder<S>::computePath(const Ball<S>& ball, int index, BallRecord<S>& record, S from, S travel) const
{
  if (ball.motion == Motion::Stationary)
  {
    restingPath(ball, index, record);
    return;
  }
  computeOwnEvent(ball, index, record);
  drawBox(ball, record, from, travel);
}

namespace
{
/// How long a ball on `path` takes from tau to travel `distance` at most: its speed there and
/// its acceleration bound the distance by |v| T + |a| T^2 / 2 (+inf if it neither moves nor
/// speeds up).
template <typename S>
S timeToTravel(const Trajectory<S>& path, S tau, S distance)
{
  const S speed = path.velocityAt(tau).norm(), acceleration = S(2) * path.c2.norm();
  const S denominator = speed + std::sqrt(speed * speed + S(2) * acceleration * distance);
  return denominator > S(0) ? S(2) * distance / denominator : infinity<S>();
}
}  // namespace

template <typename S>
void CandidateFinder<S>::drawBox(const Ball<S>& ball, BallRecord<S>& record, S from, S travel) const
{
  // A ball that does not translate stays in its box until it changes: drawn once, never renewed.
  const S window = std::isfinite(static_cast<double>(travel))
                       ? from + timeToTravel(record.path, from - ball.time, travel)
                       : infinity<S>();
  record.window = ball.translating() ? std::min(window, record.first.time) : record.first.time;
  const Trajectory<S>& p = record.path;
  const S T = ball.translating() ? record.window - ball.time : S(0);
  const S T0 = ball.translating() ? std::min(from - ball.time, T) : S(0);
  for (int axis = 0; axis < 2; ++axis)
  {
    S low, high;
    quadraticRange(p.c0[axis], p.c1[axis], p.c2[axis], T0, T, low, high);
    record.low[axis] = low - margin_;
    record.high[axis] = high + margin_;
  }
}

template <typename S>
void CandidateFinder<S>::computeOwnEvent(const Ball<S>& ball, int index, BallRecord<S>& record) const
{
  record.path = trajectoryFrom(ball, ball.time, params_);
  record.time = ball.time;
  record.in_play = ball.inPlay();
  record.translating = ball.translating();
  record.airborne = ball.airborne();
  record.supported = ball.supported();
  Candidate<S>& first = record.first;
  first = Candidate<S>();
  first.ball = index;
  if (!ball.inPlay())
    return;
  first.time = ball.moving() ? ball.time + timeToTransition(ball, params_) : infinity<S>();  // or never
  if (ball.supported())
    first.rank = Candidate<S>::Step;  // its piece's end: its group's next step
  if (!ball.translating())
    return;
  const S R = params_.ball_radius;
  // The walls a ball in sustained contact touches are its group's to follow (src/physics/supports/).
  std::vector<WallTouch> touching;
  if (ball.supported())
    wallsTouching(geometry_, ball.r, R, touch_, touching);
  if (ball.airborne())
  {
    findAirborneWallEvents(record.path, ball.time, geometry_, R, first, ball.supported() ? &touching : nullptr);
    return;
  }
  OwnEventSearch<S> search(record.path, ball.time, first, ball.supported() ? &touching : nullptr);
  for (std::size_t k = 0; k < geometry_.segments.size(); ++k)
    search.segment(geometry_.segments[k], k, R);
  for (std::size_t k = 0; k < geometry_.circles.size(); ++k)
  {
    const S reach = R + geometry_.circles[k].radius;
    search.circle(geometry_.circles[k], reach, -S(2) * reach * zeroSpeed<S>(), true, Candidate<S>::Circle, k);
  }
  for (std::size_t k = 0; k < geometry_.pockets.size(); ++k)
    search.circle(geometry_.pockets[k], geometry_.pockets[k].radius, S(0), false, Candidate<S>::Pocket, k);
}

template <typename S>
bool CandidateFinder<S>::pairMayMeet(int a, int b, const BallRecords<S>& records, Candidate<S>& pair,
                                     PairMotion<S>& motion) const
{
  const auto& ra = records[a];
  const auto& rb = records[b];
  if (!ra.in_play || !rb.in_play || (!ra.translating && !rb.translating) || (ra.low.array() > rb.high.array()).any() ||
      (rb.low.array() > ra.high.array()).any())
    return false;
  // The pair belongs to the scan of its translating ball, the lower index if both translate.
  int i = a, j = b;
  if (!ra.translating || (rb.translating && b < a))
    std::swap(i, j);
  motion = PairMotion<S>::of(records, i, j);
  // Touching a ball in sustained contact, a ball is its group's to follow (src/physics/supports/).
  if (motion.supported)
  {
    const S reach = S(2) * params_.ball_radius + touch_;
    if (motion.c0.squaredNorm() + motion.h0 * motion.h0 <= reach * reach)
      return false;
  }
  // Dismissed if they cannot meet before a window ends (a contact after that is looked for
  // again when the window is drawn further).
  if (cannotMeet<S>(motion.c0, motion.c1, motion.c2, S(2) * params_.ball_radius,
                    horizon(std::min(records[i].window, records[j].window), motion.base)))
    return false;
  pair.rank = Candidate<S>::Unsolved;
  pair.ball = i;
  pair.other = j;
  pair.obstacle = -1;
  return true;
}

template <typename S>
bool CandidateFinder<S>::solvePair(const PairMotion<S>& motion, Candidate<S>& pair) const
{
  // Solved over the whole horizon, so the result never depends on the windows.
  const S R = params_.ball_radius;
  const Poly4<S> gap = motion.airborne
                           ? distanceGap<S>(motion.c0, motion.c1, motion.c2, motion.h0, motion.h1, motion.h2, S(2) * R)
                           : distanceGap<S>(motion.c0, motion.c1, motion.c2, S(2) * R);
  const S tau = contactTime(gap, motion.limit, -S(4) * R * zeroSpeed<S>(), touchTolerance(S(4) * R * R), true);
  if (!(tau <= motion.limit))
    return false;
  pair.time = motion.base + tau;
  pair.rank = Candidate<S>::Pair;
  return true;
}

template <typename S>
bool CandidateFinder<S>::pairCandidate(int a, int b, const BallRecords<S>& records, Candidate<S>& out) const
{
  PairMotion<S> motion;
  return pairMayMeet(a, b, records, out, motion) && solvePair(motion, out);
}

template <typename S>
void CandidateFinder<S>::departing(const Ball<S>& ball, const Candidate<S>& c, Event<S>& e) const
{
  const Ball<S> then = evolve(ball, c.time, params_);
  if (c.rank == Candidate<S>::Pocket && !fliesOverPocket(then, geometry_, params_.ball_radius))
    return;
  if (c.rank == Candidate<S>::Circle && !onPostTop(then, geometry_.circles[c.obstacle], geometry_))
    return;
  const Departure<S> d = departureOf(then, geometry_, params_);
  e.kind = d.kind;
  e.obstacle = d.obstacle;
}

template <typename S>
Event<S> CandidateFinder<S>::eventOf(const TableState<S>& state, const Candidate<S>& c) const
{
  Event<S> e;
  e.time = c.time;
  e.ball = state.balls[c.ball].id;
  switch (c.rank)
  {
    case Candidate<S>::Step:
    case Candidate<S>::Unsolved:
    case Candidate<S>::Renewal:
      break;
    case Candidate<S>::Transition: {
      // Which transition it is follows from applying it to a copy.
      Ball<S> copy = evolve(state.balls[c.ball], c.time, params_);
      e.kind = applyTransition(copy, params_);
      break;
    }
    case Candidate<S>::Segment:
      e.kind = EventKind::BallCushion;
      e.obstacle = c.obstacle;
      break;
    case Candidate<S>::Circle:
      e.kind = EventKind::BallCircle;
      e.obstacle = c.obstacle;
      departing(state.balls[c.ball], c, e);
      break;
    case Candidate<S>::Pocket:
      e.kind = EventKind::Pocketed;
      e.obstacle = c.obstacle;
      departing(state.balls[c.ball], c, e);
      break;
    case Candidate<S>::Overboard:
      departing(state.balls[c.ball], c, e);
      break;
    case Candidate<S>::Pair:
      e.kind = EventKind::BallBall;
      e.other = state.balls[c.other].id;
      break;
  }
  return e;
}

template struct PairMotion<double>;
template struct PairMotion<long double>;
template class CandidateFinder<double>;
template class CandidateFinder<long double>;

}  // namespace physics
}  // namespace cue_sim

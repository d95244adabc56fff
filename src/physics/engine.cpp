#include "cue_sim/physics/engine.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>

#include "cue_sim/physics/motion.hpp"
#include "cue_sim/physics/polynomial.hpp"

namespace cue_sim
{
namespace physics
{
const char* eventKindName(EventKind kind)
{
  switch (kind)
  {
    case EventKind::None:
      return "none";
    case EventKind::SlideToRoll:
      return "slide_to_roll";
    case EventKind::RollToSpin:
      return "roll_to_spin";
    case EventKind::RollToStop:
      return "roll_to_stop";
    case EventKind::SpinToStop:
      return "spin_to_stop";
    case EventKind::SlideToSpin:
      return "slide_to_spin";
    case EventKind::SlideToStop:
      return "slide_to_stop";
    case EventKind::BallBall:
      return "ball_ball";
    case EventKind::BallCushion:
      return "ball_cushion";
    case EventKind::BallCircle:
      return "ball_circle";
    case EventKind::Pocketed:
      return "pocketed";
  }
  return "unknown";
}

/// The table's geometry converted once to the engine's scalar type.
template <typename S>
struct Engine<S>::Obstacles
{
  struct Segment
  {
    Vec2<S> start, direction, normal;
    S length;
  };
  struct Circle
  {
    Vec2<S> centre;
    S radius;
  };
  std::vector<Segment> segments;
  std::vector<Circle> circles;  // jaws and cushion end caps
  std::vector<Circle> pockets;
};

namespace
{
/// Horizon for balls whose motion never ends (no friction): far beyond any shot, and fixed,
/// so that predictions never depend on how far a caller asks to advance.
template <typename S>
constexpr S kEndlessHorizon = S(1e7);

/// Time from the base at which a gap function (positive while apart) closes with the bodies
/// approaching, within (0, limit]; 0 if they touch and approach now; +inf if never.
/// `approach_slope` is the gap's rate of change that counts as approaching; `touch` is the gap
/// within which two bodies count as touching (the rounding of the gap's constant term).
///
/// Bodies that touch and separate slowly may be pushed back together by their accelerations
/// (two slow balls rolling in slightly different directions) before the computed gap ever
/// becomes positive. For them the contact is when the gap returns to its starting value: the
/// down-crossing of (gap(tau) - gap(0)) / tau, which has no cancellation.
///
/// With `pressing_is_contact`, touching bodies that do not separate while their accelerations
/// press them together are in contact now: ball pairs, which the engine then joins, and a ball
/// on a wall, which it holds there.
template <typename S>
S contactTime(const Poly4<S>& gap, S limit, S approach_slope, S touch, bool pressing_is_contact = false)
{
  if (gap[0] > touch)
    return firstDownCrossing(gap, S(0), limit);
  if (gap[1] < approach_slope || (pressing_is_contact && gap[1] <= S(0) && gap[2] < S(0)))
    return S(0);
  const Poly4<S> relative = {gap[1], gap[2], gap[3], gap[4], S(0)};
  return firstDownCrossing(relative, S(0), limit);
}

/// Gap values within this of zero are rounding: 64 ulps of the gap's scale, the contact
/// distance for a gap in metres, its square for a squared distance.
template <typename S>
S touchTolerance(S scale)
{
  return S(64) * std::numeric_limits<S>::epsilon() * scale;
}

/// A speed [m/s] a few ulps above the rounding of speeds of this size: the least change that
/// an event's tests are sure to see.
template <typename S>
S roundingSpeed(S speed)
{
  return S(2) * zeroSpeed<S>() * (S(1) + speed);
}

/// |d(tau)|^2 - reach^2 for the relative position d(tau) = c0 + c1 tau + c2 tau^2.
template <typename S>
Poly4<S> distanceGap(const Vec2<S>& c0, const Vec2<S>& c1, const Vec2<S>& c2, S reach)
{
  return {c0.squaredNorm() - reach * reach, S(2) * c0.dot(c1), c1.squaredNorm() + S(2) * c0.dot(c2), S(2) * c1.dot(c2),
          c2.squaredNorm()};
}

/// True if two bodies reach-apart at the base cannot meet within `limit`: a cheap bound on
/// the relative travel, so that far pairs never reach the quartic solver.
template <typename S>
bool cannotMeet(const Vec2<S>& c0, const Vec2<S>& c1, const Vec2<S>& c2, S reach, S limit)
{
  return c0.norm() - reach > limit * (c1.norm() + limit * c2.norm());
}
}  // namespace

template <typename S>
Engine<S>::Engine(std::shared_ptr<const TableModel> table, const PhysicsParams<S>& params, const ModelChoice& models,
                  const EngineLimits& limits)
  : table_(std::move(table)),
    params_(params),
    model_choice_(models),
    limits_(limits),
    ball_ball_(makeBallBallModel<S>(models.ball_ball)),
    cushion_(makeCushionModel<S>(models.cushion))
{
  const std::string why = params_.validate();
  if (!why.empty())
    throw std::invalid_argument("physics parameter " + why);
  auto obstacles = std::make_shared<Obstacles>();
  for (const auto& s : table_->segments())
    obstacles->segments.push_back({s.start.cast<S>(), s.direction.cast<S>(), s.normal.cast<S>(), S(s.length)});
  for (const auto& c : table_->circles())
    obstacles->circles.push_back({c.centre.cast<S>(), S(c.radius)});
  for (const auto& p : table_->pockets())
    obstacles->pockets.push_back({p.centre.cast<S>(), S(p.radius)});
  obstacles_ = obstacles;
}

template <typename S>
Ball<S> Engine<S>::ballAt(const TableState<S>& state, std::size_t index, S t) const
{
  return evolve(state.balls.at(index), t, params_);
}

template <typename S>
std::vector<Ball<S>> Engine<S>::snapshot(const TableState<S>& state) const
{
  std::vector<Ball<S>> balls;
  balls.reserve(state.balls.size());
  for (std::size_t i = 0; i < state.balls.size(); ++i)
    balls.push_back(ballAt(state, i, state.time));
  return balls;
}

template <typename S>
Event<S> Engine<S>::nextEvent(const TableState<S>& state) const
{
  const S base = state.event_time;
  const S R = params_.ball_radius;
  const std::size_t n = state.balls.size();
  Event<S> best;
  int best_index = -1;

  std::vector<S> ends(n, infinity<S>());  // absolute end of each ball's current motion
  std::vector<Trajectory<S>> paths(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const Ball<S>& b = state.balls[i];
    if (!b.inPlay())
      continue;
    paths[i] = trajectoryFrom(b, base, params_);
    if (!b.moving())
      continue;
    ends[i] = b.time + timeToTransition(b, params_);
    if (ends[i] < best.time)
    {
      best.time = ends[i];
      best_index = static_cast<int>(i);
    }
  }
  if (best_index >= 0)
  {
    // Which transition it is follows from applying it to a copy.
    Ball<S> copy = evolve(state.balls[best_index], best.time, params_);
    best.kind = applyTransition(copy, params_);
    best.ball = copy.id;
  }

  const auto limitFor = [&](S end) {
    const S until = std::min(end, best.time);
    return std::isfinite(static_cast<double>(until)) ? until - base : kEndlessHorizon<S>;
  };
  const auto consider = [&](S tau, EventKind kind, int ball, int other, int obstacle) {
    if (base + tau < best.time)
    {
      best.time = base + tau;
      best.kind = kind;
      best.ball = ball;
      best.other = other;
      best.obstacle = obstacle;
    }
  };

  for (std::size_t i = 0; i < n; ++i)
  {
    const Ball<S>& bi = state.balls[i];
    if (!bi.translating())
      continue;
    const Trajectory<S>& pi = paths[i];
    for (std::size_t k = 0; k < obstacles_->segments.size(); ++k)
    {
      const auto& seg = obstacles_->segments[k];
      const S limit = limitFor(ends[i]);
      const Poly4<S> gap = {seg.normal.dot(pi.c0 - seg.start) - R, seg.normal.dot(pi.c1), seg.normal.dot(pi.c2), S(0),
                            S(0)};
      const S tau = contactTime(gap, limit, -zeroSpeed<S>(), touchTolerance(R), true);
      if (tau <= limit)
      {
        const S along = seg.direction.dot(pi.at(tau) - seg.start);
        if (along >= S(0) && along <= seg.length)
          consider(tau, EventKind::BallCushion, bi.id, -1, static_cast<int>(k));
      }
    }
    for (std::size_t k = 0; k < obstacles_->circles.size(); ++k)
    {
      const auto& c = obstacles_->circles[k];
      const S limit = limitFor(ends[i]);
      const S reach = R + c.radius;
      if (cannotMeet<S>(pi.c0 - c.centre, pi.c1, pi.c2, reach, limit))
        continue;
      const S tau = contactTime(distanceGap<S>(pi.c0 - c.centre, pi.c1, pi.c2, reach), limit,
                                -S(2) * reach * zeroSpeed<S>(), touchTolerance(reach * reach), true);
      if (tau <= limit)
        consider(tau, EventKind::BallCircle, bi.id, -1, static_cast<int>(k));
    }
    for (std::size_t k = 0; k < obstacles_->pockets.size(); ++k)
    {
      const auto& p = obstacles_->pockets[k];
      const S limit = limitFor(ends[i]);
      if (cannotMeet<S>(pi.c0 - p.centre, pi.c1, pi.c2, p.radius, limit))
        continue;
      const S tau = contactTime(distanceGap<S>(pi.c0 - p.centre, pi.c1, pi.c2, p.radius), limit, S(0),
                                touchTolerance(p.radius * p.radius));
      if (tau <= limit)
        consider(tau, EventKind::Pocketed, bi.id, -1, static_cast<int>(k));
    }
    for (std::size_t j = 0; j < n; ++j)
    {
      const Ball<S>& bj = state.balls[j];
      if (j == i || !bj.inPlay() || (bj.translating() && j < i))
        continue;  // a pair of translating balls is examined once, from its lower index
      const S limit = limitFor(std::min(ends[i], bj.translating() ? ends[j] : infinity<S>()));
      const Vec2<S> c0 = pi.c0 - paths[j].c0, c1 = pi.c1 - paths[j].c1, c2 = pi.c2 - paths[j].c2;
      if (cannotMeet<S>(c0, c1, c2, S(2) * R, limit))
        continue;
      const S tau = contactTime(distanceGap<S>(c0, c1, c2, S(2) * R), limit, -S(4) * R * zeroSpeed<S>(),
                                touchTolerance(S(4) * R * R), true);
      if (tau <= limit)
        consider(tau, EventKind::BallBall, bi.id, bj.id, -1);
    }
  }
  return best;
}

template <typename S>
void Engine<S>::pocketBall(TableState<S>& state, Ball<S>& ball, int pocket) const
{
  // Pocketed balls rest below the cloth at their pocket's centre, stacked in arrival order.
  int already = 0;
  for (const auto& b : state.balls)
    if (b.motion == Motion::Pocketed && b.pocket == pocket)
      ++already;
  const auto& p = obstacles_->pockets[pocket];
  const S R = params_.ball_radius;
  ball.motion = Motion::Pocketed;
  ball.pocket = pocket;
  ball.r = Vec3<S>(p.centre.x(), p.centre.y(), -R - S(2) * R * S(already));
  ball.v.setZero();
  ball.w.setZero();
}

namespace
{
template <typename S>
S closingSpeed(const Ball<S>& a, const Ball<S>& b)
{
  const Vec2<S> n = (b.r - a.r).template head<2>().normalized();
  return (a.v - b.v).template head<2>().dot(n);
}
}  // namespace

template <typename S>
bool Engine<S>::inSustainedContact(const Ball<S>& a, const Ball<S>& b) const
{
  const Trajectory<S> pa = trajectoryFrom(a, a.time, params_), pb = trajectoryFrom(b, b.time, params_);
  const Vec2<S> d = pa.c0 - pb.c0;
  const Vec2<S> n = d.normalized();
  const Vec2<S> v_rel = pa.c1 - pb.c1;
  const S closing = closingSpeed(a, b);
  if (!(closing < S(limits_.sustained_contact_speed)))
    return false;
  // After a bounce that removes the closing speed, the squared distance grows as
  // (|v_t|^2 + d.a_rel) tau^2: negative means the accelerations press the balls back together.
  const Vec2<S> v_t = v_rel + closing * n;
  return v_t.squaredNorm() + d.dot(S(2) * (pa.c2 - pb.c2)) < S(0);
}

template <typename S>
void Engine<S>::joinPressedCluster(TableState<S>& state, S time, int first, int second) const
{
  // Joining only the pair would slow it against a third ball it touches, which would then
  // close on it and be joined, then the pair again, converging without end (a line of balls
  // rolling together). So every ball touching the cluster that the joined motion leaves
  // closing on it, slower than the sustained-contact speed, joins too, until none does.
  const S touching = S(2) * params_.ball_radius + S(1e-12);
  std::vector<int> cluster = {first, second};
  Vec3<S> v = Vec3<S>::Zero(), w = Vec3<S>::Zero();
  for (bool grown = true; grown;)
  {
    v.setZero();
    w.setZero();
    for (int c : cluster)
    {
      v += state.balls[c].v;
      w += state.balls[c].w;
    }
    v /= S(cluster.size());
    w /= S(cluster.size());
    grown = false;
    for (std::size_t j = 0; j < state.balls.size() && !grown; ++j)
    {
      if (!state.balls[j].inPlay() || std::find(cluster.begin(), cluster.end(), static_cast<int>(j)) != cluster.end())
        continue;
      const Ball<S> at_time = evolve(state.balls[j], time, params_);
      for (std::size_t k = 0; k < cluster.size() && !grown; ++k)
      {
        Ball<S> joined = state.balls[cluster[k]];
        joined.v = v;
        const S closing = closingSpeed(at_time, joined);
        if ((at_time.r - joined.r).template head<2>().norm() <= touching && closing > -zeroSpeed<S>() &&
            closing < S(limits_.sustained_contact_speed))
        {
          state.balls[j] = at_time;
          cluster.push_back(static_cast<int>(j));
          grown = true;
        }
      }
    }
  }
  // A wall a cluster ball touches holds the whole cluster as it would hold the ball alone: it
  // stops the joined motion into it (the wall takes momentum), and the cloth friction it
  // balances turns the slip into it into spin (holdAgainstWall). Done once for the joined
  // motion, so the cluster's balls keep moving as one.
  Ball<S> joined = state.balls[first];
  joined.v = v;
  joined.w = w;
  settleMotion(joined, params_.ball_radius);
  for (int c : cluster)
    for (const Vec3<S>& normal : touchingWalls(state.balls[c]))
    {
      joined.v -= std::min(joined.v.dot(normal), S(0)) * normal;
      settleMotion(joined, params_.ball_radius);
      holdAgainstWall(joined, normal);
    }
  for (int c : cluster)
  {
    state.balls[c].v = joined.v;
    state.balls[c].w = joined.w;
    state.balls[c].motion = joined.motion;
  }
}

template <typename S>
std::vector<Vec3<S>> Engine<S>::touchingWalls(const Ball<S>& ball) const
{
  const S R = params_.ball_radius;
  const S tolerance = S(1e-12);
  std::vector<Vec3<S>> normals;
  const Vec2<S> c = ball.r.template head<2>();
  for (const auto& seg : obstacles_->segments)
  {
    const S along = seg.direction.dot(c - seg.start);
    if (along >= S(0) && along <= seg.length && std::abs(seg.normal.dot(c - seg.start) - R) <= tolerance)
      normals.emplace_back(seg.normal.x(), seg.normal.y(), S(0));
  }
  for (const auto& circle : obstacles_->circles)
    if (std::abs((c - circle.centre).norm() - R - circle.radius) <= tolerance)
    {
      const Vec2<S> n = (c - circle.centre).normalized();
      normals.emplace_back(n.x(), n.y(), S(0));
    }
  return normals;
}

template <typename S>
bool Engine<S>::resolveImpactGroup(TableState<S>& state, S time, int first, int second) const
{
  const Vec3<S> first_before = state.balls[first].v, second_before = state.balls[second].v;
  const S R = params_.ball_radius;
  // Balls that touch, transitively, the colliding pair take part in one impact.
  const S touching = S(2) * R + S(1e-12);
  std::vector<int> group = {first, second};
  for (std::size_t k = 0; k < group.size(); ++k)
    for (std::size_t j = 0; j < state.balls.size(); ++j)
    {
      if (!state.balls[j].inPlay() || std::find(group.begin(), group.end(), static_cast<int>(j)) != group.end())
        continue;
      const Ball<S> at_time = evolve(state.balls[j], time, params_);
      if ((at_time.r - state.balls[group[k]].r).template head<2>().norm() <= touching)
      {
        state.balls[j] = at_time;
        group.push_back(static_cast<int>(j));
      }
    }
  std::vector<std::pair<int, int>> contacts;
  for (std::size_t a = 0; a < group.size(); ++a)
    for (std::size_t b = a + 1; b < group.size(); ++b)
      if ((state.balls[group[a]].r - state.balls[group[b]].r).template head<2>().norm() <= touching)
        contacts.emplace_back(group[a], group[b]);
  // Cushions and jaws a group ball touches take part too: a ball pinned against a cushion.
  struct Wall
  {
    int ball;
    Vec3<S> normal;  // into play
  };
  std::vector<Wall> walls;
  for (int g : group)
    for (const Vec3<S>& normal : touchingWalls(state.balls[g]))
      walls.push_back({g, normal});
  const auto closing = [&](const std::vector<Ball<S>>& balls, const std::pair<int, int>& c) {
    return closingSpeed(balls[c.first], balls[c.second]);
  };
  std::vector<std::size_t> closing_now, resting;
  for (std::size_t c = 0; c < contacts.size(); ++c)
    (closing(state.balls, contacts[c]) > zeroSpeed<S>() ? closing_now : resting).push_back(c);

  // Pairwise impulses, swept over the group until nothing closes (projected Gauss-Seidel).
  const auto sweepToRest = [&](std::vector<std::size_t> order) {
    order.insert(order.end(), resting.begin(), resting.end());
    std::vector<Ball<S>> balls = state.balls;
    for (int sweep = 0; sweep < 100000; ++sweep)
    {
      bool any = false;
      for (std::size_t c : order)
        if (closing(balls, contacts[c]) > zeroSpeed<S>())
        {
          ball_ball_->resolve(balls[contacts[c].first], balls[contacts[c].second], params_);
          any = true;
        }
      for (const Wall& wall : walls)
        if (balls[wall.ball].v.dot(wall.normal) < -zeroSpeed<S>())
        {
          cushion_->resolve(balls[wall.ball], wall.normal, params_);
          any = true;
        }
      if (!any)
        break;
    }
    return balls;
  };
  // Contacts closing at the same instant have no first: every order is resolved and the
  // outcomes averaged, which keeps momentum, cannot add energy (kinetic energy is convex) and
  // keeps symmetric scenes symmetric.
  std::vector<std::vector<std::size_t>> orders;
  std::vector<std::size_t> order = closing_now;
  if (order.size() <= 4)
    do
      orders.push_back(order);
    while (std::next_permutation(order.begin(), order.end()));
  else
  {
    orders.push_back(order);
    orders.emplace_back(order.rbegin(), order.rend());
  }
  std::vector<Vec3<S>> v(group.size(), Vec3<S>::Zero()), w(group.size(), Vec3<S>::Zero());
  for (const auto& o : orders)
  {
    const std::vector<Ball<S>> outcome = sweepToRest(o);
    for (std::size_t g = 0; g < group.size(); ++g)
    {
      v[g] += outcome[group[g]].v;
      w[g] += outcome[group[g]].w;
    }
  }
  for (std::size_t g = 0; g < group.size(); ++g)
  {
    Ball<S>& b = state.balls[group[g]];
    b.v = v[g] / S(orders.size());
    b.w = w[g] / S(orders.size());
    settleMotion(b, R);
  }
  return state.balls[first].v != first_before || state.balls[second].v != second_before;
}

template <typename S>
void Engine<S>::holdAgainstWall(Ball<S>& ball, const Vec3<S>& normal) const
{
  const S R = params_.ball_radius;
  const S v_n = ball.v.dot(normal);
  if (!(std::abs(v_n) < S(limits_.sustained_contact_speed)) || ball.motion != Motion::Sliding)
    return;
  Vec3<S> v = ball.v - v_n * normal;
  const S u_n = slipVelocity(v, ball.w, R).dot(normal);
  if (!(u_n > S(0)))
    return;  // the cloth pulls the ball off the wall, or along it: free motion
  // Cloth friction at the bottom point, balanced by the wall's reaction through the centre
  // (a normal force on a sphere has no torque), acts on the spin alone: an impulse of
  // j = (2/5) m u_n against the slip turns w about z x n until the slip has no part into the
  // wall. It opposes the slip, so it removes energy.
  //
  // The slip is left pointing out of the wall by a few ulps rather than exactly along it: a
  // slip a hair into the wall, by rounding, would be found as the same contact again at the
  // same instant. (The energy this can add is of the order of m ulp^2, below 1e-28 J.)
  const Vec3<S> axis = Vec3<S>::UnitZ().cross(normal);
  const S ulp = zeroSpeed<S>() * (v.norm() + R * ball.w.norm());
  Vec3<S> w = ball.w + ((u_n + ulp) / R) * axis;
  for (S nudge = ulp; slipVelocity(v, w, R).dot(normal) > -S(0.5) * ulp; nudge *= S(2))
    w += (nudge / R) * axis;
  ball.v = v;
  ball.w = w;
  settleMotion(ball, R);
}

template <typename S>
void Engine<S>::processEvent(TableState<S>& state, const Event<S>& event) const
{
  state.event_time = std::max(state.event_time, event.time);
  Ball<S>& ball = state.balls[state.indexOf(event.ball)];
  ball = evolve(ball, event.time, params_);
  const S R = params_.ball_radius;
  switch (event.kind)
  {
    case EventKind::BallBall: {
      Ball<S>& other = state.balls[state.indexOf(event.other)];
      other = evolve(other, event.time, params_);
      // A pressed pair is joined (with its cluster, held by any wall it touches); any other
      // contact is an impact of the touching group. An event must change something, or it is
      // found again at the same instant forever.
      const Vec3<S> ball_before = ball.v, other_before = other.v;
      if (inSustainedContact(ball, other))
        joinPressedCluster(state, event.time, state.indexOf(event.ball), state.indexOf(event.other));
      else if (!resolveImpactGroup(state, event.time, state.indexOf(event.ball), state.indexOf(event.other)))
      {
        // Found closing by the gap polynomial but not by the impact's own arithmetic: a closing
        // speed within rounding of zero. The model resolves it alone, or, if even it sees no
        // approach, the pair is parted by a few ulps of their speed.
        ball_ball_->resolve(ball, other, params_);
        if (ball.v == ball_before && other.v == other_before)
        {
          const Vec3<S> n = Vec3<S>(other.r.x() - ball.r.x(), other.r.y() - ball.r.y(), S(0)).normalized();
          const S part = roundingSpeed((ball.v - other.v).norm());
          ball.v -= S(0.5) * part * n;
          other.v += S(0.5) * part * n;
        }
      }
      settleMotion(ball, R);
      settleMotion(other, R);
      break;
    }
    case EventKind::BallCushion:
    case EventKind::BallCircle: {
      const Vec2<S> n = event.kind == EventKind::BallCushion
                            ? obstacles_->segments[event.obstacle].normal
                            : (ball.r.template head<2>() - obstacles_->circles[event.obstacle].centre).normalized();
      const Vec3<S> normal(n.x(), n.y(), S(0));
      const Vec3<S> v_before = ball.v, w_before = ball.w;
      cushion_->resolve(ball, normal, params_);
      settleMotion(ball, R);
      holdAgainstWall(ball, normal);
      if (ball.v == v_before && ball.w == w_before)
      {
        // Found approaching or pressing by the gap polynomial but by neither the model nor the
        // hold: within rounding of zero. Moved off by a few ulps of its speed, the ball is not
        // found at this wall again at this instant.
        ball.v += roundingSpeed(ball.v.norm()) * normal;
        settleMotion(ball, R);
      }
      break;
    }
    case EventKind::Pocketed:
      pocketBall(state, ball, event.obstacle);
      break;
    default:
      applyTransition(ball, params_);
      break;
  }
}

template <typename S>
Event<S> Engine<S>::step(TableState<S>& state) const
{
  const Event<S> event = nextEvent(state);
  if (event.valid())
  {
    processEvent(state, event);
    state.time = std::max(state.time, event.time);
  }
  return event;
}

template <typename S>
void Engine<S>::advance(TableState<S>& state, S t_end, std::vector<Event<S>>* events) const
{
  long processed = 0;
  for (;;)
  {
    const Event<S> event = nextEvent(state);
    if (!event.valid() || event.time > t_end)
      break;
    if (++processed > limits_.max_events)
    {
      std::ostringstream why;
      why << "event limit reached: more than " << limits_.max_events
          << " events before t = " << static_cast<double>(event.time) << " s (EngineLimits::max_events)";
      throw EventLimitError(why.str());
    }
    processEvent(state, event);
    if (events)
      events->push_back(event);
  }
  state.time = std::max(state.time, t_end);
}

template <typename S>
ShotResult<S> Engine<S>::simulateToRest(TableState<S>& state) const
{
  const S start = state.time;
  const S stop = start + S(limits_.max_shot_time);
  ShotResult<S> result;
  advance(state, stop, &result.events);
  result.at_rest = !state.anyMoving();
  if (result.at_rest)
    state.time = std::max(start, state.event_time);
  result.duration = state.time - start;
  return result;
}

template <typename S>
std::string Engine<S>::whyNotStrikable(const TableState<S>& state, int ball_id, const CueStrike<S>& strike) const
{
  const int index = state.indexOf(ball_id);
  if (index < 0)
    return "ball_id " + std::to_string(ball_id) + " is not on the table";
  if (!state.balls[index].inPlay())
    return "ball_id " + std::to_string(ball_id) + " is pocketed";
  return validateStrike(strike);
}

template <typename S>
void Engine<S>::strike(TableState<S>& state, int ball_id, const CueStrike<S>& strike) const
{
  const std::string why = whyNotStrikable(state, ball_id, strike);
  if (!why.empty())
    throw std::invalid_argument(why);
  Ball<S>& ball = state.balls[state.indexOf(ball_id)];
  ball = evolve(ball, state.time, params_);
  applyCueStrike(ball, strike, params_);
  settleMotion(ball, params_.ball_radius);
  // The strike is an event: predictions restart from it.
  state.event_time = state.time;
}

template <typename S>
std::string Engine<S>::whyInvalid(const TableState<S>& state, double tolerance) const
{
  const double R = static_cast<double>(params_.ball_radius);
  std::set<int> ids;
  std::ostringstream why;
  for (const auto& b : state.balls)
  {
    const std::string label = "ball " + std::to_string(b.id);
    if (b.id < 0)
      return label + ": id must be >= 0";
    if (!ids.insert(b.id).second)
      return label + ": id appears twice";
    if (!isFinite(b.r) || !isFinite(b.v) || !isFinite(b.w) || !std::isfinite(static_cast<double>(b.time)))
      return label + ": position, velocity, angular velocity and time must be finite";
    if (!b.inPlay())
      continue;
    if (std::abs(static_cast<double>(b.r.z()) - R) > tolerance)
      return label + ": a ball on the cloth has z = R = " + std::to_string(R) + " m";
    const std::string where = table_->whyNotPlaceable(b.r.template head<2>().template cast<double>(), R);
    if (!where.empty())
      return label + ": " + where;
  }
  for (std::size_t i = 0; i < state.balls.size(); ++i)
    for (std::size_t j = i + 1; j < state.balls.size(); ++j)
    {
      const Ball<S>& a = state.balls[i];
      const Ball<S>& b = state.balls[j];
      if (!a.inPlay() || !b.inPlay())
        continue;
      const double d =
          static_cast<double>((evolve(a, state.time, params_).r - evolve(b, state.time, params_).r).norm());
      if (d < 2 * R - tolerance)
      {
        why << "balls " << a.id << " and " << b.id << " overlap: centres " << d << " m apart, less than 2R = " << 2 * R;
        return why.str();
      }
    }
  return {};
}

template class Engine<double>;
template class Engine<long double>;

}  // namespace physics
}  // namespace cue_sim

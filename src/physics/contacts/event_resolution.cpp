#include "physics/contacts/event_resolution.hpp"

#include <algorithm>
#include <cmath>

#include "cue_sim/physics/motion.hpp"
#include "physics/contacts/event_resolver.hpp"
#include "physics/engine/held_balls.hpp"
#include "physics/engine/table_departure.hpp"
#include "physics/models/ball_table/slate_landing.hpp"

namespace cue_sim
{
namespace physics
{
template <typename S>
void resolveEvent(const Engine<S>& engine, TableState<S>& state, const Event<S>& event, const EventContext<S>& context)
{
  EventResolver<S> resolver(engine, state, context);
  resolver.resolve(event);
  resolver.wakeHeldBalls(event.time);
  resolver.restepTouchedGroups(event.time);
}

template <typename S>
void resolveSupportStep(const Engine<S>& engine, TableState<S>& state, S time, const EventContext<S>& context)
{
  EventResolver<S> resolver(engine, state, context);
  resolver.stepGroup(time, context.index);
}

template <typename S>
void EventResolver<S>::resolve(const Event<S>& event)
{
  if (event.time > state_.event_time + S(kSameInstant) + S(kSameInstantPerSecond) * std::abs(event.time))
    state_.events_this_instant = 0;
  state_.event_time = std::max(state_.event_time, event.time);
  const long at_this_instant = ++state_.events_this_instant;
  Ball<S>& ball = state_.balls[context_.index];
  ball = evolve(ball, event.time, params_);
  changed(context_.index);
  const long allowance = engine_.limits().collapse_events;
  // A ball in the air, or in sustained contact with one, is no part of a collapse on the cloth (its
  // pair is resolved as it comes).
  const auto offTheCloth = [](const Ball<S>& b) { return b.airborne() || b.supported(); };
  const bool in_the_air =
      offTheCloth(ball) || (context_.other_index >= 0 && offTheCloth(state_.balls[context_.other_index]));
  if (at_this_instant > allowance && !in_the_air &&
      (event.kind == EventKind::BallBall || event.kind == EventKind::BallCushion ||
       event.kind == EventKind::BallCircle))
  {
    if (context_.other_index >= 0)
      state_.balls[context_.other_index] = evolve(state_.balls[context_.other_index], event.time, params_);
    collapse(event.time, context_.index, context_.other_index, at_this_instant > 2 * allowance);
    return;
  }
  switch (event.kind)
  {
    case EventKind::BallBall:
      resolveBallBall(event);
      break;
    case EventKind::BallCushion:
    case EventKind::BallCircle:
      resolveWall(ball, event);
      break;
    case EventKind::Pocketed:
      dissolveGroup(context_.index, event.time);
      pocketBall(ball, event.obstacle);
      break;
    case EventKind::BallSlate:
      landOnSlate(ball, engine_.ballTableModel(), params_);
      break;
    case EventKind::OffTable:
      dissolveGroup(context_.index, event.time);
      leaveTable(ball);
      break;
    default:
      applyTransition(ball, params_);
      break;
  }
}

template <typename S>
void EventResolver<S>::resolveBallBall(const Event<S>& event)
{
  Ball<S>& ball = state_.balls[context_.index];
  Ball<S>& other = state_.balls[context_.other_index];
  other = evolve(other, event.time, params_);
  changed(context_.other_index);
  // A pressed pair is joined (with its cluster, held by any wall it touches); any other contact
  // is an impact of the touching group. An event must change something, or it is found again
  // at the same instant forever.
  if (ball.airborne() || other.airborne() || ball.supported() || other.supported())
  {
    resolvePairOffTheCloth(event);
    return;
  }
  const Vec3<S> ball_before = ball.v, other_before = other.v;
  if (inSustainedContact(ball, other))
    joinPressedCluster(event.time, context_.index, context_.other_index);
  else if (!resolveImpactGroup(event.time, context_.index, context_.other_index))
  {
    // Found closing by the gap polynomial but not by the impact's own arithmetic: a closing
    // speed within rounding of zero. The model resolves it alone, or, if even it sees no
    // approach, the pair is parted by a few ulps of their speed.
    engine_.ballBallModel().resolve(ball, other, params_);
    if (ball.v == ball_before && other.v == other_before)
    {
      const Vec3<S> n = Vec3<S>(other.r.x() - ball.r.x(), other.r.y() - ball.r.y(), S(0)).normalized();
      const S part = roundingSpeed((ball.v - other.v).norm());
      ball.v -= S(0.5) * part * n;
      other.v += S(0.5) * part * n;
    }
  }
  settleMotion(ball, params_.ball_radius);
  settleMotion(other, params_.ball_radius);
}

template <typename S>
void EventResolver<S>::resolvePairOffTheCloth(const Event<S>& event)
{
  const int ia = context_.index, ib = context_.other_index;
  // An event within their pieces changes a group in sustained contact: brought to it first.
  cutGroup(ia, event.time);
  cutGroup(ib, event.time);
  Ball<S>& a = state_.balls[ia];
  Ball<S>& b = state_.balls[ib];
  const Vec3<S> n = (b.r - a.r).normalized();
  // Slow enough, the contact lasts: the group's equations take it (they stop what still closes).
  // Faster, an impact, in which each ball's group comes apart.
  if (meetSlowly((a.v - b.v).dot(n)))
  {
    stepGroup(event.time, ia);
    return;
  }
  dissolveGroup(ia, event.time);
  dissolveGroup(ib, event.time);
  for (Ball<S>* held : {&a, &b})
    if (held->held())
      held->motion = Motion::Airborne;  // met by a ball: it takes part in the impact, free
  const bool a_on_cloth = !a.airborne(), b_on_cloth = !b.airborne();
  impactInAir(a, b, n);
  if (a_on_cloth != b_on_cloth)
    passImpactOnThroughCloth(state_.event_time, a_on_cloth ? ib : ia, a_on_cloth ? ia : ib);
  for (Ball<S>* one : {&a, &b})
  {
    // A ball coming down from the air meets the slate anew.
    if (one->r.z() - params_.ball_radius <= onClothHeight(params_.ball_radius) && one->v.z() < S(0))
      landOnSlate(*one, engine_.ballTableModel(), params_);
    else
      settleMotion(*one, params_.ball_radius);
  }
}

template <typename S>
void EventResolver<S>::wakeHeldBalls(S time)
{
  // A ball set moving may have held a ball up: every held ball touching it falls (and is held
  // again a few events later if its supports still hold it). A ball that stops, or keeps only a
  // spin, lets none fall, nor does any ball one that a group held in this event, judged with it as
  // it moves now. Each fallen ball is looked around in turn (a stack).
  if (std::none_of(state_.balls.begin(), state_.balls.end(), [](const Ball<S>& b) { return b.held(); }))
    return;
  const std::vector<int>& list = context_.changed ? *context_.changed : changed_here_;
  std::vector<int> near, fallen;
  for (std::size_t k = changed_from_; k < list.size(); ++k)
  {
    const int index = list[k];
    // A ball in a group touches the held balls it moves with: they are in its group.
    if (!state_.balls[index].translating() || state_.balls[index].supported())
      continue;
    nearBalls(evolve(state_.balls[index], time, params_).r.template head<2>(),
              S(2) * params_.ball_radius + S(kHeldReach), near);
    near.erase(std::remove_if(near.begin(), near.end(), [&](int j) { return heldHere(j); }), near.end());
    fallen.clear();
    letHeldBallsFall(state_, index, time, params_, near, fallen);
    for (int j : fallen)
      changed(j);  // appended to `list`: looked around in turn
  }
}

template <typename S>
void EventResolver<S>::restepTouchedGroups(S time)
{
  // A group's step took the balls touching it as they then moved: one that an event changed since
  // (struck, stopped, turned), even at the instant of the step, is met by the group's next step,
  // taken now. (A group stepped by one event at an instant and left out of the next at the same
  // instant kept the old path of a ball the next one struck into it: the event search leaves a pair
  // touching a group to the group, and the ball went 0.5 um into it.)
  const std::vector<int>& list = context_.changed ? *context_.changed : changed_here_;
  const std::size_t end = list.size();
  const S reach = S(2) * params_.ball_radius + supportTouch(params_);
  std::vector<int> near;
  for (std::size_t k = changed_from_; k < end; ++k)
  {
    const int index = list[k];
    const Ball<S>& ball = state_.balls[static_cast<std::size_t>(index)];
    if (!ball.inPlay() || ball.supported())
      continue;
    const Vec3<S> r = evolve(ball, time, params_).r;
    nearBalls(r.template head<2>(), reach, near);
    for (int j : near)
    {
      const Ball<S>& other = state_.balls[static_cast<std::size_t>(j)];
      if (other.supported() && other.time <= time && time < other.piece.until &&
          (stateAt(j, time).r - r).norm() <= reach)
        stepGroup(time, j);
    }
  }
}

template <typename S>
void EventResolver<S>::impactInAir(Ball<S>& a, Ball<S>& b, const Vec3<S>& n)
{
  const Vec3<S> a_before = a.v, b_before = b.v;
  const bool a_on_cloth = !a.airborne(), b_on_cloth = !b.airborne();
  // A ball on the cloth stays on it: the cloth takes the vertical part of the impulse, as it
  // does in every impact on the cloth (the slate, already in contact, takes a push down during
  // the impact; friction lifting it is the vertical friction the ball-ball models leave to the
  // cloth). Answered with e_table instead, a cue ball hopping into a touching rack would set it
  // hopping, ball by ball, at one instant. The cloth's part leaves the pair closing again along
  // their tilted line of centres, so the impulses follow one another, as at a wall
  // (kMaxWallImpulses), and what they leave of the closing the flying ball loses.
  const auto keepOnCloth = [&] {
    if (a_on_cloth)
      a.v.z() = S(0);
    if (b_on_cloth)
      b.v.z() = S(0);
  };
  for (int impulse = 0; impulse == 0 || (impulse < kMaxWallImpulses && (a.v - b.v).dot(n) > zeroSpeed<S>()); ++impulse)
  {
    engine_.ballBallModelInAir().resolve(a, b, params_);
    keepOnCloth();
  }
  const S closing = (a.v - b.v).dot(n);
  if (closing > zeroSpeed<S>())
    (a_on_cloth ? b : a).v += (a_on_cloth ? closing : -closing) * n;
  if (a.v == a_before && b.v == b_before)
  {
    // Found closing by the gap polynomial but not by the model: parted by a few ulps of speed.
    const S part = roundingSpeed((a.v - b.v).norm());
    a.v -= S(0.5) * part * n;
    b.v += S(0.5) * part * n;
  }
  keepOnCloth();
}

template <typename S>
void EventResolver<S>::leaveTable(Ball<S>& ball)
{
  const Departure<S> d = departureOf(ball, geometry_, params_);
  if (d.kind == EventKind::Pocketed)
  {
    pocketBall(ball, d.obstacle);
    return;
  }
  ball.motion = Motion::OffTable;
  ball.pocket = kOffTable;
  ball.r = d.where;
  ball.v.setZero();
  ball.w.setZero();
}

template <typename S>
bool EventResolver<S>::resolveWallTop(Ball<S>& ball, const Event<S>& event)
{
  // Above the wall's top: the nose's edge (or the post's rim) takes the impact, along the line
  // from its nearest point to the centre, with the cushion's restitution and no friction
  // (doc/physics.md, "Balls in the air").
  const S above = ball.r.z() - geometry_.nose_height;
  if (!ball.airborne() || !(above > S(0)))
    return false;
  Vec2<S> out;
  if (event.kind == EventKind::BallCushion)
  {
    const auto& seg = geometry_.segments[event.obstacle];
    out = std::max(seg.normal.dot(ball.r.template head<2>() - seg.start), S(0)) * seg.normal;
  }
  else
  {
    const auto& post = geometry_.circles[event.obstacle];
    const Vec2<S> from_centre = ball.r.template head<2>() - post.centre;
    const S distance = from_centre.norm();
    out = distance > post.radius ? Vec2<S>((distance - post.radius) / distance * from_centre) : Vec2<S>::Zero();
  }
  const Vec3<S> normal = Vec3<S>(out.x(), out.y(), above).normalized();
  const S approach = ball.v.dot(normal);
  // Resting on it, or meeting it slowly: a sustained contact, which the contact equations follow.
  if (meetSlowly(-approach))
  {
    stepGroup(event.time, context_.index);
    return true;
  }
  dissolveGroup(context_.index, event.time);
  ball.v -= (S(1) + params_.e_cushion) * approach * normal;
  settleMotion(ball, params_.ball_radius);
  return true;
}

template <typename S>
void EventResolver<S>::resolveWall(Ball<S>& ball, const Event<S>& event)
{
  cutGroup(context_.index, event.time);
  if (resolveWallTop(ball, event))
    return;
  if (ball.supported())
  {
    // A ball of a group meeting a cushion's face or a post's side: slowly, the group's equations
    // take the contact; faster, an impact, in which its group comes apart.
    const Vec2<S> n2 = event.kind == EventKind::BallCushion
                           ? geometry_.segments[event.obstacle].normal
                           : (ball.r.template head<2>() - geometry_.circles[event.obstacle].centre).normalized();
    if (meetSlowly(-ball.v.template head<2>().dot(n2)))
    {
      stepGroup(event.time, context_.index);
      return;
    }
    dissolveGroup(context_.index, event.time);
  }
  const Vec2<S> n = event.kind == EventKind::BallCushion
                        ? geometry_.segments[event.obstacle].normal
                        : (ball.r.template head<2>() - geometry_.circles[event.obstacle].centre).normalized();
  const Vec3<S> normal(n.x(), n.y(), S(0));
  const Vec3<S> v_before = ball.v, w_before = ball.w;
  // The cushion models take a ball on the cloth (the cloth takes their vertical part). A ball in
  // the air meets the wall as a vertical face (doc/physics.md, "Balls in the air"): the models
  // resolve its level motion, and it keeps its vertical speed.
  const bool flying = ball.airborne();
  if (flying)
    ball.v.z() = S(0);
  wallImpact(ball, normal);
  if (!flying)
    cornerImpact(ball);
  if (flying)
    ball.v.z() = v_before.z();
  settleMotion(ball, params_.ball_radius);
  holdAgainstWall(ball, normal);
  if (ball.v == v_before && ball.w == w_before)
  {
    // Found approaching or pressing by the gap polynomial but by neither the model nor the
    // hold: within rounding of zero. Moved off by a few ulps of its speed, the ball is not
    // found at this wall again at this instant.
    ball.v += roundingSpeed(ball.v.norm()) * normal;
    settleMotion(ball, params_.ball_radius);
  }
}

template <typename S>
void EventResolver<S>::wallImpact(Ball<S>& ball, const Vec3<S>& normal) const
{
  // A ball the model's impulse leaves still closing on the wall meets it again at once: the
  // impulses follow one another (a nose near the ball's top, or little restitution, takes a
  // few), and what a bounded number of them leaves, the wall stops.
  for (int impulse = 0; impulse == 0 || (impulse < kMaxWallImpulses && ball.v.dot(normal) < -zeroSpeed<S>()); ++impulse)
    engine_.cushionModel().resolve(ball, normal, params_);
  stopClosing(ball, normal);
}

template <typename S>
void EventResolver<S>::cornerImpact(Ball<S>& ball) const
{
  // A ball touching two walls at once (a corner, a jaw beside its cushion) meets them as one
  // impact: each wall's impulses in turn while it closes on it, as the impact groups take
  // theirs, and what kMaxWallImpulses rounds leave closing, the walls stop. Met one wall at a
  // time, a ball spun against both by friction above one (mu_cushion 4.6 on a frictionless
  // carom cloth, soak seed 12, shot 39701) bounced between them every 25 ns for ever.
  const std::vector<Vec3<S>> walls = touchingWalls(ball);
  if (walls.size() < 2)
    return;
  for (int round = 0; round < kMaxWallImpulses; ++round)
  {
    bool any = false;
    for (const Vec3<S>& wall : walls)
      if (ball.v.dot(wall) < -zeroSpeed<S>())
      {
        engine_.cushionModel().resolve(ball, wall, params_);
        any = true;
      }
    if (!any)
      return;
  }
  for (int sweep = 0; sweep < kInelasticSweeps; ++sweep)
  {
    bool any = false;
    for (const Vec3<S>& wall : walls)
      any = stopClosing(ball, wall) || any;
    if (!any)
      return;
  }
}

template <typename S>
void EventResolver<S>::pocketBall(Ball<S>& ball, int pocket)
{
  // Pocketed balls rest below the cloth at their pocket's centre, stacked in arrival order.
  int already = 0;
  for (const auto& b : state_.balls)
    if (b.motion == Motion::Pocketed && b.pocket == pocket)
      ++already;
  const auto& p = geometry_.pockets[pocket];
  const S R = params_.ball_radius;
  ball.motion = Motion::Pocketed;
  ball.pocket = pocket;
  ball.r = Vec3<S>(p.centre.x(), p.centre.y(), -R - S(2) * R * S(already));
  ball.v.setZero();
  ball.w.setZero();
}

// Used by the impact group's sweep too (impact_group.cpp).
template void EventResolver<double>::wallImpact(Ball<double>&, const Vec3<double>&) const;
template void EventResolver<long double>::wallImpact(Ball<long double>&, const Vec3<long double>&) const;
template void resolveEvent(const Engine<double>&, TableState<double>&, const Event<double>&,
                           const EventContext<double>&);
template void resolveEvent(const Engine<long double>&, TableState<long double>&, const Event<long double>&,
                           const EventContext<long double>&);
template void resolveSupportStep(const Engine<double>&, TableState<double>&, double, const EventContext<double>&);
template void resolveSupportStep(const Engine<long double>&, TableState<long double>&, long double,
                                 const EventContext<long double>&);

}  // namespace physics
}  // namespace cue_sim

// Balls in sustained contact in the air (doc/physics.md, "Resting contact"). A ball that comes to a
// support (another ball, a cushion's nose, a post's rim) slower than kSettleSpeed stays on it: the
// contact lasts longer than a bounce would (Luding and McNamara's TC model). From then on it, and the
// balls it presses on, move by the contact equations (src/physics/supports/), a step at a time: each
// step gathers the balls touching the group, stops what still closes, chooses every contact's modes
// (pressed or free, sticking or sliding, rolling or stuck), and either freezes the group (at rest
// and held there: Held in the air, Stationary on the cloth), lets its balls go back to their own
// closed-form motion (nothing presses a ball in the air any more), or integrates the next step and
// gives each ball the quadratic piece it follows until then.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "cue_sim/physics/motion.hpp"
#include "physics/contacts/event_resolver.hpp"
#include "physics/supports/contact_system.hpp"
#include "physics/supports/support_step.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
/// A group is at rest when none of its balls moves or turns (at its surface) faster than a sustained
/// contact begins (kSettleSpeed) and none accelerates by more than this share of g. A pile that can
/// stand finds its forces by creeping in the band where friction is regularized (a statically
/// indeterminate pile: its stuck forces of least norm, what the complementarity problem gives, may
/// exceed their bounds where another share of its weight does not), and a marginal one creeps slower
/// still: static friction, above the sliding friction on a real table, holds both. A ball this far
/// from a balance (1e-4 rad off a frictionless support's top) is held there.
constexpr double kRestShare = 1e-4;
/// The first step of a group, as a share of its natural time sqrt(R / g) (54 us for a pool ball); the
/// next is tried at twice the last.
constexpr double kFirstStep = 1e-3;
/// The longest step, in natural times: a ball creeping on its supports, whose piece is exact for long.
constexpr double kLongestStep = 10;
/// Sweeps of the impulses that stop what closes in a group before its step: frictionless and
/// perfectly inelastic, each an orthogonal projection, so they converge and cannot add energy.
constexpr int kStopSweeps = 1000;

/// Union-find over a group's bodies.
int rootOf(std::vector<int>& parent, int k)
{
  while (parent[static_cast<std::size_t>(k)] != k)
    k = parent[static_cast<std::size_t>(k)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(k)])];
  return k;
}
}  // namespace

namespace
{
/// The factor on the bodies' velocities and spins that leaves them no more energy than `allowed`
/// (1 if they have no more; 0 if their height alone has more).
template <typename S>
S energyScaleFor(S allowed, const std::vector<ContactBody<S>>& bodies, const PhysicsParams<S>& p)
{
  const S energy = groupEnergy(bodies, p);
  if (!(energy > allowed))
    return S(1);
  S kinetic = S(0);
  for (const ContactBody<S>& b : bodies)
    kinetic += S(0.5) * p.ball_mass * (b.v.squaredNorm() + S(0.4) * p.ball_radius * p.ball_radius * b.w.squaredNorm());
  return kinetic > S(0) ? std::sqrt(std::max(kinetic - (energy - allowed), S(0)) / kinetic) : S(0);
}

/// A group left with nothing pressed may hold contacts that the event search finds pressing (grazes:
/// a gap whose acceleration is within rounding of zero, where the contact equations, by their
/// tolerance, leave it free). Each ball in the air is sent off them all together by a few ulps of its
/// speed, so that none is found again at this instant (parting one pair at a time closed another).
template <typename S>
void partGrazes(const ContactSystem<S>& system, std::vector<ContactBody<S>>& bodies,
                const std::vector<ContactLink<S>>& links, S radius)
{
  for (int sweep = 0; sweep < 8; ++sweep)
  {
    bool any = false;
    for (std::size_t l = 0; l < links.size(); ++l)
    {
      const ContactLink<S>& link = links[l];
      ContactBody<S>& b = bodies[static_cast<std::size_t>(link.body)];
      ContactBody<S>* o = link.other >= 0 ? &bodies[static_cast<std::size_t>(link.other)] : nullptr;
      const bool b_air = b.r.z() - radius > onClothHeight(radius),
                 o_air = o && o->r.z() - radius > onClothHeight(radius);
      if (!b_air && !o_air)
        continue;  // on the cloth both: the planar search's own rules part them
      const ContactGeometry<S> c = system.geometryOf(link, bodies);
      const S parting = system.relativeVelocity(link, bodies).dot(c.n);
      const S wanted = roundingSpeed(b.v.norm() + (o ? o->v.norm() : S(0)));
      if (!(parting < wanted))
        continue;
      any = true;
      const S push = wanted - parting;
      if (b_air && o_air)
      {
        b.v += S(0.5) * push * c.n;
        o->v -= S(0.5) * push * c.n;
      }
      else if (b_air)
        b.v += push * c.n;
      else
        o->v -= push * c.n;
    }
    if (!any)
      return;
  }
}
}  // namespace

template <typename S>
Ball<S> EventResolver<S>::stateAt(int index, S time) const
{
  const Ball<S>& ball = state_.balls[static_cast<std::size_t>(index)];
  Ball<S> out = evolve(ball, time, params_);
  if (ball.supported() && !(time < ball.piece.until))
    out.v = ball.piece.v_end;  // the contact equations' velocity at the piece's end
  return out;
}

template <typename S>
std::vector<int> EventResolver<S>::supportedGroupOf(int index, S time)
{
  std::vector<int> group;
  if (index < 0 || !state_.balls[static_cast<std::size_t>(index)].supported())
    return group;
  const S reach = S(2) * params_.ball_radius + supportTouch(params_);
  group.push_back(index);
  std::vector<int> near;
  for (std::size_t k = 0; k < group.size(); ++k)
  {
    const Vec3<S> r = stateAt(group[k], time).r;
    nearBalls(r.template head<2>(), reach, near);
    for (int j : near)
    {
      if (!state_.balls[static_cast<std::size_t>(j)].supported() ||
          std::find(group.begin(), group.end(), j) != group.end())
        continue;
      if ((stateAt(j, time).r - r).norm() <= reach)
        group.push_back(j);
    }
  }
  return group;
}

template <typename S>
void EventResolver<S>::cutGroup(int index, S time)
{
  // Between its steps a group follows its pieces, whose energy is the integrated one only to the
  // contact tolerance: brought to an instant within them, it is given no more than it had at their
  // start (what it would gain, its speed pays).
  const std::vector<int> group = supportedGroupOf(index, time);
  std::vector<ContactBody<S>> start, cut;
  for (int j : group)
  {
    const Ball<S>& ball = state_.balls[static_cast<std::size_t>(j)];
    if (!(time < ball.piece.until))
      continue;
    start.push_back({ball.r, ball.v, ball.w, true});
    const Ball<S> then = evolve(ball, time, params_);
    cut.push_back({then.r, then.v, then.w, true});
  }
  const S scale = energyScaleFor(groupEnergy(start, params_), cut, params_);
  for (int j : group)
  {
    Ball<S>& ball = state_.balls[static_cast<std::size_t>(j)];
    if (!(time < ball.piece.until))
      continue;
    ball = evolve(ball, time, params_);
    ball.v *= scale;
    ball.w *= scale;
    ball.piece.v_end = ball.v;
    ball.piece.until = time;
    changed(j);
  }
}

template <typename S>
void EventResolver<S>::dissolveGroup(int index, S time)
{
  for (int j : supportedGroupOf(index, time))
  {
    Ball<S>& ball = state_.balls[static_cast<std::size_t>(j)];
    ball = stateAt(j, time);
    ball.motion = Motion::Airborne;  // settled below: in the air, or on the cloth
    settleMotion(ball, params_.ball_radius);
    changed(j);
  }
}

template <typename S>
void EventResolver<S>::stepGroup(S time, int seed)
{
  const S R = params_.ball_radius, touch = supportTouch(params_);
  // 1. The balls touching the seed, and what touches them in turn through balls in the air or in a
  // group (a ball on the cloth touching them is taken, but not looked around: a rack beside a ball
  // that bears one stays out until it is pushed), with every contact among them and the walls and
  // the slate they touch.
  // A group taken within its pieces (by an event of a ball it touches) is brought to `time` first,
  // with no more energy than its pieces started with.
  cutGroup(seed, time);
  std::vector<int> balls{seed};
  std::vector<Ball<S>> now{stateAt(seed, time)};
  std::vector<ContactLink<S>> links;
  const S mu_ball = engine_.ballBallModel().sustainedFriction(params_);
  const S mu_wall = engine_.cushionModel().sustainedFriction(params_);
  // The cloth's rolling resistance as a couple at the contact: 7/5 mu_roll R lambda, which slows a
  // ball rolling on the slate under its weight at mu_roll g as the closed form does. Rolling against
  // it takes a friction of mu_roll lambda at the contact, which the contact's friction must bear with
  // room for the other loads on the ball: the couple is at most what half that friction bears (as it
  // always is for the coefficients of a real table, mu_roll 0.005-0.015 against 0.1-0.4). The drilling
  // couple likewise turns the slate's spin decay into one.
  const auto rollingFor = [&](S mu) { return S(1.4) * std::min(params_.mu_roll, S(0.5) * mu) * R; };
  const S drilling = S(0.4) * R * R * params_.spinDecel() / params_.gravity;
  std::vector<int> near;
  for (std::size_t k = 0; k < balls.size(); ++k)
  {
    const Ball<S> b = now[k];
    if (k > 0 && !b.airborne() && !b.supported())
      continue;
    nearBalls(b.r.template head<2>(), S(2) * R + touch, near);
    for (int j : near)
    {
      if (j == balls[k] || !state_.balls[static_cast<std::size_t>(j)].inPlay() ||
          std::find(balls.begin(), balls.end(), j) != balls.end() ||
          cannotReach(state_.balls[static_cast<std::size_t>(j)], b.r, S(2) * R + touch, time))
        continue;
      Ball<S> o = stateAt(j, time);
      if (ballContact(b.r, o.r, R).gap > touch)
        continue;
      if (o.supported() && time < state_.balls[static_cast<std::size_t>(j)].piece.until)
      {
        cutGroup(j, time);  // another group's ball, within its pieces
        o = stateAt(j, time);
      }
      balls.push_back(j);
      now.push_back(o);
    }
  }
  const std::vector<Ball<S>> original = now;
  // A ball on the cloth slower than the slide speed is stopped: below it the contact equations'
  // friction is regularized and its closed form's is not, so the two would disagree on where it goes,
  // and it stops within v / (mu_roll g) < 6 ms anyway (less than 2e-7 m further on).
  const S slide_speed = ContactSystem<S>(geometry_, params_).slideSpeed();
  const auto stopIfCreeping = [&](Ball<S>& b) {
    if (!b.airborne() && !b.supported() && b.v.norm() < slide_speed && R * b.w.norm() < slide_speed &&
        (b.v != Vec3<S>::Zero() || b.w != Vec3<S>::Zero()))
    {
      b.v.setZero();
      b.w.setZero();
      b.motion = Motion::Stationary;
    }
  };
  for (std::size_t k = 0; k < balls.size(); ++k)
    stopIfCreeping(now[k]);
  // A ball in the air that has passed over a wall's top has left the playing surface: it leaves the
  // table, as a flight over the cushions does, and the group goes on without it.
  std::vector<char> gone(balls.size(), 0);
  for (std::size_t k = 0; k < balls.size(); ++k)
    if (now[k].airborne() && overTheTop(geometry_, now[k].r))
    {
      gone[k] = 1;
      Ball<S>& ball = state_.balls[static_cast<std::size_t>(balls[k])];
      ball = now[k];
      ball.motion = Motion::Airborne;
      ball.piece = SupportPiece<S>();
      leaveTable(ball);
      changed(balls[k]);
    }
  for (std::size_t k = 0; k < balls.size(); ++k)
    for (std::size_t j = k + 1; j < balls.size(); ++j)
      if (!gone[k] && !gone[j] && ballContact(now[k].r, now[j].r, R).gap <= touch)
        links.push_back(
            {static_cast<int>(k), static_cast<int>(j), -1, Surface::Ball, mu_ball, rollingFor(mu_ball), drilling});
  std::vector<WallTouch> walls;
  for (std::size_t k = 0; k < balls.size(); ++k)
  {
    if (gone[k])
      continue;
    const Vec3<S>& r = now[k].r;
    const int body = static_cast<int>(k);
    if (r.z() - R <= touch)
      links.push_back({body, -1, -1, Surface::Slate, params_.mu_slide, rollingFor(params_.mu_slide), drilling});
    wallsTouching(geometry_, r, R, touch, walls);
    for (const WallTouch& wall : walls)
      links.push_back({body, -1, wall.index, wall.surface, mu_wall, rollingFor(mu_wall), drilling});
  }

  // 2. What meets faster than a sustained contact is an impact (the models' impulses, swept over the
  // group until nothing closes that fast: an arrival at the very end of a step); what closes slower
  // is stopped, frictionless and perfectly inelastic.
  ContactSystem<S> system(geometry_, params_);
  std::vector<ContactBody<S>> bodies(balls.size());
  const auto toBodies = [&] {
    for (std::size_t k = 0; k < balls.size(); ++k)
      bodies[k] = {now[k].r, now[k].v, now[k].w, true, Vec3<S>::Zero(), false};
  };
  toBodies();
  const auto closingOf = [&](const ContactLink<S>& l) {
    return -system.relativeVelocity(l, bodies).dot(system.geometryOf(l, bodies).n);
  };
  for (int sweep = 0; sweep < kImpactSweeps; ++sweep)
  {
    bool any = false;
    for (const ContactLink<S>& l : links)
    {
      if (meetSlowly(closingOf(l)))
        continue;
      any = true;
      Ball<S>& b = now[static_cast<std::size_t>(l.body)];
      const Vec3<S> n = system.geometryOf(l, bodies).n;
      if (l.surface == Surface::Ball)
        impactInAir(now[static_cast<std::size_t>(l.other)], b, n);
      else if (l.surface == Surface::Slate)
        landOnSlate(b, engine_.ballTableModel(), params_);
      else if (l.surface == Surface::Face || l.surface == Surface::PostSide)
      {
        const S vz = b.v.z();
        b.v.z() = S(0);
        wallImpact(b, n);
        b.v.z() = vz;
      }
      else
        b.v -= (S(1) + params_.e_cushion) * b.v.dot(n) * n;  // a nose's edge or a rim, frictionless
      toBodies();
    }
    if (!any)
      break;
  }
  for (int sweep = 0; sweep < kStopSweeps; ++sweep)
  {
    bool any = false;
    for (const ContactLink<S>& l : links)
    {
      // (What closes within rounding is no closing: stopped, it would only stir the balls' rounding.)
      const S closing = closingOf(l);
      const ContactBody<S>& one = bodies[static_cast<std::size_t>(l.body)];
      if (!(closing >
            roundingSpeed(one.v.norm() + (l.other >= 0 ? bodies[static_cast<std::size_t>(l.other)].v.norm() : S(0)))))
        continue;
      const Vec3<S> n = system.geometryOf(l, bodies).n;
      ContactBody<S>& b = bodies[static_cast<std::size_t>(l.body)];
      if (l.other >= 0)
      {
        b.v += S(0.5) * closing * n;
        bodies[static_cast<std::size_t>(l.other)].v -= S(0.5) * closing * n;
      }
      else
        b.v += closing * n;
      any = true;
    }
    if (!any)
      break;
  }

  // 3. The contacts' modes, and who is in the group: a ball with a pressed contact whose balls,
  // linked by pressed contacts, include one in the air.
  // A ball on the cloth that nothing but the slate will press follows its own closed-form path: the
  // mode decision judges its contacts against that path.
  for (std::size_t k = 0; k < balls.size(); ++k)
    if (bodies[k].r.z() - R <= onClothHeight(R))
    {
      Ball<S> free = now[k];
      free.r = bodies[k].r;
      free.v = bodies[k].v;
      free.w = bodies[k].w;
      free.motion = Motion::Airborne;
      settleMotion(free, R);
      const Trajectory<S> path = trajectoryFrom(free, free.time, params_);
      bodies[k].free_on_cloth = true;
      bodies[k].a_free = Vec3<S>(S(2) * path.c2.x(), S(2) * path.c2.y(), S(0));
    }
  std::vector<LinkMode<S>> modes;
  std::vector<BodyRates<S>> rates;
  if (!system.decideModes(bodies, links, modes, rates))
  {
    system.jam(bodies, links);
    system.decideModes(bodies, links, modes, rates);
  }
  // Drift off the pressed contacts taken out, positions and normal velocities. (A stuck slip or turning
  // keeps what is left of it, below the slide speed: taking that out too would take out the friction
  // of the regularized band that let it stick, and stall a pile that is moving.)
  const S energy_before = groupEnergy(bodies, params_);
  system.projectPositions(bodies, links, modes);
  system.projectVelocities(bodies, links, modes, true);
  const S scale_after_projection = energyScaleFor(energy_before, bodies, params_);
  for (ContactBody<S>& b : bodies)
  {
    b.v *= scale_after_projection;
    b.w *= scale_after_projection;
  }
  system.accelerations(bodies, links, modes, rates);
  std::vector<int> parent(balls.size());
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<char> pressed(balls.size(), 0), on_slate(balls.size(), 0);
  for (std::size_t l = 0; l < links.size(); ++l)
  {
    if (!modes[l].pressed)
      continue;
    pressed[static_cast<std::size_t>(links[l].body)] = 1;
    if (links[l].surface == Surface::Slate)
      on_slate[static_cast<std::size_t>(links[l].body)] = 1;
    if (links[l].other >= 0)
    {
      pressed[static_cast<std::size_t>(links[l].other)] = 1;
      parent[static_cast<std::size_t>(rootOf(parent, links[l].body))] = rootOf(parent, links[l].other);
    }
  }
  std::vector<char> held_up(balls.size(), 0);  // by root: the linked balls hold one up in the air
  for (std::size_t k = 0; k < balls.size(); ++k)
    if (pressed[k] && !on_slate[k] && bodies[k].r.z() - R > touch)
      held_up[static_cast<std::size_t>(rootOf(parent, static_cast<int>(k)))] = 1;
  std::vector<char> member(balls.size(), 0);
  bool any_member = false, at_rest = true;
  const S rest_speed = S(kSettleSpeed), rest_acceleration = S(kRestShare) * params_.gravity;
  for (std::size_t k = 0; k < balls.size(); ++k)
  {
    member[k] = pressed[k] && held_up[static_cast<std::size_t>(rootOf(parent, static_cast<int>(k)))];
    if (!member[k])
      continue;
    any_member = true;
    at_rest = at_rest && bodies[k].v.norm() <= rest_speed && R * bodies[k].w.norm() <= rest_speed &&
              rates[k].a.norm() <= rest_acceleration && R * rates[k].alpha.norm() <= rest_acceleration;
  }

  // 4. Write back: the balls the impacts or the stops changed, those that leave the group, and the
  // group at rest; else the next step.
  const auto writeFree = [&](std::size_t k) {
    Ball<S> b = now[k];
    b.r = bodies[k].r;
    b.v = bodies[k].v;
    b.w = bodies[k].w;
    b.time = time;
    if (b.held() && (b.v != Vec3<S>::Zero() || b.w != Vec3<S>::Zero()))
      b.motion = Motion::Airborne;
    if (!b.held())
    {
      b.motion = Motion::Airborne;
      settleMotion(b, R);
      // A slip inside the band where the group's friction is regularized was stuck there: it leaves
      // rolling, that slip taken out as the cloth takes it at the end of a slide (applyTransition), or
      // its closed form would slide on for a few microseconds the group did not.
      if (b.motion == Motion::Sliding && slipVelocity(b.v, b.w, R).norm() < system.slideSpeed())
        applyTransition(b, params_);
      stopIfCreeping(b);
    }
    if (gone[k])
      return;
    if (b.motion != original[k].motion || b.v != original[k].v || b.w != original[k].w || b.r != original[k].r ||
        state_.balls[static_cast<std::size_t>(balls[k])].supported())
    {
      state_.balls[static_cast<std::size_t>(balls[k])] = b;
      changed(balls[k]);
    }
  };
  if (!any_member)
  {
    partGrazes(system, bodies, links, R);
  }
  if (!any_member || at_rest)
  {
    for (std::size_t k = 0; k < balls.size(); ++k)
    {
      if (member[k])
      {
        Ball<S>& b = state_.balls[static_cast<std::size_t>(balls[k])];
        b = now[k];
        b.time = time;
        b.r = bodies[k].r;
        b.v.setZero();
        b.w.setZero();
        b.piece = SupportPiece<S>();
        b.motion = on_slate[k] ? Motion::Stationary : Motion::Held;
        if (on_slate[k])
          b.r.z() = R;
        changed(balls[k]);
      }
      else
        writeFree(k);
    }
    return;
  }
  for (std::size_t k = 0; k < balls.size(); ++k)
    if (!member[k])
      writeFree(k);

  // The step: the group's balls move by the equations; the others touching them follow their own paths.
  std::vector<ContactLink<S>> step_links;
  std::vector<LinkMode<S>> step_modes;
  for (std::size_t l = 0; l < links.size(); ++l)
    if (member[static_cast<std::size_t>(links[l].body)] ||
        (links[l].other >= 0 && member[static_cast<std::size_t>(links[l].other)]))
    {
      step_links.push_back(links[l]);
      step_modes.push_back(modes[l]);
    }
  S longest = S(kLongestStep) * supportTime(params_);
  for (std::size_t k = 0; k < balls.size(); ++k)
  {
    bodies[k].dynamic = member[k] != 0;
    if (!member[k])
    {
      // Its own path holds until its next transition: the step ends there at the latest.
      const Ball<S>& free = state_.balls[static_cast<std::size_t>(balls[k])];
      if (free.moving())
        longest = std::min(longest, std::max(free.time + timeToTransition(free, params_) - time, S(0)));
    }
  }
  const KinematicPaths<S> paths = [&](S tau, std::vector<ContactBody<S>>& y) {
    for (std::size_t k = 0; k < balls.size(); ++k)
      if (!member[k])
      {
        const Ball<S> b = evolve(state_.balls[static_cast<std::size_t>(balls[k])], time + tau, params_);
        y[k].r = b.r;
        y[k].v = b.v;
        y[k].w = b.w;
      }
  };
  const Ball<S>& first = state_.balls[static_cast<std::size_t>(seed)];
  const S last = first.supported() ? first.piece.until - first.time : S(0);
  const S trial = std::max(S(2) * last, S(kFirstStep) * supportTime(params_));
  if (!(longest > S(0)))
    longest = S(kFirstStep) * supportTime(params_);
  SupportStep<S> step =
      stepSupported(system, bodies, step_links, step_modes, paths, trial, longest, params_.contact_tolerance);
  // Energy is never gained: what the integration's error would add, the group's speed pays.
  std::vector<ContactBody<S>> start_members, end_members;
  for (std::size_t k = 0; k < balls.size(); ++k)
    if (member[k])
    {
      start_members.push_back(bodies[k]);
      end_members.push_back(step.end[k]);
    }
  const S scale = energyScaleFor(groupEnergy(start_members, params_), end_members, params_);
  std::size_t d = 0;
  for (std::size_t k = 0; k < balls.size(); ++k)
  {
    if (!member[k])
      continue;
    Ball<S>& b = state_.balls[static_cast<std::size_t>(balls[k])];
    b = now[k];
    b.time = time;
    b.r = bodies[k].r;
    b.v = bodies[k].v;
    b.w = bodies[k].w;
    b.pocket = -1;
    b.motion = on_slate[k] ? Motion::Bearing : Motion::Supported;
    b.piece.a = step.a[d];
    b.piece.v_end = scale * step.end[k].v;
    b.piece.alpha = (scale * step.end[k].w - bodies[k].w) / step.h;
    b.piece.until = time + step.h;
    if (on_slate[k])
    {
      // On the cloth, exactly: the slate's contact keeps z = R and v_z = 0.
      b.r.z() = R;
      b.v.z() = b.piece.a.z() = b.piece.v_end.z() = S(0);
    }
    ++d;
    changed(balls[k]);
  }
}

#define CUE_SIM_INSTANTIATE_SUPPORT_GROUPS(S)                                                                          \
  template Ball<S> EventResolver<S>::stateAt(int, S) const;                                                            \
  template std::vector<int> EventResolver<S>::supportedGroupOf(int, S);                                                \
  template void EventResolver<S>::cutGroup(int, S);                                                                    \
  template void EventResolver<S>::dissolveGroup(int, S);                                                               \
  template void EventResolver<S>::stepGroup(S, int);
CUE_SIM_INSTANTIATE_SUPPORT_GROUPS(double)
CUE_SIM_INSTANTIATE_SUPPORT_GROUPS(long double)

}  // namespace physics
}  // namespace cue_sim

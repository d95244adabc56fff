// The event engine on stiff and extreme cases (issue 4): every case ends, stays finite, never
// overlaps or enters a cushion beyond 1e-9 m, never gains energy at an event, conserves
// momentum at ball-ball events, and keeps symmetric scenes symmetric.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

#include "cue_sim/physics/engine.hpp"
#include "cue_sim/physics/motion.hpp"
#include "cue_sim/physics/rack.hpp"
#include "cue_sim/physics/scan.hpp"
#include "cue_sim/physics/simulation.hpp"
#include "invariants.hpp"

using namespace cue_sim::physics;

namespace
{
std::shared_ptr<const TableModel> sevenFoot()
{
  static const auto table = std::make_shared<const TableModel>(TableModel::pool("7ft", 1.9812, 0.9906, 0.118, 0.137));
  return table;
}

std::shared_ptr<const TableModel> carom()
{
  static const auto table = std::make_shared<const TableModel>(TableModel::carom("carom", 2.84, 1.42));
  return table;
}

Ball<double> ball(int id, double x, double y, double vx, double vy, const PhysicsParams<double>& p)
{
  Ball<double> b;
  b.id = id;
  b.r = Vec3<double>(x, y, p.ball_radius);
  b.v = Vec3<double>(vx, vy, 0);
  settleMotion(b, p.ball_radius);
  return b;
}

TableState<double> breakShot(const Engine<double>& engine, double speed, double gap = 1e-5)
{
  RackOptions options;
  options.gap = gap;
  TableState<double> s = rackLayout<double>("eight", engine.table(), engine.params().ball_radius, options);
  CueStrike<double> cue;
  cue.speed = speed;
  engine.strike(s, 0, cue);
  return s;
}

/// Runs to rest checking every invariant; returns the number of events.
int runChecked(const Engine<double>& engine, TableState<double>& s, int max_events = 20000)
{
  const int events = checkInvariantsEventByEvent(engine, s, max_events);
  EXPECT_FALSE(s.anyMoving()) << "still moving after " << events << " events";
  EXPECT_EQ(engine.whyInvalid(s), "");
  return events;
}
}  // namespace

TEST(Stability, StiffFrictionSlidesForMicroseconds)
{
  for (double mu : {0.2, 2.0, 10.0, 50.0})
  {
    PhysicsParams<double> p;
    p.mu_slide = mu;
    const Engine<double> engine(sevenFoot(), p);
    TableState<double> single;
    single.balls.push_back(ball(0, -0.5, 0.1, 0, 0, p));
    CueStrike<double> cue;
    cue.speed = 3.0;
    cue.phi = 0.4;
    cue.b = -0.3;
    engine.strike(single, 0, cue);
    EXPECT_NEAR(timeToTransition(single.balls[0], p) * mu,
                timeToTransition(single.balls[0], PhysicsParams<double>()) * 0.2, 1e-12)
        << "sliding time scales as 1/mu";
    runChecked(engine, single);
    TableState<double> rack = breakShot(engine, 8.0);
    runChecked(engine, rack);
  }
}

TEST(Stability, FrictionlessClothStopsAtTheSetTime)
{
  PhysicsParams<double> p;
  p.mu_slide = p.mu_roll = p.mu_spin = 0;
  EngineLimits limits;
  limits.max_shot_time = 5.0;
  const Engine<double> engine(carom(), p, {}, limits);
  TableState<double> s;
  s.balls.push_back(ball(0, -0.5, 0.1, 2.0, 1.3, p));
  s.balls.push_back(ball(1, 0.3, -0.2, 0, 0, p));
  const ShotResult<double> result = simulateToRest(engine, s);
  EXPECT_FALSE(result.at_rest);
  EXPECT_DOUBLE_EQ(s.time, 5.0);
  EXPECT_TRUE(s.anyMoving());
  EXPECT_EQ(engine.whyInvalid(s), "");
}

TEST(Stability, TinyAndHugeSpeeds)
{
  const PhysicsParams<double> p;
  const Engine<double> engine(sevenFoot(), p);
  TableState<double> tiny;
  tiny.balls.push_back(ball(0, 0.1, 0.1, 1e-9, -1e-9, p));
  EXPECT_LE(runChecked(engine, tiny), 3);
  EXPECT_NEAR(tiny.balls[0].r.x(), 0.1, 1e-12);
  TableState<double> hard = breakShot(engine, CueLimits::max_speed);
  runChecked(engine, hard);
  TableState<double> thrown = rackLayout<double>("eight", engine.table(), p.ball_radius);
  thrown.balls[0].v = Vec3<double>(50.0, 0.0003, 0);  // given directly, beyond any cue
  settleMotion(thrown.balls[0], p.ball_radius);
  runChecked(engine, thrown);
}

/// An 8-ball break with this ball-ball restitution, in every ball-ball model, checked at every
/// event.
void breakWithBallRestitution(double e_ball)
{
  PhysicsParams<double> p;
  p.e_ball = e_ball;
  for (const std::string& model : ballBallModelNames())
  {
    const Engine<double> engine(sevenFoot(), p, {model, "han2005"});
    TableState<double> s = breakShot(engine, 8.0);
    runChecked(engine, s);
  }
}

TEST(Stability, BallRestitutionOne)
{
  breakWithBallRestitution(1.0);
}

// e_ball = 0 leaves the balls of a break pressed together in lines and against cushions:
// inelastic collapse, which the joining of pressed clusters and the holding of balls on walls
// must end.
TEST(Stability, BallRestitutionZero)
{
  breakWithBallRestitution(0.0);
}

TEST(Stability, CushionRestitutionOne)
{
  PhysicsParams<double> p;
  p.e_cushion = p.e_cushion_work = 1.0;
  for (const std::string& model : cushionModelNames())
  {
    const Engine<double> engine(sevenFoot(), p, {"frictional", model});
    TableState<double> s = breakShot(engine, 8.0);
    runChecked(engine, s);
  }
}

TEST(Stability, CushionRestitutionZero)
{
  for (const double e_ball : {0.95, 0.0})
    for (const std::string& ball_model : ballBallModelNames())
      for (const std::string& cushion_model : cushionModelNames())
      {
        SCOPED_TRACE("e_ball " + std::to_string(e_ball) + ", " + ball_model + ", " + cushion_model);
        PhysicsParams<double> p;
        p.e_cushion = p.e_cushion_work = 0.0;
        p.e_ball = e_ball;
        const Engine<double> engine(sevenFoot(), p, {ball_model, cushion_model});
        TableState<double> s = breakShot(engine, 8.0);
        runChecked(engine, s);
      }
}

TEST(Stability, RandomBreaksWithLittleRestitutionEnd)
{
  // Low restitution makes inelastic collapse common: balls pressed into lines, clusters and
  // against cushions, and contacts closing within rounding of zero. Random breaks, every model
  // pair, e from 0 up, random rack gaps, speeds and English, each checked at every event.
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int k = 0; k < 160; ++k)
  {
    PhysicsParams<double> p;
    p.e_ball = k % 3 == 0 ? 0.0 : 0.5 * unit(rng);
    p.e_cushion = p.e_cushion_work = k % 2 == 0 ? 0.0 : 0.5 * unit(rng);
    const std::vector<std::string> balls = ballBallModelNames(), cushions = cushionModelNames();
    const ModelChoice models{balls[k % balls.size()], cushions[(k / balls.size()) % cushions.size()]};
    SCOPED_TRACE("shot " + std::to_string(k) + ": e_ball " + std::to_string(p.e_ball) + ", e_cushion " +
                 std::to_string(p.e_cushion) + ", " + models.ball_ball + ", " + models.cushion);
    const Engine<double> engine(sevenFoot(), p, models);
    RackOptions options;
    options.gap = 1e-4 * unit(rng);
    TableState<double> s = rackLayout<double>(k % 5 ? "eight" : "nine", engine.table(), p.ball_radius, options);
    CueStrike<double> cue;
    cue.speed = 1.0 + 11.0 * unit(rng);
    cue.phi = 0.2 * (unit(rng) - 0.5);
    cue.theta = 0.3 * unit(rng);
    cue.a = 0.6 * (unit(rng) - 0.5);
    cue.b = 0.6 * (unit(rng) - 0.5);
    if (std::hypot(cue.a, cue.b) > 0.5)
      cue.a = cue.b = 0.0;
    engine.strike(s, 0, cue);
    runChecked(engine, s, 5000);
    if (HasFailure())
      break;
  }
}

TEST(Stability, SpinHoldsADeadBallOnTheCushion)
{
  // With e_cushion = 0 a ball with follow, driven straight into a cushion at an angle, keeps
  // no normal speed, and its follow keeps pressing it into the cushion through cloth
  // friction. It must stay on the cushion, sliding along it, never inside, until it stops.
  PhysicsParams<double> p;
  p.e_cushion = p.e_cushion_work = 0.0;
  const double hy = 1.42 / 2;
  for (const std::string& model : cushionModelNames())
  {
    const Engine<double> engine(carom(), p, {"frictional", model});
    TableState<double> s;
    s.balls.push_back(ball(0, 0.0, hy - 0.3, 0, 0, p));
    CueStrike<double> cue;
    cue.speed = 2.0;
    cue.phi = 1.2;  // into the top cushion, 21 degrees off its normal
    cue.b = 0.4;    // follow
    engine.strike(s, 0, cue);
    Event<double> hit;
    while (hit.kind != EventKind::BallCushion)
      hit = scanStep(engine, s);
    const double y_on_cushion = hy - p.ball_radius;
    runChecked(engine, s);
    EXPECT_NEAR(s.balls[0].r.y(), y_on_cushion, 1e-9) << model << ": it stops on the cushion";
    EXPECT_GT(s.balls[0].r.x(), 0.1) << model << ": after sliding along it";
  }
}

TEST(Stability, ALinePressedTogetherIsJoinedAtOnce)
{
  // Three touching balls moving together along x: the rear one has follow and speeds up, the
  // middle and front are stunned and slow down. Joining only the pressed pair would slow it
  // against the front ball, which would be joined next, then the pair again, without end.
  const PhysicsParams<double> p;
  const Engine<double> engine(carom(), p, {"frictionless", "simple"});
  const double R = p.ball_radius;
  TableState<double> s;
  for (int i = 0; i < 3; ++i)
    s.balls.push_back(ball(i, -0.5 + 2 * R * i, 0.0, 0.5, 0.0, p));
  s.balls[0].w.y() = 3 * 0.5 / R;  // follow: the slip points backwards, friction forwards
  settleMotion(s.balls[0], R);
  const int events = runChecked(engine, s);
  EXPECT_LE(events, 10);
  EXPECT_NEAR(s.balls[1].r.x() - s.balls[0].r.x(), 2 * R, 1e-9) << "still touching";
  EXPECT_NEAR(s.balls[2].r.x() - s.balls[1].r.x(), 2 * R, 1e-9) << "still touching";
}

TEST(Stability, FrozenRackBrokenAtFullSpeed)
{
  const PhysicsParams<double> p;
  const Engine<double> engine(sevenFoot(), p);
  TableState<double> s = breakShot(engine, CueLimits::max_speed, 0.0);
  runChecked(engine, s);
}

TEST(Stability, NewtonsCradleOfEightTouchingBalls)
{
  // Frictionless, e = 1, a stun cue ball into a line of eight frozen balls: the whole velocity
  // passes down the line to the last ball, the others stay (as near as the cloth allows).
  PhysicsParams<double> p;
  p.e_ball = 1.0;
  const Engine<double> engine(sevenFoot(), p, {"frictionless", "simple"});
  TableState<double> s;
  s.balls.push_back(ball(0, -0.3 - 2 * p.ball_radius - 1e-6, 0, 1.0, 0, p));  // about to hit, no spin yet
  for (int i = 1; i <= 8; ++i)
    s.balls.push_back(ball(i, -0.3 + 2 * p.ball_radius * (i - 1), 0, 0, 0, p));
  double impact_speed = NAN;
  while (true)
  {
    const Event<double> e = scanNextEvent(engine, s);
    if (e.kind != EventKind::BallBall)
      break;
    if (std::isnan(impact_speed))
      impact_speed = engine.ballAt(s, 0, e.time).v.x();  // after sliding its 1e-6 m
    scanStep(engine, s);
  }
  for (int i = 0; i < 8; ++i)
    EXPECT_NEAR(s.balls[i].v.x(), 0.0, 1e-12) << "ball " << i;
  EXPECT_NEAR(s.balls[8].v.x(), impact_speed, 1e-12);
  runChecked(engine, s);
}

TEST(Stability, FrozenToACushionStruckIntoItAndAlongIt)
{
  const PhysicsParams<double> p;
  const Engine<double> engine(carom(), p);
  const double hy = 1.42 / 2;
  for (double heading : {M_PI / 2, 0.0, M_PI / 2 - 1e-3})
  {
    TableState<double> s;
    s.balls.push_back(ball(0, 0.0, hy - p.ball_radius, 0, 0, p));  // touching the top cushion
    ASSERT_EQ(engine.whyInvalid(s), "");
    CueStrike<double> cue;
    cue.speed = 2.0;
    cue.phi = heading;
    engine.strike(s, 0, cue);
    runChecked(engine, s);
  }
}

TEST(Stability, CornerAtFortyFiveDegreesHitsBothCushions)
{
  // On the carom table the corner is a right angle: the ball touches both cushions at once, and
  // meets them as one impact (EventResolver::cornerImpact): one event, after which it closes on
  // neither.
  PhysicsParams<double> p;
  const Engine<double> engine(carom(), p, {"frictionless", "simple"});
  const double hx = 2.84 / 2 - p.ball_radius, hy = 1.42 / 2 - p.ball_radius;
  TableState<double> s;
  s.balls.push_back(ball(0, hx - 0.3, hy - 0.3, 1.0, 1.0, p));
  s.balls[0].w = Vec3<double>(-1.0, 1.0, 0) / p.ball_radius;  // rolling, no slip
  settleMotion(s.balls[0], p.ball_radius);
  const Event<double> first = scanStep(engine, s);
  EXPECT_EQ(first.kind, EventKind::BallCushion);
  const Vec3<double> v = s.balls[0].v;
  const Event<double> second = scanStep(engine, s);
  EXPECT_GT(second.time, first.time + 0.1);  // nothing more in the corner
  EXPECT_LT(v.x(), 0);
  EXPECT_LT(v.y(), 0);
  EXPECT_NEAR(v.x(), v.y(), 1e-12) << "straight back out of the corner";
  runChecked(engine, s);
}

TEST(Stability, ABallSpunIntoACornerMeetsBothCushionsAsOneImpact)
{
  // A ball in a carom table's corner, spun so that friction at one cushion drives it into the
  // other (mu_cushion 4.6, side and running spin, the cloth frictionless or nearly): met one
  // cushion at a time it went from one to the other every 25 ns for ever (soak seed 12, shot
  // 39701: 3 million events in 5 ms). Every cushion model, spins every way.
  std::mt19937 rng(53);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (const std::string& model : cushionModelNames())
    for (const double mu_slide : {0.0, 1e-3})
      for (int k = 0; k < 24; ++k)
      {
        SCOPED_TRACE(model + ", mu_slide " + std::to_string(mu_slide) + ", spin " + std::to_string(k));
        PhysicsParams<double> p;
        if (k % 2 == 0)  // shot 39701's balls and nose, and the standard
        {
          p.ball_radius = 0.0011304;
          p.cushion_height = 0.00176042;
          p.e_cushion_work = 5.2e-4;
        }
        p.mu_slide = mu_slide;
        p.mu_cushion = 4.6;
        p.e_cushion = 0.155;
        p.e_cushion_work = 0.155;
        const Engine<double> engine(carom(), p, {"frictionless", model});
        const double hx = 2.84 / 2 - p.ball_radius, hy = 1.42 / 2 - p.ball_radius;
        TableState<double> s;
        // Touching both, closing on one (at shot 39701's 1.9e-9 m/s) or both.
        const double closing = k < 12 ? 1.877e-9 : 1e-3;
        s.balls.push_back(ball(0, -hx, hy, -closing, k % 3 == 0 ? 0.0 : closing, p));
        // The first as in shot 39701 (running spin 22 rad/s, side 15 rad/s); then any.
        s.balls[0].w = k == 0 ? Vec3<double>(0, 22.17, 14.88) : Vec3<double>(unit(rng), unit(rng), unit(rng)) * 25.0;
        settleMotion(s.balls[0], p.ball_radius);
        ASSERT_EQ(engine.whyInvalid(s), "");
        Simulation<double> simulation(engine, s);
        int events = 0;
        while (!simulation.atRest() && simulation.time() < 1.0 && events < 1000)
        {
          if (!simulation.step(1.0).valid())
            break;
          ++events;
        }
        EXPECT_LT(events, 100);
        const Ball<double>& b = simulation.state().balls[0];
        EXPECT_TRUE(b.v.allFinite());
        EXPECT_GE(b.v.x(), -1e-12);  // out of the corner, or still in it: not through a cushion
        EXPECT_LE(b.v.y(), 1e-12);
        EXPECT_EQ(engine.whyInvalid(simulation.state()), "");
      }
}

TEST(Stability, BallsWedgedAcrossTheTableSlideAlongItsCushionsAsOne)
{
  // Two large balls touching each other, one on each long cushion, wedged across the table,
  // sliding along it together with any spin: the walls hold them both ways, so their slip
  // across is taken out. Held against one wall at a time, the slip was left a few ulps into the
  // other, and the pair was pressed into it again within nanoseconds, hundreds of times (soak
  // seed 12, shot 19678, whose balls, 0.69 m across on the 9 ft table, made 3 million events in
  // 0.65 s). Every model pair, spins every way, on tables whose cushions lie on their axes.
  std::mt19937 rng(19678);
  std::uniform_real_distribution<double> unit(-1, 1);
  const auto nine_foot = std::make_shared<const TableModel>(TableModel::pool("9ft", 2.54, 1.27, 0.118, 0.137));
  for (const std::string& ball_ball : ballBallModelNames())
    for (const std::string& cushion : cushionModelNames())
      for (int k = 0; k < 8; ++k)
      {
        SCOPED_TRACE(ball_ball + "/" + cushion + ", case " + std::to_string(k));
        const bool on_carom = k % 2 == 1;
        PhysicsParams<double> p;
        p.ball_radius = on_carom ? 0.4 : 0.34709503521035645;
        p.cushion_height = 2 * p.ball_radius - 0.0017;
        p.mu_ball_b = k < 4 ? 10.0 : p.mu_ball_b;  // shot 19678's grip between the balls
        p.e_cushion = 0.0152;
        const Engine<double> engine(on_carom ? carom() : nine_foot, p, {ball_ball, cushion});
        const double width = on_carom ? 1.42 : 1.27;
        const double dy = width - 2 * p.ball_radius, dx = std::sqrt(4 * p.ball_radius * p.ball_radius - dy * dy);
        // Up to 0.2 m/s, on the cushions' middle: they stop short of a pocket's jaws.
        const double speed = 0.1 * (1 + unit(rng)) * (k % 4 < 2 ? 1 : -1), x = on_carom ? 0.1 : -0.6;
        TableState<double> s;
        s.balls.push_back(ball(0, x + dx / 2, width / 2 - p.ball_radius, speed, 0, p));
        s.balls.push_back(ball(1, x - dx / 2, -width / 2 + p.ball_radius, speed, 0, p));
        for (Ball<double>& b : s.balls)
        {
          b.w = Vec3<double>(unit(rng), unit(rng), unit(rng)) * 2.0;
          settleMotion(b, p.ball_radius);
        }
        ASSERT_EQ(engine.whyInvalid(s), "");
        // Energy never gained, no overlap, nothing in a cushion or a jaw, to rest in a few events.
        EXPECT_LT(checkInvariantsEventByEvent(engine, s, 1000), 100);
        EXPECT_EQ(engine.whyInvalid(s), "");
      }
}

TEST(Stability, GrazingAJawAndRollingAlongACushion)
{
  // A ball rolling along the top cushion past the side pocket: its path is tangent to both of
  // the pocket's jaws (to within +-1e-12 m) and passes under the capture circle.
  const PhysicsParams<double> p;
  const Engine<double> engine(sevenFoot(), p);
  const auto& circles = engine.table().circles();
  const auto jaw = std::find_if(circles.begin(), circles.end(),
                                [](const CircularCushion& c) { return c.name == "jaw_side_ypos_foot"; });
  ASSERT_NE(jaw, circles.end());
  for (double miss : {0.0, 1e-12, -1e-12})
  {
    TableState<double> s;
    const double y = jaw->centre.y() - (p.ball_radius + jaw->radius + miss);
    // Rolling at 0.5 m/s it stops after v^2 / (2 mu_r g) = 1.27 m, short of the corner pocket.
    s.balls.push_back(ball(0, 0.4, y, -0.5, 0, p));
    s.balls[0].w = Vec3<double>(0, -0.5 / p.ball_radius, 0);
    settleMotion(s.balls[0], p.ball_radius);
    ASSERT_EQ(engine.whyInvalid(s), "") << "miss " << miss;
    runChecked(engine, s);
    EXPECT_TRUE(s.balls[0].inPlay()) << "miss " << miss << ": it rolls past the pocket";
    EXPECT_LT(s.balls[0].r.x(), -jaw->centre.x() - p.ball_radius) << "miss " << miss;
  }
  // Rolling exactly along the top cushion, touching it.
  const double hy = 0.9906 / 2;
  TableState<double> along;
  along.balls.push_back(ball(0, -0.6, hy - p.ball_radius, 0.8, 0, p));
  along.balls[0].w = Vec3<double>(0, 0.8 / p.ball_radius, 0);
  settleMotion(along.balls[0], p.ball_radius);
  runChecked(engine, along);
}

TEST(Stability, ExactlySimultaneousCollisionsStaySymmetric)
{
  // A cue ball straight between two object balls placed symmetrically: it meets both at the
  // same instant, and the outcome must mirror about the line of the shot.
  const PhysicsParams<double> p;
  const Engine<double> engine(sevenFoot(), p);
  const double R = p.ball_radius;
  TableState<double> s;
  s.balls.push_back(ball(0, -0.5, 0, 0, 0, p));
  s.balls.push_back(ball(1, 0.0, R * 1.0, 0, 0, p));
  s.balls.push_back(ball(2, 0.0, -R * 1.0, 0, 0, p));
  CueStrike<double> cue;
  cue.speed = 2.0;
  engine.strike(s, 0, cue);
  runChecked(engine, s);
  const Vec3<double> a = s.balls[1].r, b = s.balls[2].r;
  EXPECT_NEAR(a.x(), b.x(), 1e-9);
  EXPECT_NEAR(a.y(), -b.y(), 1e-9);
  EXPECT_NEAR(s.balls[0].r.y(), 0.0, 1e-9);
}

TEST(Stability, StateJustBeforeACollision)
{
  // 1e-15 s before two balls meet: the contact is found, not skipped or doubled.
  const PhysicsParams<double> p;
  const Engine<double> engine(sevenFoot(), p);
  TableState<double> s;
  s.balls.push_back(ball(0, 0.0, 0.0, 1.0, 0, p));
  s.balls.push_back(ball(1, 2 * p.ball_radius + 1e-15, 0.0, 0, 0, p));
  const Event<double> first = scanNextEvent(engine, s);
  ASSERT_EQ(first.kind, EventKind::BallBall);
  EXPECT_LT(first.time, 1e-14);
  runChecked(engine, s);
  EXPECT_GT(s.balls[1].r.x(), 0.1);  // the hit happened once and sent ball 1 on
}

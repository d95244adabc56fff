// The event loop on whole shots: cushions, pockets, breaks, and the invariants at every event.
#include <gtest/gtest.h>

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
  return std::make_shared<const TableModel>(TableModel::pool("7ft", 1.9812, 0.9906, 0.118, 0.137));
}

Ball<double> rollingBall(int id, double x, double y, double speed, double heading, const PhysicsParams<double>& p)
{
  Ball<double> b;
  b.id = id;
  b.r = Vec3<double>(x, y, p.ball_radius);
  b.v = speed * Vec3<double>(std::cos(heading), std::sin(heading), 0);
  b.w = Vec3<double>(-b.v.y(), b.v.x(), 0) / p.ball_radius;
  settleMotion(b, p.ball_radius);
  return b;
}

}  // namespace

TEST(Engine, RollingBallHitsTheFootCushionWhereTheFormulaSays)
{
  const PhysicsParams<double> p;
  Engine<double> engine(sevenFoot(), p, {"frictionless", "simple"});
  const double v0 = 1.5, heading = 0.3, x0 = 0.2, y0 = -0.1;
  TableState<double> s;
  s.balls.push_back(rollingBall(0, x0, y0, v0, heading, p));
  const Event<double> ev = scanNextEvent(engine, s);
  ASSERT_EQ(ev.kind, EventKind::BallCushion);
  EXPECT_EQ(engine.table().segments()[ev.obstacle].name, "cushion_foot");
  // Travel along the heading to x = L/2 - R, decelerating at mu_r g.
  const double distance = (1.9812 / 2 - p.ball_radius - x0) / std::cos(heading);
  const double a = p.mu_roll * p.gravity;
  const double t_hit = (v0 - std::sqrt(v0 * v0 - 2 * a * distance)) / a;
  EXPECT_NEAR(ev.time, t_hit, 1e-12);
  const Ball<double> before = engine.ballAt(s, 0, ev.time);
  advance(engine, s, ev.time);
  const Ball<double>& after = s.balls[0];
  EXPECT_NEAR(after.v.x(), -p.e_cushion * before.v.x(), 1e-12);
  EXPECT_NEAR(after.v.y(), before.v.y(), 1e-12);
  EXPECT_EQ(after.motion, Motion::Sliding);  // its roll no longer matches its velocity
}

TEST(Engine, BallAimedAtACornerIsPocketedAndLeavesPlay)
{
  const PhysicsParams<double> p;
  Engine<double> engine(sevenFoot(), p);
  TableState<double> s;
  const double heading = std::atan2(0.9906 / 2 - 0.1, 1.9812 / 2 - 0.3);
  s.balls.push_back(rollingBall(3, 0.3, 0.1, 2.0, heading, p));
  s.balls.push_back(rollingBall(4, -0.5, 0.0, 0.0, 0, p));
  const ShotResult<double> result = simulateToRest(engine, s);
  ASSERT_TRUE(result.at_rest);
  ASSERT_EQ(result.events.size(), 1u);
  EXPECT_EQ(result.events[0].kind, EventKind::Pocketed);
  EXPECT_EQ(engine.table().pockets()[result.events[0].obstacle].name, "pocket_foot_ypos");
  const Ball<double>& b = s.balls[0];
  EXPECT_EQ(b.motion, Motion::Pocketed);
  EXPECT_LT(b.r.z(), 0);  // below the cloth
  EXPECT_FALSE(b.inPlay());
}

TEST(Engine, BreakKeepsEveryInvariantAtEveryEvent)
{
  const PhysicsParams<double> p;
  Engine<double> engine(sevenFoot(), p);
  TableState<double> s = rackLayout<double>("eight", engine.table(), p.ball_radius);
  ASSERT_EQ(engine.whyInvalid(s), "");
  CueStrike<double> cue;
  cue.speed = 8.0;
  engine.strike(s, 0, cue);
  const int events = checkInvariantsEventByEvent(engine, s);
  EXPECT_GT(events, 40);
  EXPECT_FALSE(s.anyMoving());
  EXPECT_EQ(engine.whyInvalid(s), "");
}

TEST(Engine, NoOverlapBetweenEvents)
{
  const PhysicsParams<double> p;
  Engine<double> engine(sevenFoot(), p);
  TableState<double> s = rackLayout<double>("nine", engine.table(), p.ball_radius);
  CueStrike<double> cue;
  cue.speed = 6.0;
  cue.phi = 0.01;
  engine.strike(s, 0, cue);
  for (double t = 0.0005; t < 3.0; t += 0.0005)
  {
    advance(engine, s, t);
    ASSERT_GT(smallestGap(engine, s, t), -1e-9) << "t = " << t;
  }
}

TEST(Engine, ResultDoesNotDependOnHowOftenItIsAdvanced)
{
  const PhysicsParams<double> p;
  Engine<double> engine(sevenFoot(), p);
  TableState<double> once = rackLayout<double>("eight", engine.table(), p.ball_radius);
  CueStrike<double> cue;
  cue.speed = 7.0;
  cue.phi = -0.004;
  engine.strike(once, 0, cue);
  TableState<double> stepped = once;
  const ShotResult<double> whole = simulateToRest(engine, once);
  std::vector<Event<double>> events;
  for (double t = 0.01; stepped.anyMoving(); t += 0.01)
    advance(engine, stepped, t, &events);
  ASSERT_EQ(events.size(), whole.events.size());
  for (std::size_t i = 0; i < events.size(); ++i)
  {
    EXPECT_EQ(events[i].time, whole.events[i].time) << i;  // bit for bit
    EXPECT_EQ(events[i].kind, whole.events[i].kind) << i;
  }
  for (std::size_t i = 0; i < once.balls.size(); ++i)
    EXPECT_EQ(once.balls[i].r, stepped.balls[i].r) << "ball " << once.balls[i].id;
}

TEST(Engine, ThousandsOfRandomShotsKeepTheInvariantsInEveryModel)
{
  const PhysicsParams<double> p;
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> heading(-M_PI, M_PI), speed(0.2, 10.0), x(-0.9, -0.3), y(-0.45, 0.45),
      unit(-1.0, 1.0), elevation(0.0, 0.6);
  int shots = 0;
  for (const std::string& ball_ball : ballBallModelNames())
    for (const std::string& cushion : cushionModelNames())
    {
      Engine<double> engine(sevenFoot(), p, {ball_ball, cushion});
      for (int shot = 0; shot < 500; ++shot, ++shots)
      {
        TableState<double> s = rackLayout<double>(shot % 2 ? "eight" : "nine", engine.table(), p.ball_radius);
        s.balls[0].r.x() = x(rng);
        s.balls[0].r.y() = y(rng);
        CueStrike<double> cue;
        cue.speed = speed(rng);
        cue.phi = heading(rng);
        cue.theta = elevation(rng);
        cue.a = 0.35 * unit(rng);
        cue.b = 0.35 * unit(rng);
        engine.strike(s, 0, cue);
        checkInvariantsEventByEvent(engine, s);
        EXPECT_FALSE(s.anyMoving()) << ball_ball << "/" << cushion << " shot " << shot;
      }
    }
  EXPECT_EQ(shots, 500 * static_cast<int>(ballBallModelNames().size() * cushionModelNames().size()));
}

TEST(Engine, FrozenBallsPassTheImpulseOn)
{
  // Two balls touching, the first hit straight into the second: with e = 1 the first stops
  // dead and the second takes its whole velocity (the contact is found at tau = 0).
  PhysicsParams<double> p;
  p.e_ball = 1.0;
  Engine<double> engine(sevenFoot(), p, {"frictionless", "simple"});
  TableState<double> s;
  s.balls.push_back(rollingBall(0, 0.0, 0.0, 0.0, 0, p));
  s.balls.push_back(rollingBall(1, 2 * p.ball_radius, 0.0, 0.0, 0, p));
  ASSERT_EQ(engine.whyInvalid(s), "");
  s.balls[0].v = Vec3<double>(1.0, 0, 0);
  settleMotion(s.balls[0], p.ball_radius);
  const Event<double> ev = scanNextEvent(engine, s);
  ASSERT_EQ(ev.kind, EventKind::BallBall);
  EXPECT_EQ(ev.time, 0.0);
  advance(engine, s, 0.0);
  EXPECT_NEAR(s.balls[0].v.norm(), 0, 1e-15);
  EXPECT_NEAR(s.balls[1].v.x(), 1.0, 1e-15);
}

TEST(Engine, CaromTableHasNoPocketsAndBallsStayOn)
{
  const PhysicsParams<double> p;
  auto carom = std::make_shared<const TableModel>(TableModel::carom("carom", 2.84, 1.42));
  Engine<double> engine(carom, p);
  EXPECT_TRUE(carom->pockets().empty());
  EXPECT_TRUE(carom->circles().empty());  // closed corners need no end caps
  TableState<double> s;
  s.balls.push_back(rollingBall(0, 0.0, 0.0, 0.0, 0, p));
  CueStrike<double> cue;
  cue.speed = 6.0;
  cue.phi = 0.7;
  engine.strike(s, 0, cue);
  const ShotResult<double> r = simulateToRest(engine, s);
  EXPECT_TRUE(r.at_rest);
  int cushions = 0;
  for (const auto& e : r.events)
    cushions += e.kind == EventKind::BallCushion;
  EXPECT_GE(cushions, 3);
  EXPECT_EQ(engine.whyInvalid(s), "");
}

TEST(Engine, EventCapGivesAClearError)
{
  const PhysicsParams<double> p;
  EngineLimits limits;
  limits.max_events = 5;
  Engine<double> engine(sevenFoot(), p, {}, limits);
  TableState<double> s = rackLayout<double>("eight", engine.table(), p.ball_radius);
  CueStrike<double> cue;
  cue.speed = 8.0;
  engine.strike(s, 0, cue);
  try
  {
    simulateToRest(engine, s);
    FAIL() << "no EventLimitError";
  }
  catch (const EventLimitError& e)
  {
    EXPECT_NE(std::string(e.what()).find("max_events"), std::string::npos);
  }
}

TEST(Engine, InvalidStatesAreNamed)
{
  const PhysicsParams<double> p;
  Engine<double> engine(sevenFoot(), p);
  TableState<double> s;
  s.balls.push_back(rollingBall(0, 0.0, 0.0, 0.0, 0, p));
  s.balls.push_back(rollingBall(1, p.ball_radius, 0.0, 0.0, 0, p));
  EXPECT_NE(engine.whyInvalid(s).find("overlap"), std::string::npos);
  s.balls[1].r.x() = 5.0;
  EXPECT_NE(engine.whyInvalid(s).find("off the cloth"), std::string::npos);
  s.balls[1].r.x() = 1.9812 / 2 - 0.03;
  s.balls[1].r.y() = 0.9906 / 2 - 0.03;
  EXPECT_NE(engine.whyInvalid(s).find("pocket_foot_ypos"), std::string::npos);
  // Hanging in the jaws of a corner pocket, past the cushion line (a break left one there).
  s.balls[1].r.x() = 0.910537;
  s.balls[1].r.y() = 0.466859;
  EXPECT_GT(s.balls[1].r.y(), 0.9906 / 2 - p.ball_radius);
  EXPECT_EQ(engine.whyInvalid(s), "");
  // As near the pocket, but behind the long cushion that leads to it.
  s.balls[1].r.x() = 0.88;
  s.balls[1].r.y() = 0.53;
  EXPECT_NE(engine.whyInvalid(s).find("behind cushion_ypos_foot"), std::string::npos) << engine.whyInvalid(s);
  s.balls[1].r.x() = NAN;
  EXPECT_NE(engine.whyInvalid(s).find("finite"), std::string::npos);
  s.balls[1].r.x() = 0.5;
  s.balls[1].id = 0;
  EXPECT_NE(engine.whyInvalid(s).find("twice"), std::string::npos);
  CueStrike<double> cue;
  cue.speed = 1;
  EXPECT_NE(engine.whyNotStrikable(s, 7, cue).find("not on the table"), std::string::npos);
}

TEST(Engine, LongDoubleEngineAgreesWithDouble)
{
  const PhysicsParams<double> p;
  auto table = sevenFoot();
  Engine<double> fast(table, p);
  Engine<long double> exact(table, p.cast<long double>());
  TableState<double> s = rackLayout<double>("nine", *table, p.ball_radius);
  TableState<long double> s_exact = s.cast<long double>();
  CueStrike<double> cue;
  cue.speed = 3.0;
  cue.phi = 0.002;
  fast.strike(s, 0, cue);
  CueStrike<long double> cue_exact;
  cue_exact.speed = 3.0L;
  cue_exact.phi = 0.002L;
  exact.strike(s_exact, 0, cue_exact);
  // A slow, nearly straight shot: a few collisions, not yet chaotic.
  advance(fast, s, 0.4);
  advance(exact, s_exact, 0.4L);
  for (std::size_t i = 0; i < s.balls.size(); ++i)
  {
    const auto a = fast.ballAt(s, i, 0.4);
    const auto b = exact.ballAt(s_exact, i, 0.4L);
    EXPECT_NEAR((a.r - b.r.cast<double>()).norm(), 0, 1e-9) << "ball " << a.id;
  }
}

TEST(Engine, SustainedContactJoinsTheBallsInsteadOfEndlessBounces)
{
  // Two slow balls touching along x with equal x-velocities, the leading one slower overall:
  // rolling resistance decelerates it more along x, pressing the pair together while their
  // relative velocity is purely tangential. An impulse model alone answers with endless
  // micro-bounces; the engine joins them.
  const PhysicsParams<double> p;
  Engine<double> engine(sevenFoot(), p);
  TableState<double> s;
  const double u = -0.01;
  s.balls.push_back(rollingBall(1, 0.0, 0.0, std::hypot(u, 0.0), std::atan2(0.0, u), p));
  s.balls.push_back(rollingBall(5, 2 * p.ball_radius, 0.0, std::hypot(u, 0.01), std::atan2(0.01, u), p));
  const double m = p.ball_mass;
  const Vec3<double> momentum = m * (s.balls[0].v + s.balls[1].v);
  const Event<double> first = scanNextEvent(engine, s);
  ASSERT_EQ(first.kind, EventKind::BallBall);
  EXPECT_LT(first.time, 1e-12);  // at once (cos(pi) and sin(pi) leave a 1e-18 m/s separation)
  scanStep(engine, s);
  EXPECT_EQ(s.balls[0].v, s.balls[1].v);  // joined
  EXPECT_NEAR((m * (s.balls[0].v + s.balls[1].v) - momentum).norm(), 0, 1e-14 * momentum.norm());
  const int events = checkInvariantsEventByEvent(engine, s);
  EXPECT_LT(events, 10);
  EXPECT_FALSE(s.anyMoving());
  EXPECT_EQ(engine.whyInvalid(s), "");
}

// Issue 53 (../shared/repro/sticky_cluster_overlap.yaml: balls 22 and 59 ended 2e-8 m into each
// other): two touching balls rolling past each other, closing or parting within rounding of zero,
// whose rolling resistances turn them into each other about as fast as their passing turns them
// apart (d . (a_b - a_a) against -|v_rel|^2), meet at the touch and never go into each other, by
// the kept search and the full scan alike.
TEST(Engine, TouchingBallsRollingPastEachOtherMeetAtTheTouch)
{
  const PhysicsParams<double> p;
  const Engine<double> engine(sevenFoot(), p);
  const double R = p.ball_radius, roll = p.mu_roll * p.gravity;
  int cases = 0;
  for (const double heading : {0.0, 0.7, 2.0})
    for (const double speed_a : {0.0, 0.002, 0.01})
      for (const double v_rel : {0.01, 0.02})
        for (const double share : {0.5, 0.9, 0.99, 1.0, 1.01, 1.1, 2.0})
          for (const double closing : {-1e-14, -1e-15, 0.0, 1e-15, 1e-14})
          {
            // Both move along -n (from b towards a) at the same w, so they neither close nor part
            // but by `closing`; b passes a along u at v_rel. Each rolling resistance is along its own
            // heading, so b's has less of -n than a's: b is turned into a by (a_b - a_a) . n =
            // roll w (1/|v_a| - 1/|v_b|) (w < 0), set to share of the passing's -|v_rel|^2 / 2R.
            const Eigen::Vector2d u(std::cos(heading), std::sin(heading)), n(-u.y(), u.x());
            const auto turn = [&](double w) {
              const double a = std::hypot(speed_a, w), b = std::hypot(speed_a + v_rel, w);
              return roll * w * (1 / a - 1 / b) + share * v_rel * v_rel / (2 * R);
            };
            double lo = -1.0, hi = -1e-9, best = hi;
            for (double w = hi; w > lo; w *= 1.05)  // the strongest turn, then the root above it
              if (turn(w) < turn(best))
                best = w;
            if (!(turn(best) < 0))
              continue;  // no heading turns them that hard
            lo = best;
            for (int k = 0; k < 200; ++k)
              (turn(0.5 * (lo + hi)) < 0 ? lo : hi) = 0.5 * (lo + hi);
            const double w = hi;
            const Eigen::Vector2d va = speed_a * u + w * n, vb = (speed_a + v_rel) * u + (w - closing) * n;
            TableState<double> s;
            for (int id = 0; id < 2; ++id)
            {
              Ball<double> b;
              b.id = id;
              const Eigen::Vector2d v = id == 0 ? va : vb;
              const Eigen::Vector2d at = id == 0 ? Eigen::Vector2d(0, 0) : Eigen::Vector2d(2 * R * n);
              b.r = Vec3<double>(at.x(), at.y(), R);
              b.v = Vec3<double>(v.x(), v.y(), 0);
              b.w = Vec3<double>(-v.y() / R, v.x() / R, 0);  // rolling
              settleMotion(b, R);
              s.balls.push_back(b);
            }
            ++cases;
            TableState<double> kept = s, scanned = s;
            double deepest = 0;
            for (int e = 0; e < 200; ++e)
            {
              const Event<double> next = scanNextEvent(engine, scanned);
              if (!next.valid())
                break;
              for (int k = 1; k <= 16; ++k)
                deepest = std::max(deepest,
                                   -smallestGap(engine, scanned, scanned.time + (next.time - scanned.time) * k / 16));
              scanStep(engine, scanned);
            }
            simulateToRest(engine, kept);
            EXPECT_LE(deepest, 1e-9) << "heading " << heading << ", speed " << speed_a << ", v_rel " << v_rel
                                     << ", share " << share << ", closing " << closing;
            for (int i = 0; i < 2; ++i)
              EXPECT_EQ(kept.balls[i].r, scanned.balls[i].r) << "ball " << i;
          }
  EXPECT_GT(cases, 300);
}

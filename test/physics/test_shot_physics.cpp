// Shot physics against published behaviour (Alciatore's technical proofs, PHYSICS.md).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "cue_sim/physics/engine.hpp"
#include "cue_sim/physics/motion.hpp"
#include "cue_sim/physics/scan.hpp"
#include "resting_ball.hpp"

using namespace cue_sim::physics;

namespace
{
constexpr double kDeg = M_PI / 180;

std::shared_ptr<const TableModel> sevenFoot()
{
  static const auto table = std::make_shared<const TableModel>(TableModel::pool("7ft", 1.9812, 0.9906, 0.118, 0.137));
  return table;
}

double headingOf(const Vec3<double>& v)
{
  return std::atan2(v.y(), v.x());
}

/// The cue ball rolling along +x hits an object ball with cut angle `cut` (between the path and
/// the line of centres). Returns the engine state right after the ball-ball event.
TableState<double> afterCut(const Engine<double>& engine, double cut, double speed, bool rolling)
{
  const PhysicsParams<double>& p = engine.params();
  TableState<double> s;
  s.balls.push_back(restingBall(0, -0.5, 0.0, p));
  s.balls.push_back(restingBall(1, -0.2, 2 * p.ball_radius * std::sin(cut), p));
  s.balls[0].v = Vec3<double>(speed, 0, 0);
  if (rolling)
    s.balls[0].w = Vec3<double>(0, speed / p.ball_radius, 0);
  settleMotion(s.balls[0], p.ball_radius);
  for (int i = 0; i < 20; ++i)
    if (scanStep(engine, s).kind == EventKind::BallBall)
      return s;
  ADD_FAILURE() << "no ball-ball event";
  return s;
}

/// The cue ball's heading once it rolls again after the collision (Alciatore's "after the
/// spin takes").
double headingWhenRollingAgain(const Engine<double>& engine, TableState<double>& s)
{
  for (int i = 0; i < 20; ++i)
  {
    const Event<double> e = scanStep(engine, s);
    if (e.kind == EventKind::SlideToRoll && e.ball == 0)
      return headingOf(s.balls[s.indexOf(0)].v);
    if (!e.valid() || (e.isCollision() && e.ball == 0))
      break;
  }
  ADD_FAILURE() << "the cue ball did not roll freely after the hit";
  return NAN;
}

/// Throw: the angle of the object ball's departure off the line of centres, positive towards
/// the cue ball's side of travel (clockwise here, as the cue ball passes on the right of the
/// line of centres), for a stun cue ball (no spin at contact).
double throwAngle(const BallBallModel<double>& model, const PhysicsParams<double>& p, double cut, double speed)
{
  Ball<double> cue = restingBall(0, 0, 0, p),
               object = restingBall(1, 2 * p.ball_radius * std::cos(cut), 2 * p.ball_radius * std::sin(cut), p);
  cue.v = Vec3<double>(speed, 0, 0);
  model.resolve(cue, object, p);
  return cut - headingOf(object.v);
}
}  // namespace

TEST(ShotPhysics, StunShotFrictionlessLeavesAlongTheTangentLine)
{
  // With no spin at contact and e = 1 the balls part at exactly 90 degrees.
  PhysicsParams<double> p;
  p.e_ball = 1.0;
  p.mu_slide = 0.0;  // keeps the cue ball stunned until the hit
  Engine<double> engine(sevenFoot(), p, {"frictionless", "simple"});
  for (double cut : {10.0, 30.0, 50.0, 70.0})
  {
    const TableState<double> s = afterCut(engine, cut * kDeg, 2.0, false);
    const Vec3<double> cue = s.balls[0].v, object = s.balls[1].v;
    EXPECT_NEAR(std::acos(cue.normalized().dot(object.normalized())), M_PI / 2, 1e-9) << cut;
    EXPECT_NEAR(headingOf(object), cut * kDeg, 1e-9) << cut;  // along the line of centres
  }
}

TEST(ShotPhysics, RollingCueBallDeflectsAboutThirtyDegrees)
{
  // Alciatore TP A-4: ideal balls give tan(theta_c) = sin(a) cos(a) / (sin^2(a) + 2/5) for a
  // rolling cue ball at cut angle a; between a 1/4 and a 3/4 ball hit that is 27 to 34 degrees.
  PhysicsParams<double> ideal;
  ideal.e_ball = 1.0;
  const Engine<double> frictionless(sevenFoot(), ideal, {"frictionless", "simple"});
  const Engine<double> realistic(sevenFoot(), PhysicsParams<double>());
  for (double fraction : {0.25, 0.375, 0.5, 0.625, 0.75})
  {
    const double cut = std::asin(1 - fraction);
    const double expected = std::atan(std::sin(cut) * std::cos(cut) / (std::pow(std::sin(cut), 2) + 0.4));
    TableState<double> s = afterCut(frictionless, cut, 1.5, true);
    EXPECT_NEAR(-headingWhenRollingAgain(frictionless, s), expected, 1e-9) << "fraction " << fraction;
    s = afterCut(realistic, cut, 1.5, true);
    const double deflection = -headingWhenRollingAgain(realistic, s) / kDeg;
    EXPECT_GT(deflection, 25.0) << "fraction " << fraction;
    EXPECT_LT(deflection, 36.0) << "fraction " << fraction;
  }
}

TEST(ShotPhysics, CutInducedThrowIsAFewDegreesLargestNearHalfBall)
{
  // Alciatore TP A-14: a stun shot throws the object ball a few degrees towards the cue
  // ball's travel, most near a half-ball hit and more at slow speed.
  const PhysicsParams<double> p;
  const auto frictional = makeBallBallModel<double>("frictional");
  const BallBallModel<double>& model = *frictional;
  double largest = 0, largest_at = 0;
  for (double fraction = 0.125; fraction < 0.9; fraction += 0.125)
  {
    const double cut = std::asin(1 - fraction);
    const double slow = throwAngle(model, p, cut, 0.5) / kDeg;
    EXPECT_GT(slow, 0.5) << fraction;
    EXPECT_LT(slow, 6.0) << fraction;
    // Faster shots slide more easily: less throw, except at thin cuts near full ball, where
    // friction only has to stop the small slip and tan(throw) = 2 tan(cut) / (7 (1 + e))
    // whatever the speed.
    const double fast = throwAngle(model, p, cut, 5.0) / kDeg;
    EXPECT_LE(fast, slow + 1e-9) << fraction;
    if (fraction <= 0.625)
    {
      EXPECT_LT(fast, slow - 0.5) << fraction;
    }
    if (fraction >= 0.875)
    {
      EXPECT_NEAR(std::tan(slow * kDeg), 2 * std::tan(cut) / (7 * (1 + p.e_ball)), 1e-12) << fraction;
    }
    if (slow > largest)
    {
      largest = slow;
      largest_at = fraction;
    }
  }
  EXPECT_GE(largest_at, 0.25);
  EXPECT_LE(largest_at, 0.625);
  EXPECT_NEAR(throwAngle(*makeBallBallModel<double>("frictionless"), p, 30 * kDeg, 0.5), 0.0, 1e-12);
}

TEST(ShotPhysics, DrawComesBackAndFollowRollsOn)
{
  // A straight shot into an object ball: after the hit the cue ball stops (its forward speed
  // passed on), then its spin takes: draw brings it back, follow rolls it on.
  const PhysicsParams<double> p;
  const Engine<double> engine(sevenFoot(), p);
  for (double b : {-0.4, 0.4})
  {
    TableState<double> s;
    s.balls.push_back(restingBall(0, -0.5, 0.0, p));
    s.balls.push_back(restingBall(1, 0.0, 0.0, p));
    CueStrike<double> cue;
    cue.speed = 2.0;
    cue.b = b;
    engine.strike(s, 0, cue);
    bool hit = false;
    double rolling_vx = NAN;
    for (int i = 0; i < 20 && std::isnan(rolling_vx); ++i)
    {
      const Event<double> e = scanStep(engine, s);
      ASSERT_TRUE(e.valid());
      if (e.kind == EventKind::BallBall && e.ball == 0)
      {
        hit = true;
        EXPECT_LT(std::abs(s.balls[0].v.x()), 0.1 * 2.0) << "the cue ball nearly stops at the hit";
      }
      if (hit && e.kind == EventKind::SlideToRoll && e.ball == 0)
        rolling_vx = s.balls[0].v.x();
    }
    ASSERT_TRUE(hit);
    if (b < 0)
      EXPECT_LT(rolling_vx, -0.1) << "draw: the cue ball comes back";
    else
      EXPECT_GT(rolling_vx, 0.3) << "follow: the cue ball rolls on";
  }
}

TEST(ShotPhysics, SideSpinChangesTheRebound)
{
  // Alciatore, "Sidespin Terminology": right of centre spins the ball counter-clockwise seen
  // from above and it rebounds to the right off a cushion; running English lengthens the
  // rebound angle, reverse English shortens it.
  const PhysicsParams<double> p;
  const Engine<double> engine(sevenFoot(), p);
  const double hy = 0.9906 / 2;
  // Angles from the cushion's normal, measured on the velocities at the event itself, so that
  // squirt and the English's slower start do not count.
  struct Rebound
  {
    Vec3<double> out;
    double angle_in, angle_out;
  };
  const auto rebound = [&](double heading, double a) {
    TableState<double> s;
    s.balls.push_back(restingBall(0, -0.7, hy - 0.3, p));
    CueStrike<double> cue;
    cue.speed = 1.5;
    cue.phi = heading;
    cue.a = a;
    engine.strike(s, 0, cue);
    for (int i = 0; i < 10; ++i)
    {
      const Event<double> e = scanNextEvent(engine, s);
      const Vec3<double> in = engine.ballAt(s, 0, e.time).v;
      scanStep(engine, s);
      if (e.kind == EventKind::BallCushion)
      {
        const Vec3<double> out = s.balls[0].v;
        return Rebound{out, std::atan2(std::abs(in.x()), in.y()), std::atan2(std::abs(out.x()), -out.y())};
      }
    }
    ADD_FAILURE() << "no cushion";
    return Rebound{Vec3<double>::Constant(NAN), NAN, NAN};
  };
  // Straight into the top cushion: the shooter's right is +x.
  EXPECT_GT(rebound(M_PI / 2, 0.4).out.x(), 0.05);
  EXPECT_LT(rebound(M_PI / 2, -0.4).out.x(), -0.05);
  EXPECT_NEAR(rebound(M_PI / 2, 0.0).out.x(), 0.0, 1e-12);
  // Up and to the right into the top cushion, right English runs along the rail.
  const auto change = [&](double heading, double a) {
    const Rebound r = rebound(heading, a);
    return r.angle_out - r.angle_in;
  };
  const double steep = 65 * kDeg;  // 25 degrees off the normal
  EXPECT_GT(change(steep, 0.4), change(steep, 0.0) + 5 * kDeg) << "running English lengthens the angle";
  EXPECT_LT(change(steep, -0.4), change(steep, 0.0) - 5 * kDeg) << "reverse English shortens it";
  EXPECT_GT(change(M_PI / 4, 0.4), change(M_PI / 4, 0.0) + 5 * kDeg);
}

TEST(ShotPhysics, MasseCurvesWhileSliding)
{
  const PhysicsParams<double> p;
  const Engine<double> engine(sevenFoot(), p);
  const auto turn = [&](double theta) {
    TableState<double> s;
    s.balls.push_back(restingBall(0, -0.5, 0.0, p));
    CueStrike<double> cue;
    cue.speed = 2.0;
    cue.theta = theta;
    cue.a = 0.3;
    engine.strike(s, 0, cue);
    const double start = headingOf(s.balls[0].v);
    const double slide_end = s.balls[0].time + timeToTransition(s.balls[0], p);
    return headingOf(engine.ballAt(s, 0, slide_end).v) - start;
  };
  EXPECT_GT(std::abs(turn(70 * kDeg)), 10 * kDeg) << "an elevated cue with side offset curves the path";
  EXPECT_NEAR(turn(0.0), 0.0, 1e-12) << "a level cue's side spin does not curve it";
}

TEST(ShotPhysics, AMasseSlideFollowsTheClosedFormParabola)
{
  // While a ball slides, cloth friction mu_s g acts against the contact point's slip u, whose
  // direction does not change (PHYSICS.md): the centre follows r0 + v0 t - mu_s g t^2 / 2 u/|u|,
  // a parabola, until the slip is gone at t = 2 |u| / (7 mu_s g).
  const PhysicsParams<double> p;
  const Engine<double> engine(sevenFoot(), p);
  for (double theta : {0.6, 1.2})
  {
    TableState<double> s;
    s.balls.push_back(restingBall(0, -0.5, 0.0, p));
    CueStrike<double> cue;
    cue.speed = 1.5;
    cue.phi = 0.2;
    cue.theta = theta;
    cue.a = 0.3;
    cue.b = -0.2;
    engine.strike(s, 0, cue);
    const Ball<double> b0 = s.balls[0];
    const Vec3<double> slip = b0.v - p.ball_radius * b0.w.cross(Vec3<double>::UnitZ());
    const Vec3<double> along = slip.normalized();
    const double g = p.mu_slide * p.gravity, slide_end = 2 * slip.norm() / (7 * g);
    ASSERT_NEAR(timeToTransition(b0, p), slide_end, 1e-12);
    for (double f : {0.1, 0.4, 0.7, 0.99})
    {
      const double t = f * slide_end;
      const Vec3<double> want = b0.r + b0.v * t - 0.5 * g * t * t * along;
      EXPECT_NEAR((engine.ballAt(s, 0, b0.time + t).r - want).norm(), 0, 1e-12) << theta << " " << f;
    }
    // It curves: the heading turns while it slides.
    const double turn = headingOf(engine.ballAt(s, 0, b0.time + 0.99 * slide_end).v) - headingOf(b0.v);
    EXPECT_GT(std::abs(turn), 5 * kDeg) << theta;
  }
}

TEST(ShotPhysics, AMasseEndsHeadingFromTheRestingPointToTheAimPoint)
{
  // Coriolis' masse aiming (Alciatore, "Coriolis was brilliant ... Part V: masse shot aiming",
  // Principle 25, TP A.19): once the slide is over the ball heads along the line from where it
  // rested on the cloth (R) to where the cue's line of action meets the cloth (A). Angular
  // momentum about the cloth contact is all the strike gives it there, and the cloth's friction
  // keeps it. The tip meets the ball at P - C = a R side + b R u - c d (a, b on the face seen along
  // the cue), and the line of action runs from P along d. Squirt, which the principle leaves out,
  // is kept below 1e-5 rad here by a cue end mass of 1e-6 kg.
  PhysicsParams<double> p;
  p.cue_end_mass = 1e-6;
  const Engine<double> engine(sevenFoot(), p);
  struct Case
  {
    double theta_deg, phi, a, b;
  };
  for (const Case c : {Case{30, 0.0, 0.4, 0.0}, Case{55, 0.7, -0.3, 0.2}, Case{80, -1.2, 0.2, -0.4},
                       Case{70, 2.0, 0.0, 0.5}, Case{45, 0.3, 0.4, -0.3}})
  {
    TableState<double> s;
    s.balls.push_back(restingBall(0, -0.3, 0.1, p));
    const Vec3<double> rest(-0.3, 0.1, 0), centre = rest + p.ball_radius * Vec3<double>::UnitZ();
    CueStrike<double> cue;
    cue.speed = 2.0;
    cue.phi = c.phi;
    cue.theta = c.theta_deg * kDeg;
    cue.a = c.a;
    cue.b = c.b;
    engine.strike(s, 0, cue);
    const Vec3<double> h(std::cos(c.phi), std::sin(c.phi), 0), side(h.y(), -h.x(), 0);
    const Vec3<double> up = std::sin(cue.theta) * h + std::cos(cue.theta) * Vec3<double>::UnitZ();
    const Vec3<double> d = std::cos(cue.theta) * h - std::sin(cue.theta) * Vec3<double>::UnitZ();
    const double depth = std::sqrt(1 - c.a * c.a - c.b * c.b);
    const Vec3<double> tip = centre + p.ball_radius * (c.a * side + c.b * up - depth * d);
    const Vec3<double> aim = tip + (tip.z() / std::sin(cue.theta)) * d;  // on the cloth, z = 0
    const Ball<double> b0 = s.balls[0];
    const Vec3<double> rolling = engine.ballAt(s, 0, b0.time + timeToTransition(b0, p)).v;
    const double expected = std::atan2(aim.y() - rest.y(), aim.x() - rest.x());
    EXPECT_NEAR(std::remainder(headingOf(rolling) - expected, 2 * M_PI), 0, 1e-5)
        << c.theta_deg << " deg, a " << c.a << ", b " << c.b;
  }
}

TEST(ShotPhysics, SquirtIsAboutTwoDegreesAtHalfTipOffset)
{
  const PhysicsParams<double> p;
  EXPECT_NEAR(squirtAngle(0.5, p) / kDeg, 1.9, 0.05);
  for (double a : {0.5, -0.5})
  {
    Ball<double> b;
    CueStrike<double> cue;
    cue.speed = 2.0;
    cue.phi = 0.3;
    cue.a = a;
    applyCueStrike(b, cue, p);
    // Away from the side struck: right English (a > 0) squirts left of the heading.
    EXPECT_NEAR((headingOf(b.v) - 0.3) / kDeg, a > 0 ? 1.886 : -1.886, 0.01);
  }
  EXPECT_NEAR(contactOffset(0.5, p), 0.5 / (1 + 0.0106 / 0.028575), 1e-15);
}

TEST(ShotPhysics, SideSpinThrowsTheObjectBallAndGearsItsSpin)
{
  // A full hit with right English (w_z > 0): friction at the contact drags the object ball to
  // the left of the line of centres and spins it the other way (Alciatore TP A-14, "gear").
  const PhysicsParams<double> p;
  const auto frictional = makeBallBallModel<double>("frictional");
  const BallBallModel<double>& model = *frictional;
  for (const double spin : {40.0, -40.0})
  {
    Ball<double> cue = restingBall(0, 0, 0, p), object = restingBall(1, 2 * p.ball_radius, 0, p);
    cue.v = Vec3<double>(1.0, 0, 0);
    cue.w = Vec3<double>(0, 1.0 / p.ball_radius, spin);  // rolling, with side spin
    model.resolve(cue, object, p);
    const double thrown = headingOf(object.v) / kDeg;
    EXPECT_GT(std::abs(thrown), 0.5) << spin;
    EXPECT_LT(std::abs(thrown), 6.0) << spin;
    EXPECT_GT(thrown * spin, 0) << "right English throws left";
    EXPECT_LT(object.w.z() * spin, 0) << "the object ball spins the other way";
    EXPECT_LT(std::abs(cue.w.z()), std::abs(spin)) << "the cue ball gives up spin";
  }
}

TEST(ShotPhysics, BallsRattleInTheJawsOrDropCleanly)
{
  // Balls rolled at the foot-left corner pocket along lines offset from its centre: near the
  // middle they drop without touching a jaw; further out they hit a jaw first, and some of
  // those still drop (rattle in) while others bounce out (jawed).
  const PhysicsParams<double> p;
  const Engine<double> engine(sevenFoot(), p);
  const double hx = 1.9812 / 2, hy = 0.9906 / 2;
  const Vec2<double> mouth_middle(hx - 0.0834 / 2, hy - 0.0834 / 2);
  int clean = 0, rattled_in = 0, jawed = 0;
  for (double offset = -0.05; offset <= 0.05; offset += 0.0025)
  {
    // 0.6 m out along a line at 30 degrees to the long rail, shifted sideways by `offset`.
    const Vec2<double> along(std::cos(30 * kDeg), std::sin(30 * kDeg)), across(-along.y(), along.x());
    const Vec2<double> start = mouth_middle - 0.6 * along + offset * across;
    TableState<double> s;
    s.balls.push_back(restingBall(0, start.x(), start.y(), p));
    s.balls[0].v = Vec3<double>(along.x(), along.y(), 0) * 1.2;
    s.balls[0].w = Vec3<double>(-s.balls[0].v.y(), s.balls[0].v.x(), 0) / p.ball_radius;
    settleMotion(s.balls[0], p.ball_radius);
    bool touched_jaw = false, dropped = false;
    for (int i = 0; i < 30 && !dropped; ++i)
    {
      const Event<double> e = scanStep(engine, s);
      if (!e.valid() || e.kind == EventKind::BallCushion)
        break;
      if (e.kind == EventKind::BallCircle)
      {
        EXPECT_EQ(engine.table().circles()[e.obstacle].name.rfind("jaw_foot_ypos", 0), 0u);
        touched_jaw = true;
      }
      dropped = e.kind == EventKind::Pocketed;
    }
    clean += dropped && !touched_jaw;
    rattled_in += dropped && touched_jaw;
    jawed += !dropped && touched_jaw;
  }
  RecordProperty("clean", clean);
  RecordProperty("rattled_in", rattled_in);
  RecordProperty("jawed", jawed);
  EXPECT_GE(clean, 3) << rattled_in << " rattled in, " << jawed << " jawed";
  EXPECT_GE(rattled_in, 1) << clean << " clean, " << jawed << " jawed";
  EXPECT_GE(jawed, 1) << clean << " clean, " << rattled_in << " rattled in";
}

// Contact models against the article's numbers and the conservation laws.
#include <gtest/gtest.h>

#include <cmath>

#include "cue_sim/physics/collision_models.hpp"
#include "cue_sim/physics/cue_strike.hpp"
#include "cue_sim/physics/motion.hpp"

using namespace cue_sim::physics;

TEST(FrictionlessBallBall, ReproducesTheArticleExample)
{
  // Lander 1999: A at 20 ft/s, 40 degrees to the line of centres, B at rest, e = 0.8 gives
  // v_A' = (1.53, -12.86) and v_B' = (13.79, 0.0) ft/s in (n, t). The model is linear in the
  // velocities, so feet per second in give feet per second out.
  PhysicsParams<double> p;
  p.e_ball = 0.8;
  const double deg = M_PI / 180;
  Ball<double> a, b;
  a.r = Vec3<double>(0, 0, p.ball_radius);
  b.r = Vec3<double>(2 * p.ball_radius, 0, p.ball_radius);  // n = +x, t = +y
  a.v = 20.0 * Vec3<double>(std::cos(40 * deg), -std::sin(40 * deg), 0);
  makeBallBallModel<double>("frictionless")->resolve(a, b, p);
  EXPECT_NEAR(a.v.x(), 1.53, 0.005);
  EXPECT_NEAR(a.v.y(), -12.86, 0.005);
  EXPECT_NEAR(b.v.x(), 13.79, 0.005);
  EXPECT_NEAR(b.v.y(), 0.0, 1e-15);
}

TEST(FrictionlessBallBall, ConservesMomentumAndNeverGainsEnergy)
{
  PhysicsParams<double> p;
  for (double e : {0.0, 0.5, 0.95, 1.0})
  {
    p.e_ball = e;
    Ball<double> a, b;
    a.r = Vec3<double>(0, 0, p.ball_radius);
    b.r = Vec3<double>(1.2 * p.ball_radius, 1.6 * p.ball_radius, p.ball_radius);  // |d| = 2R
    a.v = Vec3<double>(1.5, 2.5, 0);
    b.v = Vec3<double>(-0.4, 0.3, 0);
    a.w = Vec3<double>(3, -4, 10);
    const Vec3<double> momentum = a.v + b.v;
    const double energy = kineticEnergy(a, p) + kineticEnergy(b, p);
    makeBallBallModel<double>("frictionless")->resolve(a, b, p);
    EXPECT_NEAR((a.v + b.v - momentum).norm(), 0, 1e-14) << "e = " << e;
    const double after = kineticEnergy(a, p) + kineticEnergy(b, p);
    EXPECT_LE(after, energy * (1 + 1e-14)) << "e = " << e;
    if (e == 1.0)
    {
      EXPECT_NEAR(after, energy, 1e-14 * energy);
    }
  }
}

TEST(SimpleCushion, ReflectsTheNormalVelocityWithRestitution)
{
  PhysicsParams<double> p;
  Ball<double> b;
  b.v = Vec3<double>(0.8, -1.5, 0);
  b.w = Vec3<double>(1, 2, 3);
  const Vec3<double> n(0, 1, 0);  // cushion along x, play at +y
  makeCushionModel<double>("simple")->resolve(b, n, p);
  EXPECT_DOUBLE_EQ(b.v.x(), 0.8);
  EXPECT_NEAR(b.v.y(), 1.5 * p.e_cushion, 1e-15);
  EXPECT_EQ(b.w, Vec3<double>(1, 2, 3));
}

TEST(ModelRegistry, UnknownNamesAreRefusedWithTheKnownOnes)
{
  EXPECT_NO_THROW(makeBallBallModel<double>("frictionless"));
  EXPECT_NO_THROW(makeCushionModel<double>("simple"));
  try
  {
    makeBallBallModel<double>("sticky");
    FAIL();
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("frictionless"), std::string::npos);
  }
  EXPECT_THROW(makeCushionModel<double>("rubber"), std::invalid_argument);
}

TEST(CueStrike, CentreHitGivesTwoV0OverOnePlusMassRatio)
{
  PhysicsParams<double> p;
  Ball<double> b;
  CueStrike<double> s;
  s.speed = 2.0;
  s.phi = 0.3;
  applyCueStrike(b, s, p);
  // PHYSICS.md: a centre hit at V0 = 2 m/s sends the ball off at about 3.08 m/s.
  EXPECT_NEAR(b.v.norm(), 2 * 2.0 / (1 + p.ball_mass / p.cue_mass), 1e-12);
  EXPECT_NEAR(b.v.norm(), 3.08, 0.005);
  EXPECT_NEAR(std::atan2(b.v.y(), b.v.x()), 0.3, 1e-15);
  EXPECT_NEAR(b.w.norm(), 0, 1e-12);
}

TEST(CueStrike, HitTwoFifthsOfARadiusAboveCentreRollsNaturally)
{
  // The classic result: a level cue at height 7/5 R above the cloth gives natural roll.
  PhysicsParams<double> p;
  Ball<double> b;
  CueStrike<double> s;
  s.speed = 2.0;
  s.phi = -1.0;
  s.b = 0.4;
  applyCueStrike(b, s, p);
  EXPECT_NEAR(slipVelocity(b.v, b.w, p.ball_radius).norm(), 0, 1e-12);
  settleMotion(b, p.ball_radius);
  EXPECT_EQ(b.motion, Motion::Rolling);
  // Below centre: backspin, the contact point slips forward faster than the ball.
  s.b = -0.4;
  applyCueStrike(b, s, p);
  EXPECT_GT(slipVelocity(b.v, b.w, p.ball_radius).dot(b.v), b.v.squaredNorm());
}

TEST(CueStrike, OutOfRangeFieldsAreNamed)
{
  CueStrike<double> s;
  s.speed = 2;
  EXPECT_EQ(validateStrike(s), "");
  for (double bad : {-1.0, 0.0, 12.5, double(NAN), double(INFINITY)})
  {
    s.speed = bad;
    EXPECT_NE(validateStrike(s).find("speed"), std::string::npos) << bad;
  }
  s.speed = 2;
  s.phi = NAN;
  EXPECT_NE(validateStrike(s).find("phi"), std::string::npos);
  s.phi = 0;
  s.theta = -0.1;
  EXPECT_NE(validateStrike(s).find("theta"), std::string::npos);
  s.theta = 0;
  s.a = 0.4;
  s.b = 0.4;
  EXPECT_NE(validateStrike(s).find("sqrt(a^2 + b^2)"), std::string::npos);
}

TEST(CueStrike, SpeedAndSpinAgreeWithThePublishedFormulaForAnyOffset)
{
  // PHYSICS.md (Alciatore TP A-30), with a and b on the ball's face seen along the cue (pooltool's
  // convention since 2025): the tip meets the ball at P - C = A right + B up - c d, so that
  // v = 2 V0 / (1 + m/M + 5/(2R^2) (A^2 + B^2)) and the spin is (P - C) x d times v / (2/5 R^2),
  // computed here as a cross product of the contact point and the cue direction.
  PhysicsParams<double> p;
  const double R = p.ball_radius;
  for (double theta : {0.0, 0.2, 0.7, 1.4})
    for (double a : {-0.3, 0.0, 0.25})
      for (double b : {-0.35, 0.0, 0.1})
      {
        CueStrike<double> s;
        s.speed = 3.0;
        s.phi = 2.2;
        s.theta = theta;
        s.a = a;
        s.b = b;
        Ball<double> ball;
        applyCueStrike(ball, s, p);
        const double A = a * R, B = b * R, C = std::sqrt(R * R - A * A - B * B);
        const double ct = std::cos(theta), st = std::sin(theta);
        const double v = 2 * s.speed / (1 + p.ball_mass / p.cue_mass + 5 / (2 * R * R) * (A * A + B * B));
        EXPECT_NEAR(ball.v.norm(), v * ct, 1e-12) << theta << " " << a << " " << b;
        const Vec3<double> h(std::cos(s.phi), std::sin(s.phi), 0), z(0, 0, 1);
        const Vec3<double> cue_direction = ct * h - st * z;
        const Vec3<double> right = cue_direction.cross(z).normalized();
        const Vec3<double> up = right.cross(cue_direction);
        const Vec3<double> contact = A * right + B * up - C * cue_direction;
        EXPECT_NEAR(contact.norm(), R, 1e-15) << "on the ball's surface";
        const Vec3<double> w = v / (0.4 * R * R) * contact.cross(cue_direction);
        EXPECT_NEAR((ball.w - w).norm(), 0, 1e-9 * (1 + w.norm())) << theta << " " << a << " " << b;
      }
}

TEST(CueStrike, ACentreHitGivesNoSpinAtAnyElevation)
{
  const PhysicsParams<double> p;
  for (double theta : {0.0, 0.1, 0.5, 1.0, 1.5})
  {
    CueStrike<double> s;
    s.speed = 4.0;
    s.phi = -0.7;
    s.theta = theta;
    Ball<double> ball;
    applyCueStrike(ball, s, p);
    EXPECT_EQ(ball.w.norm(), 0) << "theta " << theta;
    // All of the cue's impulse along its axis: the horizontal part is cos(theta) of a level hit's.
    const double level = 2 * s.speed / (1 + p.ball_mass / p.cue_mass);
    EXPECT_NEAR(ball.v.norm(), level * std::cos(theta), 1e-12) << "theta " << theta;
  }
}

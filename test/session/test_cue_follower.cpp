// Following a cue through samples of its pose: the touch found between samples at 100 Hz and
// 1 kHz, the speed there from the cue's motion (steady, accelerating, jittering), and what is not a
// strike (a cue resting against a ball, creeping into it, a gap, a jump, a sample out of order), and
// settings out of their declared ranges.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "cue_sim/session/cue_follower.hpp"

using namespace cue_sim;
using namespace cue_sim::physics;
using session::CueFollower;
using session::CueStep;

namespace
{
const PhysicsParams<double> kParams;
const double R = kParams.ball_radius;

std::vector<Ball<double>> oneBall()
{
  Ball<double> b;
  b.id = 4;
  b.r = Vec3<double>(0.5, 0.3, R);
  return {b};
}

/// A level cue along +x, through the ball's centre offset by `dy`, its tip's end at `x`.
CuePose cueAt(double stamp, double x, double dy = 0)
{
  CuePose pose;
  pose.stamp = stamp;
  pose.cue.tip = Vec3<double>(x, 0.3 + dy, R);
  pose.cue.axis = Vec3<double>(1, 0, 0);
  return pose;
}

/// Feeds the follower the stroke x(t) sampled every `period` from t = 0 to `end`; the steps.
template <typename Stroke>
std::vector<CueStep> follow(CueFollower& follower, Stroke x, double period, double end, double dy = 0)
{
  std::vector<CueStep> steps;
  for (int k = 0; k * period <= end + 1e-12; ++k)
    steps.push_back(follower.observe(cueAt(k * period, x(k * period), dy), oneBall(), kParams));
  return steps;
}

std::vector<session::CueContact> contactsOf(const std::vector<CueStep>& steps)
{
  std::vector<session::CueContact> out;
  for (const auto& s : steps)
    if (s.contact)
      out.push_back(*s.contact);
  return out;
}

/// Where the tip's end touches the ball on a stroke through its centre.
const double kTouchX = 0.5 - R;
}  // namespace

TEST(CueFollower, ASteadyStrokeTouchesOnceAtItsSpeedAt100Hz1kHzAnd10kHz)
{
  for (const double period : {0.01, 0.001, 0.0001})
  {
    CueFollower follower;
    // 2 m/s from 0.2 m short of the touch, on through the ball's place (a robot's follow-through).
    const auto contacts = contactsOf(follow(
        follower, [](double t) { return kTouchX - 0.2 + 2 * t; }, period, 0.2));
    ASSERT_EQ(contacts.size(), 1u) << period;
    EXPECT_EQ(contacts[0].ball_id, 4);
    EXPECT_EQ(contacts[0].refusal, "");
    EXPECT_NEAR(contacts[0].stamp, 0.1, 1e-12);
    EXPECT_NEAR(contacts[0].speed, 2.0, 1e-9);
    EXPECT_NEAR((contacts[0].point - Vec3<double>(kTouchX, 0.3, R)).norm(), 0, 1e-12);
    // The strike's cue: the stroke's line, its tip a hair short of the ball.
    CueAim aim;
    ASSERT_EQ(aimCue(oneBall(), kParams, contacts[0].cue, contacts[0].speed, aim), "");
    EXPECT_EQ(aim.ball_id, 4);
    EXPECT_NEAR(aim.strike.a, 0, 1e-12);
    EXPECT_LT(aim.travel, 1e-8);
  }
}

TEST(CueFollower, AnAcceleratingStrokesSpeedIsItsSpeedAtTheTouch)
{
  // From rest at 30 m/s^2: 2.4 m/s at the touch 0.08 s on, found through a parabola's fit.
  for (const double period : {0.01, 0.001})
  {
    CueFollower follower;
    const double start = kTouchX - 0.5 * 30 * 0.08 * 0.08;
    const auto contacts = contactsOf(follow(
        follower, [&](double t) { return start + 0.5 * 30 * t * t; }, period, 0.12));
    ASSERT_EQ(contacts.size(), 1u) << period;
    EXPECT_NEAR(contacts[0].stamp, 0.08, 1e-9);
    EXPECT_NEAR(contacts[0].speed, 2.4, 1e-8) << period;
  }
}

TEST(CueFollower, ACueThatSlowsAtTheTouchIsReadAtItsSpeedIntoTheBall)
{
  // Accelerating at 20 m/s^2 to 2 m/s at the touch, then slowing at 40 m/s^2 (a robot's
  // follow-through, or a real cue slowed by the ball): the speed into the ball, from the samples
  // before the touch only, at 100 Hz as at 1 kHz (the samples after it would pull it down). The
  // touch itself is found on the straight segment between two samples, which the kink bends: its
  // stamp is off by under 2 % of a sample period, and the speed read there by 20 m/s^2 times that.
  for (const double period : {0.01, 0.001})
  {
    for (const double offset : {0.0, 0.3, 0.7})
    {
      CueFollower follower;
      const double touch = 0.1 + offset * period;
      const auto x = [&](double t) {
        const double u = t - touch;
        return u < 0 ? kTouchX + 2 * u + 10 * u * u : kTouchX + 2 * u - 20 * u * u;
      };
      const auto contacts = contactsOf(follow(follower, x, period, 0.15));
      ASSERT_EQ(contacts.size(), 1u) << period;
      EXPECT_NEAR(contacts[0].stamp, touch, 0.02 * period) << period;
      EXPECT_NEAR(contacts[0].speed, 2.0, 20 * 0.02 * period + 1e-9) << period << " " << offset;
    }
  }
}

TEST(CueFollower, ATipJitteringByATenthOfAMillimetreStillReadsItsSpeed)
{
  std::mt19937 rng(11);
  std::normal_distribution<double> jitter(0, 1e-4);
  CueFollower follower;
  std::vector<CueStep> steps;
  for (int k = 0; k <= 300; ++k)
  {
    const double t = 0.001 * k;
    CuePose pose = cueAt(t, kTouchX - 0.15 + 1.5 * t);
    pose.cue.tip += Vec3<double>(jitter(rng), jitter(rng), jitter(rng));
    steps.push_back(follower.observe(pose, oneBall(), kParams));
  }
  const auto contacts = contactsOf(steps);
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_EQ(contacts[0].refusal, "");
  EXPECT_NEAR(contacts[0].stamp, 0.1, 2e-4);   // a tenth of a millimetre at 1.5 m/s
  EXPECT_NEAR(contacts[0].speed, 1.5, 0.034);  // four of the fit's standard deviations (0.0085 m/s)
}

TEST(CueFollower, ACueRestingAgainstABallOrCreepingIntoItStrikesNothing)
{
  // Held 1 mm short of the ball for 0.1 s, pushed on to 0.05 mm short of it at 1 cm/s, then held
  // there for ten seconds, jittering by 0.1 mm at 1 kHz all along: it touches once, under the
  // strike's minimum speed, and its jitter in and out of touch (many times a second) touches
  // nothing again, for it never draws 2 mm clear.
  std::mt19937 rng(5);
  std::normal_distribution<double> jitter(0, 1e-4);
  CueFollower follower;
  std::vector<session::CueContact> touches;
  for (int k = 0; k <= 10200; ++k)
  {
    const double t = 0.001 * k;
    const double x = t < 0.1 ? kTouchX - 1e-3 : std::min(kTouchX - 5e-5, kTouchX - 1e-3 + 0.01 * (t - 0.1));
    CuePose pose = cueAt(t, x);
    pose.cue.tip += Vec3<double>(jitter(rng), jitter(rng), jitter(rng));
    const CueStep step = follower.observe(pose, oneBall(), kParams);
    if (step.contact)
      touches.push_back(*step.contact);
  }
  ASSERT_EQ(touches.size(), 1u);
  EXPECT_NE(touches[0].refusal.find("0.05 m/s a strike needs"), std::string::npos) << touches[0].refusal;
  // Creeping in at 1 mm/s: one touch, refused, and the refusal says the speed and the minimum.
  CueFollower creeping;
  const auto contacts = contactsOf(follow(
      creeping, [](double t) { return kTouchX - 1e-4 + 1e-3 * t; }, 0.001, 0.2));
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_NEAR(contacts[0].speed, 1e-3, 1e-9);
  EXPECT_NE(contacts[0].refusal.find("0.05 m/s a strike needs"), std::string::npos) << contacts[0].refusal;
}

TEST(CueFollower, AGapOrAJumpIsNotSweptAndSaysSo)
{
  // Frames lost for 0.2 s across the touch: the tip is next seen past the ball's centre, in it.
  CueFollower follower;
  std::vector<CueStep> steps;
  for (const double t : {0.0, 0.01, 0.02, 0.22, 0.23})
    steps.push_back(follower.observe(cueAt(t, kTouchX - 0.05 + 0.5 * t), oneBall(), kParams));
  EXPECT_TRUE(contactsOf(steps).empty());
  EXPECT_NE(steps[3].note.find("no sample for 0.2"), std::string::npos) << steps[3].note;
  EXPECT_EQ(follower.samples().size(), 2u);
  // A tip 1 m from where it was a millisecond before.
  CueFollower jumping;
  jumping.observe(cueAt(0, kTouchX - 0.5), oneBall(), kParams);
  const CueStep jump = jumping.observe(cueAt(0.001, kTouchX + 0.5), oneBall(), kParams);
  EXPECT_FALSE(jump.contact);
  EXPECT_NE(jump.note.find("jumped"), std::string::npos) << jump.note;
}

TEST(CueFollower, ASampleOutOfOrderOrNotAPoseChangesNothing)
{
  CueFollower follower;
  follower.observe(cueAt(0.1, 0), oneBall(), kParams);
  const CueStep old = follower.observe(cueAt(0.05, 0.01), oneBall(), kParams);
  EXPECT_NE(old.note.find("not after the last"), std::string::npos) << old.note;
  CuePose bad = cueAt(0.2, std::numeric_limits<double>::quiet_NaN());
  EXPECT_NE(follower.observe(bad, oneBall(), kParams).note, "");
  bad = cueAt(0.2, 0);
  bad.cue.axis = Vec3<double>::Zero();
  EXPECT_NE(follower.observe(bad, oneBall(), kParams).note, "");
  ASSERT_EQ(follower.samples().size(), 1u);
  EXPECT_EQ(follower.samples().back().stamp, 0.1);
}

TEST(CueFollower, AStrokeAfterDrawingBackTouchesAgainAndADrawBackIsNoStrike)
{
  // Strike, draw back 10 cm, strike again: two touches, each reported (the node refuses the second
  // while the table moves: a double hit is never struck twice). Through a ball's place by 2 cm the
  // tip stays in it and draws back out with no touch; by 10 cm it passes it, and drawing back
  // touches its far side moving backwards: reported, no strike.
  for (const double through : {0.02, 0.1})
  {
    CueFollower follower;
    auto x = [through](double t) {
      if (t <= 0.1 + through)
        return kTouchX - 0.1 + 1.0 * t;
      const double back = 0.1 + through;  // seconds of drawing back to 0.1 m short
      if (t <= 2 * back)
        return kTouchX + through - 1.0 * (t - back);
      return kTouchX - 0.1 + 1.0 * (t - 2 * back);
    };
    const double second = 2 * (0.1 + through) + 0.1;
    std::vector<session::CueContact> strikes, refused;
    for (const auto& c : contactsOf(follow(follower, x, 0.001, second + 0.05)))
      (c.refusal.empty() ? strikes : refused).push_back(c);
    ASSERT_EQ(strikes.size(), 2u) << through;
    EXPECT_NEAR(strikes[0].stamp, 0.1, 1e-9);
    EXPECT_NEAR(strikes[1].stamp, second, 1e-9);
    EXPECT_NEAR(strikes[1].speed, 1.0, 1e-9);
    ASSERT_EQ(refused.size(), through > 0.05 ? 1u : 0u) << through;
    if (!refused.empty())
    {
      EXPECT_LT(refused[0].speed, -0.5);  // backwards (the fit spans this stroke's instant turn 22 ms before)
    }
  }
}

TEST(CueFollower, ACueFollowedTooBrieflyBeforeItsTouchStrikesNothing)
{
  // The frame first seen 5 ms before the tip reaches the ball at 2 m/s: its speed there is not
  // known from 5 ms of a tracker's samples.
  CueFollower follower;
  const auto contacts = contactsOf(follow(
      follower, [](double t) { return kTouchX - 0.01 + 2 * t; }, 0.001, 0.02));
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_NE(contacts[0].refusal.find("followed for 0.005"), std::string::npos) << contacts[0].refusal;
}

TEST(CueFollower, EverySettingOutOfItsDeclaredRangeIsRefusedByName)
{
  EXPECT_EQ(session::CueFollowerSettings().whyInvalid(), "");
  ASSERT_EQ(session::cueFollowerFields().size(), 5u);
  for (const auto& field : session::cueFollowerFields())
  {
    session::CueFollowerSettings defaults;
    EXPECT_GE(defaults.*field.member, field.min) << field.name;
    EXPECT_LE(defaults.*field.member, field.max) << field.name;
    for (const double bad : {field.min - 1e-3, field.max * 2 + 1, std::numeric_limits<double>::quiet_NaN()})
    {
      session::CueFollowerSettings settings;
      settings.*field.member = bad;
      const std::string why = settings.whyInvalid();
      EXPECT_NE(why.find(field.name), std::string::npos) << field.name << " = " << bad << ": " << why;
      EXPECT_THROW(CueFollower{settings}, std::invalid_argument) << field.name;
    }
  }
}

#include "cue_sim/session/cue_follower.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace cue_sim
{
namespace session
{
namespace
{
using physics::Vec3;

/// [m] how far short of the ball the strike's cue is drawn back along its axis: at the touch of a
/// stroke through the centre the tip's end lies on the ball to rounding, and aimCue refuses a tip
/// inside a ball. A nanometre changes no strike's parameters (they depend on the axis's line).
constexpr double kTouchBackoff = 1e-9;
/// Samples kept at most, whatever their rate: the velocity's fit needs a window's worth (300 at
/// 10 kHz); beyond it the fit's cost is bounded and its window shorter.
constexpr std::size_t kMaxSamples = 1024;

const physics::Ball<double>* findBall(const std::vector<physics::Ball<double>>& balls, int id)
{
  for (const auto& b : balls)
    if (b.id == id)
      return &b;
  return nullptr;
}

bool isPose(const physics::CuePose& pose)
{
  return std::isfinite(pose.stamp) && physics::isCue(pose.cue);
}
}  // namespace

const std::vector<CueFollowerField>& cueFollowerFields()
{
  // The ranges keep each setting to what it is for: a stroke is metres a second, a tracker's
  // jitter tenths of a millimetre, a tf rate between 10 Hz and 10 kHz.
  static const std::vector<CueFollowerField> fields{
      {"min_speed", &CueFollowerSettings::min_speed, "m/s", 0.0, 1.0,
       "slowest strike along the cue's axis; slower touches are reported, not struck"},
      {"rearm_distance", &CueFollowerSettings::rearm_distance, "m", 0.0, 0.05,
       "how far the tip must draw clear of a ball it touched before it may touch it again"},
      {"velocity_window", &CueFollowerSettings::velocity_window, "s", 0.001, 0.2,
       "the tip's velocity at a touch is fitted over this long before it; a cue followed for less "
       "strikes nothing"},
      {"max_gap", &CueFollowerSettings::max_gap, "s", 0.001, 1.0,
       "samples further apart are not swept (the cue's path between them is unknown)"},
      {"max_tip_speed", &CueFollowerSettings::max_tip_speed, "m/s", 1.0, 100.0,
       "a tip moving faster between two samples jumped (a tracker's glitch): not swept"},
  };
  return fields;
}

std::string CueFollowerSettings::whyInvalid() const
{
  for (const CueFollowerField& field : cueFollowerFields())
  {
    const double value = this->*field.member;
    if (!(value >= field.min && value <= field.max))
    {
      std::ostringstream why;
      why << field.name << " must be in [" << field.min << ", " << field.max << "] " << field.unit << ", got " << value;
      return why.str();
    }
  }
  return "";
}

CueFollower::CueFollower(const CueFollowerSettings& settings) : settings_(settings)
{
  const std::string why = settings_.whyInvalid();
  if (!why.empty())
    throw std::invalid_argument("cue follower: " + why);
}

void CueFollower::reset()
{
  samples_.clear();
  touched_.clear();
}

void CueFollower::restart(const physics::CuePose& pose)
{
  samples_.clear();
  samples_.push_back(pose);
  following_since_ = pose.stamp;
}

void CueFollower::forgetBefore(double stamp)
{
  while (samples_.size() > kMaxSamples || (samples_.size() > 2 && samples_[1].stamp < stamp))
    samples_.pop_front();
}

void CueFollower::rearm(const physics::CuePose& pose, const std::vector<physics::Ball<double>>& balls,
                        const physics::PhysicsParams<double>& params)
{
  const Vec3<double> centre = physics::tipCentre(pose.cue, params);
  const double clear = params.ball_radius + params.cue_tip_radius + settings_.rearm_distance;
  std::vector<int> still;
  for (const int id : touched_)
  {
    const physics::Ball<double>* ball = findBall(balls, id);
    if (ball && (ball->r - centre).norm() <= clear)
      still.push_back(id);
  }
  touched_ = still;
}

Vec3<double> CueFollower::tipVelocity(double stamp) const
{
  // The samples up to `stamp` (the touch), from the window before it on, and at least three: what
  // the tip did after the touch is not its stroke into the ball (a real cue is slowed by the
  // ball; a robot's follow-through starts there). Their times from `stamp` in units of the window
  // (the normal equations' columns then of one size): a parabola (constant acceleration) through
  // three or more, extrapolated to the touch less than a sample on; a line through two.
  std::vector<const physics::CuePose*> before;
  for (const auto& s : samples_)
    if (s.stamp <= stamp)
      before.push_back(&s);
  std::size_t first = before.size();
  while (first > 0 && (before[first - 1]->stamp >= stamp - settings_.velocity_window || before.size() - first < 3))
    --first;
  std::vector<const physics::CuePose*> used(before.begin() + static_cast<std::ptrdiff_t>(first), before.end());
  if (used.size() < 2)  // followed from the sample before the touch only (a refusal): the segment's
    used = {&samples_[samples_.size() - 2], &samples_.back()};
  const int terms = used.size() >= 3 ? 3 : 2;
  const double unit = settings_.velocity_window;
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d moments = Eigen::Matrix3d::Zero();  // row: term, column: axis
  for (const physics::CuePose* s : used)
  {
    const double tau = (s->stamp - stamp) / unit;
    const Eigen::Vector3d basis(1, tau, terms == 3 ? 0.5 * tau * tau : 0.0);
    normal += basis * basis.transpose();
    moments += basis * s->cue.tip.transpose();
  }
  if (terms == 2)
    normal(2, 2) = 1;  // the parabola's term held at zero
  const Eigen::Matrix3d fit = normal.ldlt().solve(moments);
  return fit.row(1).transpose() / unit;
}

CueContact CueFollower::contactOf(const physics::CueTouch& touch, const std::vector<physics::Ball<double>>& balls,
                                  const physics::PhysicsParams<double>& params) const
{
  CueContact contact;
  contact.ball_id = touch.ball_id;
  contact.stamp = touch.stamp;
  const Vec3<double> centre = physics::tipCentre(touch.cue, params);
  const physics::Ball<double>& ball = *findBall(balls, touch.ball_id);
  contact.point = ball.r + (centre - ball.r).normalized() * params.ball_radius;
  contact.velocity = tipVelocity(touch.stamp);
  const Vec3<double> axis = touch.cue.axis.normalized();
  contact.speed = contact.velocity.dot(axis);
  contact.cue = touch.cue;
  contact.cue.tip -= axis * kTouchBackoff;
  const double followed = touch.stamp - following_since_;
  if (followed < settings_.velocity_window)
  {
    std::ostringstream why;
    why << "the cue was followed for " << followed << " s before it touched ball " << contact.ball_id
        << ": its velocity there needs " << settings_.velocity_window << " s of its motion";
    contact.refusal = why.str();
  }
  else if (!(contact.speed >= settings_.min_speed))
  {
    std::ostringstream why;
    why << "the tip touched ball " << contact.ball_id << " at " << contact.speed
        << " m/s along the cue's axis, under the " << settings_.min_speed
        << " m/s a strike needs (a push, or a tracker's jitter)";
    contact.refusal = why.str();
  }
  return contact;
}

CueStep CueFollower::observe(const physics::CuePose& pose, const std::vector<physics::Ball<double>>& balls,
                             const physics::PhysicsParams<double>& params)
{
  CueStep step;
  std::ostringstream note;
  if (!isPose(pose))
  {
    step.note = "a sample that is not a pose (a stamp, tip and axis finite, the axis not zero): dropped";
    return step;
  }
  if (!samples_.empty() && !(pose.stamp > samples_.back().stamp))
  {
    note << "a sample at " << pose.stamp << " s, not after the last (" << samples_.back().stamp << " s): dropped";
    step.note = note.str();
    return step;
  }
  if (samples_.empty())
  {
    restart(pose);
    return step;
  }
  const physics::CuePose previous = samples_.back();
  const double gap = pose.stamp - previous.stamp;
  const double moved = (pose.cue.tip - previous.cue.tip).norm();
  if (gap > settings_.max_gap || moved > settings_.max_tip_speed * gap)
  {
    if (gap > settings_.max_gap)
      note << "no sample for " << gap << " s (more than " << settings_.max_gap << " s)";
    else
      note << "the tip jumped " << moved << " m in " << gap << " s (faster than " << settings_.max_tip_speed << " m/s)";
    note << ": not swept, the cue followed afresh from " << pose.stamp << " s";
    step.note = note.str();
    restart(pose);
    rearm(pose, balls, params);
    return step;
  }
  samples_.push_back(pose);
  std::vector<physics::Ball<double>> untouched;
  for (const auto& b : balls)
    if (std::find(touched_.begin(), touched_.end(), b.id) == touched_.end())
      untouched.push_back(b);  // a ball touched and not drawn clear of is not touched again
  const auto touch = physics::firstTouch(previous, pose, untouched, params);
  if (touch)
  {
    step.contact = contactOf(*touch, balls, params);
    touched_.push_back(touch->ball_id);
  }
  rearm(pose, balls, params);
  forgetBefore(pose.stamp - settings_.velocity_window);
  return step;
}

}  // namespace session
}  // namespace cue_sim

#include "learning/actions.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cue_sim/game/referee.hpp"

namespace cue_sim
{
namespace learning
{
ActionLayout::ActionLayout(const EnvOptions& options)
  : relative_(options.action == "relative"),
    spin_(options.spin),
    place_(isGameTask(options.task)),
    push_out_(place_ && game::makeRules(options.task)->pushOutAfterBreak())
{
  const auto add = [this](const char* name, double low, double high) {
    box_.names.emplace_back(name);
    box_.low.push_back(low);
    box_.high.push_back(high);
  };
  if (relative_)
  {
    add("ball", 0, 1);
    add("pocket", 0, 1);
    add("cut_offset", -kMaxCutOffset, kMaxCutOffset);
  }
  else
    add("phi", -M_PI, M_PI);
  add("speed", kMinActionSpeed, physics::CueLimits::max_speed);
  if (spin_)
  {
    add("theta", 0, physics::CueLimits::max_elevation);
    add("tip_right", -1, 1);
    add("tip_up", -1, 1);
  }
  if (place_)
  {
    add("place_x", 0, 1);
    add("place_y", 0, 1);
  }
  if (push_out_)
    add("push_out", 0, 1);
}

std::string ActionLayout::whyInvalid(const double* action, std::size_t size) const
{
  if (size == box_.size())
  {
    bool inside = true;
    for (std::size_t i = 0; i < size; ++i)
      inside = inside && action[i] >= box_.low[i] && action[i] <= box_.high[i];  // NaN fails both
    if (inside)
      return {};  // every step comes here: no stream is made for it
  }
  std::ostringstream why;
  if (size != box_.size())
  {
    why << "action: " << box_.size() << " values (";
    for (std::size_t i = 0; i < box_.size(); ++i)
      why << (i ? ", " : "") << box_.names[i];
    why << "), got " << size;
    return why.str();
  }
  for (std::size_t i = 0; i < size; ++i)
    if (!(action[i] >= box_.low[i] && action[i] <= box_.high[i]))  // NaN fails both
    {
      why << "action: " << box_.names[i] << " (component " << i << ") must be in [" << box_.low[i] << ", "
          << box_.high[i] << "], got " << action[i];
      return why.str();
    }
  return {};
}

void squareToTipOffset(double u, double v, double& a, double& b)
{
  const double r = physics::CueLimits::max_offset;
  a = r * u * std::sqrt(std::max(0.0, 1 - v * v / 2));
  b = r * v * std::sqrt(std::max(0.0, 1 - u * u / 2));
  const double norm = std::hypot(a, b);
  if (norm > r)  // rounding at the square's corners
  {
    a *= r / norm;
    b *= r / norm;
  }
}

double ghostBallHeading(const Eigen::Vector2d& cue, const Eigen::Vector2d& object, const Eigen::Vector2d& target,
                        double ball_radius)
{
  const Eigen::Vector2d to_target = target - object;
  const Eigen::Vector2d ghost =
      to_target.norm() > 0 ? Eigen::Vector2d(object - 2 * ball_radius * to_target.normalized()) : object;
  const Eigen::Vector2d aim = ghost - cue;
  return aim.norm() > 0 ? std::atan2(aim.y(), aim.x()) : 0.0;
}

Eigen::Vector2d pocketAimPoint(const physics::TableModel& table, const physics::Pocket& pocket)
{
  const Eigen::Vector2d half(table.clothLength() / 2, table.clothWidth() / 2);
  const Eigen::Vector2d from_centre = pocket.centre - table.clothCentre();
  return table.clothCentre() + from_centre.cwiseMax(-half).cwiseMin(half);
}

namespace
{
/// The item a value in [0, 1] picks out of `count`: equal shares, 1 taking the last.
std::size_t choice(double u, std::size_t count)
{
  return std::min(count - 1, static_cast<std::size_t>(u * static_cast<double>(count)));
}

/// An angle brought into [-pi, pi].
double wrapped(double angle)
{
  return std::remainder(angle, 2 * M_PI);
}
}  // namespace

ShotPlan ActionLayout::plan(const double* action, const AimContext& aim) const
{
  ShotPlan plan;
  physics::CueStrike<double>& s = plan.strike;
  std::size_t k = 0;
  if (relative_)
  {
    const double ball_u = action[k++], pocket_u = action[k++], offset = action[k++];
    s.phi = 0;
    const int cue_index = aim.table->indexOf(0);
    if (!aim.choices.empty() && !aim.model->pockets().empty() && cue_index >= 0)
    {
      plan.aimed_ball = aim.choices[choice(ball_u, aim.choices.size())];
      plan.aimed_pocket = static_cast<int>(choice(pocket_u, aim.model->pockets().size()));
      const auto& pocket = aim.model->pockets()[static_cast<std::size_t>(plan.aimed_pocket)];
      const Eigen::Vector2d cue = aim.table->balls[static_cast<std::size_t>(cue_index)].r.head<2>();
      const Eigen::Vector2d object =
          aim.table->balls[static_cast<std::size_t>(aim.table->indexOf(plan.aimed_ball))].r.head<2>();
      s.phi = ghostBallHeading(cue, object, pocketAimPoint(*aim.model, pocket), aim.ball_radius);
    }
    s.phi = wrapped(s.phi + offset);
  }
  else
    s.phi = action[k++];
  s.speed = action[k++];
  if (spin_)
  {
    s.theta = action[k++];
    const double u = action[k++], v = action[k++];
    squareToTipOffset(u, v, s.a, s.b);
  }
  if (place_)
    k += 2;
  if (push_out_)
    plan.push_out = action[k++] > 0.5;
  return plan;
}

bool ActionLayout::placement(const double* action, double& u, double& v) const
{
  if (!place_)
    return false;
  const std::size_t at = box_.size() - (push_out_ ? 3 : 2);
  u = action[at];
  v = action[at + 1];
  return true;
}

}  // namespace learning
}  // namespace cue_sim

#include "cue_sim/session/ball_orientations.hpp"

#include "cue_sim/physics/orientation.hpp"

namespace cue_sim
{
namespace session
{
namespace
{
bool sameState(const physics::Ball<double>& a, const physics::Ball<double>& b)
{
  return a.time == b.time && a.motion == b.motion && a.v == b.v && a.w == b.w && a.r == b.r;
}
}  // namespace

void BallOrientations::turn(const std::vector<physics::Ball<double>>& before,
                            const std::vector<physics::Ball<double>>& after, const physics::PhysicsParams<double>& p)
{
  std::map<int, const physics::Ball<double>*> old;
  for (const auto& b : before)
    old[b.id] = &b;
  for (const auto& b : after)
  {
    const auto was = old.find(b.id);
    if (was == old.end() || sameState(*was->second, b))
      continue;
    Eigen::Quaterniond& q = at_reference_.try_emplace(b.id, Eigen::Quaterniond::Identity()).first->second;
    q = (physics::rotationAlong(*was->second, b.time, p) * q).normalized();
  }
}

void BallOrientations::turnTo(const physics::Ball<double>& ball, double t, const physics::PhysicsParams<double>& p)
{
  Eigen::Quaterniond& q = at_reference_.try_emplace(ball.id, Eigen::Quaterniond::Identity()).first->second;
  q = (physics::rotationAlong(ball, t, p) * q).normalized();
}

std::vector<Eigen::Quaterniond> BallOrientations::at(const std::vector<physics::Ball<double>>& balls, double t,
                                                     const physics::PhysicsParams<double>& p) const
{
  std::vector<Eigen::Quaterniond> out;
  out.reserve(balls.size());
  for (const auto& b : balls)
  {
    const auto q = at_reference_.find(b.id);
    const Eigen::Quaterniond base = q == at_reference_.end() ? Eigen::Quaterniond::Identity() : q->second;
    out.push_back((physics::rotationAlong(b, t, p) * base).normalized());
  }
  return out;
}

void BallOrientations::keepOnly(const std::vector<physics::Ball<double>>& balls)
{
  std::map<int, Eigen::Quaterniond> kept;
  for (const auto& b : balls)
  {
    const auto q = at_reference_.find(b.id);
    kept[b.id] = q == at_reference_.end() ? Eigen::Quaterniond::Identity() : q->second;
  }
  at_reference_ = std::move(kept);
}

}  // namespace session
}  // namespace cue_sim

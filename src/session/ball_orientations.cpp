#include "cue_sim/session/ball_orientations.hpp"

#include "cue_sim/physics/motion.hpp"
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

Eigen::Quaterniond BallOrientations::turnedTo(const Track& track, double t, const physics::PhysicsParams<double>& p)
{
  if (!(t > track.t))
    return track.q;  // no time passed (or a clock set back at rest: nothing moved)
  return (physics::rotationAlong(physics::evolve(track.state, track.t, p), t, p) * track.q).normalized();
}

void BallOrientations::sync(const std::vector<physics::Ball<double>>& balls, const physics::PhysicsParams<double>& p)
{
  std::map<int, Track> synced;
  for (const auto& b : balls)
  {
    const auto was = tracks_.find(b.id);
    Track track;
    track.state = b;
    track.t = b.time;
    if (was != tracks_.end())
    {
      if (sameState(was->second.state, b))
        track = was->second;
      else
        track.q = turnedTo(was->second, b.time, p);  // its old motion lasted until its new state
    }
    synced.emplace(b.id, track);
  }
  tracks_ = std::move(synced);
}

std::vector<Eigen::Quaterniond> BallOrientations::advance(const std::vector<physics::Ball<double>>& balls, double t,
                                                          const physics::PhysicsParams<double>& p)
{
  std::vector<Eigen::Quaterniond> out;
  out.reserve(balls.size());
  for (const auto& b : balls)
  {
    Track& track = tracks_[b.id];
    track.q = turnedTo(track, t, p);
    track.t = std::max(track.t, t);
    out.push_back(track.q);
  }
  return out;
}

}  // namespace session
}  // namespace cue_sim

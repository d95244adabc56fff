#include "cue_sim/camera/exposure.hpp"

#include <algorithm>
#include <cmath>

namespace cue_sim
{
namespace camera
{
std::vector<BallPose> posesOf(const session::LiveBalls& live)
{
  const auto& balls = live.balls();
  const auto& orientations = live.orientations();
  std::vector<BallPose> poses(balls.size());
  for (std::size_t i = 0; i < balls.size(); ++i)
    poses[i] = {balls[i].id, balls[i].r, orientations[i], balls[i].inPlay()};
  return poses;
}

void advanceTo(session::LiveBalls& balls, const session::TableClock& clock, session::Stamp stamp)
{
  balls.advance(std::max(clock.at(stamp), balls.time()));
  balls.look();
}

int instantsFor(const session::LiveBalls& live, double physics_duration)
{
  const double radius = live.engine().params().ball_radius;
  double fastest = 0;
  for (const auto& b : live.balls())
    if (b.inPlay())
      fastest = std::max(fastest, b.v.norm() + radius * b.w.norm());
  const double travel = fastest * physics_duration;
  return static_cast<int>(std::min<double>(kMaxInstants, std::max(1.0, std::ceil(travel / kBlurStep))));
}

Exposure exposureOf(session::LiveBalls balls, const session::TableClock& clock, session::Stamp start, double duration)
{
  const session::Stamp length = static_cast<session::Stamp>(std::llround(duration * 1e9));
  advanceTo(balls, clock, start);
  const int count = instantsFor(balls, clock.at(start + length) - clock.at(start));
  Exposure exposure;
  exposure.instants.reserve(count);
  for (int i = 0; i < count; ++i)
  {
    advanceTo(balls, clock, start + static_cast<session::Stamp>(std::llround((i + 0.5) * length / count)));
    exposure.instants.push_back(posesOf(balls));
  }
  return exposure;
}

}  // namespace camera
}  // namespace cue_sim

#include "cue_sim/camera/exposure.hpp"

#include <algorithm>
#include <cmath>

namespace cue_sim
{
namespace camera
{
std::vector<BallPose> posesOf(const session::LiveTable& table)
{
  const auto& balls = table.balls();
  const auto& orientations = table.orientations();
  std::vector<BallPose> poses(balls.size());
  for (std::size_t i = 0; i < balls.size(); ++i)
    poses[i] = {balls[i].id, balls[i].r, orientations[i], balls[i].inPlay()};
  return poses;
}

int instantsFor(const session::LiveTable& table, double physics_duration)
{
  const double radius = table.engine().params().ball_radius;
  double fastest = 0;
  for (const auto& b : table.balls())
    if (b.inPlay())
      fastest = std::max(fastest, b.v.norm() + radius * b.w.norm());
  const double travel = fastest * physics_duration;
  return static_cast<int>(std::min<double>(kMaxInstants, std::max(1.0, std::ceil(travel / kBlurStep))));
}

Exposure exposureOf(session::LiveTable table, session::Stamp start, double duration)
{
  const session::Stamp length = static_cast<session::Stamp>(std::llround(duration * 1e9));
  table.advanceTo(start);
  const int count = instantsFor(table, table.physicsTime(start + length) - table.physicsTime(start));
  Exposure exposure;
  exposure.instants.reserve(count);
  for (int i = 0; i < count; ++i)
  {
    table.advanceTo(start + static_cast<session::Stamp>(std::llround((i + 0.5) * length / count)));
    exposure.instants.push_back(posesOf(table));
  }
  return exposure;
}

}  // namespace camera
}  // namespace cue_sim

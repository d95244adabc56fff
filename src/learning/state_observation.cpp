#include "learning/state_observation.hpp"

#include <algorithm>

namespace cue_sim
{
namespace learning
{
void addBallBlock(BoxSpec& box, int slots)
{
  for (int id = 0; id < slots; ++id)
  {
    const std::string ball = "ball" + std::to_string(id) + "_";
    for (const char* field : {"x", "y"})
    {
      box.names.push_back(ball + field);
      box.low.push_back(-kPositionBound);
      box.high.push_back(kPositionBound);
    }
    box.names.push_back(ball + "on_table");
    box.low.push_back(0);
    box.high.push_back(1);
  }
}

void writeBallBlock(const physics::TableModel& table, const physics::TableState<double>& state, float* out, int slots)
{
  std::fill(out, out + 3 * slots, 0.0f);
  const Eigen::Vector2d centre = table.clothCentre();
  const Eigen::Vector2d half(table.clothLength() / 2, table.clothWidth() / 2);
  for (const auto& ball : state.balls)
  {
    if (ball.id < 0 || ball.id >= slots || !ball.inPlay())
      continue;
    const Eigen::Vector2d p = (ball.r.head<2>() - centre).cwiseQuotient(half);
    float* slot = out + 3 * ball.id;
    slot[0] = static_cast<float>(std::clamp(p.x(), -kPositionBound, kPositionBound));
    slot[1] = static_cast<float>(std::clamp(p.y(), -kPositionBound, kPositionBound));
    slot[2] = 1.0f;
  }
}

}  // namespace learning
}  // namespace cue_sim

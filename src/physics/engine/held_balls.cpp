#include "physics/engine/held_balls.hpp"

#include <algorithm>

#include "cue_sim/physics/motion.hpp"

namespace cue_sim
{
namespace physics
{
template <typename S>
void letHeldBallsFall(TableState<S>& state, int mover, S time, const PhysicsParams<S>& params,
                      const std::vector<int>& candidates, std::vector<int>& fallen)
{
  const S reach = S(2) * params.ball_radius + S(kHeldReach);
  const Vec3<S> at = evolve(state.balls[mover], time, params).r;
  for (int j : candidates)
  {
    Ball<S>& ball = state.balls[j];
    if (j == mover || !ball.held() || (ball.r - at).norm() > reach)
      continue;
    ball.motion = Motion::Airborne;
    ball.time = std::max(ball.time, time);
    fallen.push_back(j);
  }
}

#define CUE_SIM_INSTANTIATE_HELD_BALLS(S)                                                                              \
  template void letHeldBallsFall(TableState<S>&, int, S, const PhysicsParams<S>&, const std::vector<int>&,             \
                                 std::vector<int>&);
CUE_SIM_INSTANTIATE_HELD_BALLS(double)
CUE_SIM_INSTANTIATE_HELD_BALLS(long double)

}  // namespace physics
}  // namespace cue_sim

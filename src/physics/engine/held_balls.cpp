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

template <typename S>
void releaseSupportedBalls(TableState<S>& state, S time, const PhysicsParams<S>& params, std::vector<int>& released)
{
  for (std::size_t j = 0; j < state.balls.size(); ++j)
  {
    Ball<S>& ball = state.balls[j];
    if (!ball.supported())
      continue;
    const S until = ball.piece.until;
    const Vec3<S> v_end = ball.piece.v_end;
    ball = evolve(ball, time, params);
    if (!(time < until))
      ball.v = v_end;
    ball.motion = Motion::Airborne;  // settled: in the air, or on the cloth
    settleMotion(ball, params.ball_radius);
    released.push_back(static_cast<int>(j));
  }
}

#define CUE_SIM_INSTANTIATE_HELD_BALLS(S)                                                                              \
  template void letHeldBallsFall(TableState<S>&, int, S, const PhysicsParams<S>&, const std::vector<int>&,             \
                                 std::vector<int>&);                                                                   \
  template void releaseSupportedBalls(TableState<S>&, S, const PhysicsParams<S>&, std::vector<int>&);
CUE_SIM_INSTANTIATE_HELD_BALLS(double)
CUE_SIM_INSTANTIATE_HELD_BALLS(long double)

}  // namespace physics
}  // namespace cue_sim

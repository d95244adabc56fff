// What a preview draws of a predicted shot: the path of each ball that moves, from the strike to
// rest, as points on its exact trajectory (the prediction keeps each ball's closed-form pieces as
// its one run made them). Evaluated, not simulated: drawing a preview runs no shot.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "cue_sim/session/shot_prediction.hpp"

namespace cue_sim
{
namespace session
{
struct PreviewPath
{
  int id = -1;
  std::vector<Eigen::Vector2d> points;  ///< [m] in the table frame, while the ball is on the cloth
};

/// The paths of the balls that move in `prediction` (made with PredictionOptions::trajectories):
/// points every max(0.02 s, the shot's duration / max_points), and at each change of a ball's
/// motion, so that every bounce is a corner. Empty if the prediction failed or kept no trajectories.
std::vector<PreviewPath> previewPaths(const ShotPrediction& prediction, const physics::PhysicsParams<double>& params,
                                      std::size_t max_points = 2000);

/// previewPaths' path of ball `id` alone (what rviz shows of a three-cushion point); empty points
/// if it did not move or the prediction kept no trajectories.
PreviewPath ballPath(const ShotPrediction& prediction, const physics::PhysicsParams<double>& params, int id);

}  // namespace session
}  // namespace cue_sim

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

/// The path of the ball struck in `shot` from `start` (run to rest once, keeping its trajectory),
/// drawn as previewPaths draws it: what rviz shows of a three-cushion point. Empty points if the
/// shot cannot be played from `start`.
PreviewPath shotPath(const physics::Engine<double>& engine, const physics::TableState<double>& start, const Shot& shot);

}  // namespace session
}  // namespace cue_sim

#include "cue_sim/session/shot_preview.hpp"

#include <algorithm>

namespace cue_sim
{
namespace session
{
namespace
{
/// The times a ball's path is drawn at: the grid, its own changes, the end.
std::vector<double> drawingTimes(const BallTrajectory& trajectory, double start, double end, double period)
{
  std::vector<double> times;
  for (double t = start; t < end; t += period)
    times.push_back(t);
  for (const auto& piece : trajectory.pieces)
    if (piece.start > start && piece.start < end)
      times.push_back(piece.start);
  times.push_back(end);
  std::sort(times.begin(), times.end());
  return times;
}
}  // namespace

std::vector<PreviewPath> previewPaths(const ShotPrediction& prediction, const physics::PhysicsParams<double>& params,
                                      std::size_t max_points)
{
  std::vector<PreviewPath> paths;
  if (!prediction.success)
    return paths;
  const double start = prediction.strike_time, end = prediction.strike_time + prediction.time_to_rest;
  const double period =
      std::max(0.02, prediction.time_to_rest / static_cast<double>(std::max<std::size_t>(1, max_points)));
  for (const BallTrajectory& trajectory : prediction.trajectories)
  {
    PreviewPath path;
    path.id = trajectory.id;
    for (double t : drawingTimes(trajectory, start, end, period))
    {
      const physics::Ball<double> ball = trajectory.at(t, params);
      if (ball.inPlay())
        path.points.push_back(ball.r.head<2>());
    }
    // Only the balls that move have a path worth drawing.
    const bool moved = std::any_of(path.points.begin(), path.points.end(),
                                   [&](const Eigen::Vector2d& p) { return p != path.points.front(); });
    if (moved)
      paths.push_back(std::move(path));
  }
  return paths;
}

PreviewPath ballPath(const ShotPrediction& prediction, const physics::PhysicsParams<double>& params, int id)
{
  for (PreviewPath& path : previewPaths(prediction, params))
    if (path.id == id)
      return std::move(path);
  PreviewPath none;
  none.id = id;
  return none;
}

}  // namespace session
}  // namespace cue_sim

// The campaign: shots in chunks on a thread pool, tallied, and each violation written as a scene
// file that reproduces it.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>

#include "cue_sim/evaluation/soak.hpp"
#include "cue_sim/physics/thread_pool.hpp"

namespace cue_sim
{
namespace evaluation
{
namespace
{
/// How often the progress is shown [s].
constexpr double kProgressPeriod = 1.0;

std::string ballsBucket(std::size_t count)
{
  return count <= 16 ? "1-16" : count <= 64 ? "17-64" : "65-200";
}

/// Writes the scene with the violations it showed and how to see them again; returns the file.
std::string writeViolation(const SoakOptions& options, long k, const Scene& scene, const SceneCheck& check)
{
  std::ostringstream comment;
  comment << "soak --seed " << options.seed << " --first " << k << " --shots 1"
          << (options.airborne ? " --airborne" : "") << ": shot " << k << " broke\n";
  for (const Violation& v : check.violations)
    comment << "  " << v.kind << ": " << v.detail << "\n";
  const std::string name = "soak_" + std::to_string(options.seed) + "_" + std::to_string(k) + ".yaml";
  const std::filesystem::path path = std::filesystem::path(options.out_dir.empty() ? "." : options.out_dir) / name;
  comment << "Checked again: soak --replay " << path.string() << "\nIts events: simulate " << path.string();
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path) << sceneYaml(scene, comment.str());
  return path.string();
}
}  // namespace

SoakSummary runSoak(const SoakOptions& options, const std::function<void(const SoakSummary&)>& progress)
{
  const auto started = std::chrono::steady_clock::now();
  const auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  };
  physics::ThreadPool pool(options.threads);
  SoakSummary summary;
  double shown = 0;
  std::mutex mutex;
  // One loop over every shot: each thread takes the next shot when it is done, so a long shot
  // holds up no other.
  pool.parallelFor(static_cast<std::size_t>(options.shots), [&](std::size_t i) {
    const long k = options.first + static_cast<long>(i);
    const Scene scene = soakScene(options.seed, k, options.airborne);
    const bool small = scene.state.balls.size() <= 40;
    const auto shot_started = std::chrono::steady_clock::now();
    const SceneCheck check = checkScene(scene, small || k % std::max(1L, options.full_scan_every) == 0);
    const double shot_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - shot_started).count();
    std::string written;
    if (!check.violations.empty())
      written = writeViolation(options, k, scene, check);
    const std::lock_guard<std::mutex> lock(mutex);
    ++summary.shots;
    summary.events += check.events;
    summary.scanned += check.scanned;
    summary.at_rest += check.at_rest;
    summary.endless += !check.endless.empty();
    ++summary.by_table[scene.table_name];
    const std::string regime = scene.models.ball_ball + "/" + scene.models.cushion +
                               (options.airborne ? "/" + scene.models.ball_table + "/" + scene.models.cue : "");
    ++summary.by_models[regime];
    ++summary.regime_shots[regime];
    summary.regime_seconds[regime] += shot_seconds;
    ++summary.by_balls[ballsBucket(scene.state.balls.size())];
    for (const Violation& v : check.violations)
      ++summary.violations[v.kind];
    if (!written.empty())
      summary.reports.push_back("shot " + std::to_string(k) + ": " + check.violations.front().kind + " (" +
                                check.violations.front().detail + "): " + written);
    summary.seconds = elapsed();
    if (progress && summary.seconds > shown + kProgressPeriod)
    {
      shown = summary.seconds;
      progress(summary);
    }
  });
  summary.seconds = elapsed();
  if (progress)
    progress(summary);
  return summary;
}

}  // namespace evaluation
}  // namespace cue_sim

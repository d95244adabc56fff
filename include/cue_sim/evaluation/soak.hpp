// The soak campaign: random scenes on every bundled table, in every model, with every coefficient
// across its whole accepted range and 1 to 200 balls, each run three ways and checked at every
// event (doc/accuracy.md, "Soak campaign"). Scene k of a campaign depends on (seed, k) alone, so any shot
// can be made again, and each violation is written as a scene file that reproduces it.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "cue_sim/scene/scene_file.hpp"

namespace cue_sim
{
namespace evaluation
{
/// The limits a campaign's shots run under: at least 20 s of each shot (longer where the
/// coefficients take longer to stop every ball: src/evaluation/soak/shot_ending.hpp), and an event
/// allowance no real shot comes near (a break has a few hundred events; 200 balls at a tenth of the
/// Earth's gravity a few thousand; 119 large balls rolling without resistance and bouncing
/// elastically on a 9-ft table 380 000). A shot that reaches it is a violation: events that
/// never end.
struct SoakLimits
{
  static constexpr double max_shot_time = 20.0;  ///< [s], the least a shot is given
  static constexpr long max_events = 3000000;
};

/// What a shot broke, and where.
struct Violation
{
  /// nan, overlap, off_table (in a cushion, jaw or pocket, or off the playing area), energy_gain,
  /// still_moving (moving when every ball's coefficients must have stopped it, none of them zero),
  /// not_repeatable (advanced in steps, or copied mid-shot, it did not give the same events and
  /// state bit for bit), scan_mismatch (the kept search and the full scan of every ball and pair
  /// disagree), event_limit (unless the shot cannot end by physics and its events were not a
  /// storm at one instant: then it is endless), invalid_start (the campaign made a scene validation refuses),
  /// invalid_end (the balls at rest make a scene validation refuses), error (anything thrown).
  std::string kind;
  std::string detail;
};

/// Scene k of the campaign with this seed. With `airborne` (issue 33), balls also fly: some are
/// thrown (up to 0.3 m above the cloth, up to 6 m/s, up or down at up to 3 m/s), one may be dropped
/// onto another, and the ball-table and cue models are drawn too (the sequential cue lifts the
/// struck ball). Its violations' scene files hold the balls in the air too (their height and
/// vertical speed).
Scene soakScene(std::uint64_t seed, long k, bool airborne = false);

struct SceneCheck
{
  std::vector<Violation> violations;  ///< the first of each kind
  long events = 0;
  bool at_rest = false;
  /// Not at rest, and cannot be by physics: why (a ball rolling with mu_roll = 0, ...); not a
  /// violation.
  std::string endless;
  bool scanned = false;  ///< whether the full scan was compared
};

/// Runs the scene (struck, if it has a shot) event by event until it is at rest or every ball must
/// have stopped (stoppingTime), checking after every event and at the end that no number is NaN, no ball overlaps
/// another or a cushion, jaw or pocket by more than 1e-9 m or is off the playing area, and the kinetic energy has not
/// grown (1e-12 of it), and that the balls at rest make a scene the engine accepts (Engine::whyInvalid, as `simulate`);
/// then again advanced in uneven steps and copied mid-shot, which must give the same events and
/// final state bit for bit; then, if `full_scan`, by the full scan of every ball and pair, which
/// must too.
SceneCheck checkScene(const Scene& scene, bool full_scan);

struct SoakOptions
{
  std::uint64_t seed = 1;
  long first = 0;            ///< the first shot's number
  long shots = 1000;         ///< how many
  unsigned threads = 0;      ///< 0: every core
  std::string out_dir;       ///< where violations are written as scene files (created if needed)
  long full_scan_every = 4;  ///< the full scan on every this many shots of more than 40 balls (all smaller ones)
  bool airborne = false;     ///< scenes with balls in the air (soakScene)
};

struct SoakSummary
{
  long shots = 0, events = 0, scanned = 0, at_rest = 0;
  long endless = 0;  ///< shots that cannot end by physics (SceneCheck::endless): not violations
  std::map<std::string, long> by_table, by_models, by_balls;  ///< shots of each kind
  /// Each regime's shots and the time their checks took (one thread's): its shots per second.
  std::map<std::string, long> regime_shots;
  std::map<std::string, double> regime_seconds;
  std::map<std::string, long> violations;  ///< by kind
  /// Each shot that broke something: its number, what, and the scene file that reproduces it.
  std::vector<std::string> reports;
  double seconds = 0;
};

/// Runs shots first to first + shots - 1 on a thread pool. `progress` is called now and then
/// with the summary so far.
SoakSummary runSoak(const SoakOptions& options, const std::function<void(const SoakSummary&)>& progress = {});

}  // namespace evaluation
}  // namespace cue_sim

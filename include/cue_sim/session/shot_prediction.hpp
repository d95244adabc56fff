// What a shot would do: the engine run on a copy of a table. The live table's strikes, its
// predictions and batches of predictions all go through predictShot, so that they agree bit for
// bit. Read-only on the engine: predictions may run on several threads at once.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "cue_sim/physics/engine.hpp"
#include "cue_sim/physics/execution_noise.hpp"
#include "cue_sim/physics/thread_pool.hpp"

namespace cue_sim
{
namespace session
{
/// A cue strike on one ball.
struct Shot
{
  int ball_id = 0;
  physics::CueStrike<double> strike;
};

/// What a request may ask for, checked before any work is done (or, for what only the shots
/// themselves tell, before the samples and the reply are built). Each bounds a request's cost
/// and the memory of its reply.
struct PredictionLimits
{
  /// Shots in one batch: each is a run to rest (a break takes about 35 us, a slow shot with
  /// many events a few ms).
  std::size_t max_batch_shots = 10000;
  /// Samples in one reply, all its shots together: a sample holds every ball (about 100 bytes
  /// each in a message).
  std::size_t max_samples = 100000;
  /// Samples of one shot; ~predict's documented limit.
  std::size_t max_samples_per_shot = 10000;
  /// Bytes of one reply, by the sizes below: events, final balls and samples.
  std::size_t max_reply_bytes = std::size_t(256) << 20;
};

/// The bytes a reply's parts take in a message, serialised (a little more than the fields, for
/// the strings they carry): what PredictionLimits::max_reply_bytes counts.
struct ReplySize
{
  static constexpr std::size_t event = 96;
  static constexpr std::size_t ball = 112;
  static constexpr std::size_t shot = 160;  ///< a prediction's own fields and message
};

struct PredictionOptions
{
  double sample_period = 0;                        ///< [s]; 0: no samples
  const physics::ExecutionNoise* noise = nullptr;  ///< null: the shot as asked
  std::uint64_t seed = 0;                          ///< of the noise
  bool trajectories = false;                       ///< keep each ball's trajectory (a preview draws them)
};

/// One ball's exact path through a shot, as its closed-form pieces: its state from the strike, and
/// again after each event that changed it. Where it is at any time of the shot is
/// physics::evolve of the last piece that starts at or before that time: no simulation.
struct BallTrajectory
{
  struct Piece
  {
    double start = 0;  ///< [s] physics time from which `ball` holds (the event that made it)
    physics::Ball<double> ball;
  };
  int id = -1;
  std::vector<Piece> pieces;  ///< by start, the first at the strike

  /// The ball at physics time t (from the first piece's start on), exactly as the shot's own
  /// simulation has it then: events at t included.
  physics::Ball<double> at(double t, const physics::PhysicsParams<double>& params) const;
};

struct ShotPrediction
{
  bool success = false;
  std::string message;      ///< why not, when success is false; else a summary
  Shot executed;            ///< the shot plus execution noise, if asked for
  double time_to_rest = 0;  ///< [s] from the strike to the last event
  bool at_rest = false;     ///< false if the shot still moved at the engine's max_shot_time
  double strike_time = 0;   ///< the physics time of the strike: events' shot times count from it
  std::vector<physics::Ball<double>> final_balls;
  std::vector<physics::Event<double>> events;
  std::vector<std::vector<physics::Ball<double>>> samples;  ///< at strike_time + k sample_period
  std::vector<BallTrajectory> trajectories;                 ///< each ball's, in the table's order, if asked

  /// The bytes of this prediction in a reply (ReplySize).
  std::size_t replyBytes() const;
};

/// Empty if `period` [s] is 0 (no samples) or in [0.001, 10], else why not.
std::string whyBadSamplePeriod(double period);

/// Strikes `start` and runs it to rest, once: the samples (at most limits.max_samples_per_shot)
/// and trajectories asked for are taken from that one run. A refused shot gives success false and
/// the reason, by field.
ShotPrediction predictShot(const physics::Engine<double>& engine, const physics::TableState<double>& start,
                           const Shot& shot, const PredictionOptions& options, const PredictionLimits& limits = {});

/// Many shots from one table on the pool's threads; shot i uses seed + i. Each runs to rest once,
/// and, if sampled, once more once the reply is known to fit (its samples are taken then, so that
/// a batch that will not fit holds no samples). Trajectories are not kept. Refused as a whole
/// (`why` says how big the request is and which limit it passes) if it has more shots than
/// max_batch_shots, or, once every shot has run to rest, if their samples or the reply would
/// pass max_samples or max_reply_bytes: no samples are then taken and nothing is returned.
std::vector<ShotPrediction> predictBatch(const physics::Engine<double>& engine,
                                         const physics::TableState<double>& start, const std::vector<Shot>& shots,
                                         const PredictionOptions& options, const PredictionLimits& limits,
                                         physics::ThreadPool& pool, std::string& why);

}  // namespace session
}  // namespace cue_sim

// Many shots from one table state, run on all cores of a ThreadPool. Each outcome is exactly
// what Engine::strike and simulateToRest give for that shot alone, bit for bit.
#pragma once

#include <string>
#include <vector>

#include "cue_sim/physics/simulation.hpp"
#include "cue_sim/physics/thread_pool.hpp"

namespace cue_sim
{
namespace physics
{
template <typename S>
struct BatchShot
{
  int ball_id = 0;  ///< the ball the cue strikes
  CueStrike<S> cue;
};

template <typename S>
struct ShotOutcome
{
  /// Empty if the shot ran to rest or to max_shot_time; else why it was not run (the strike
  /// is refused, as by Engine::whyNotStrikable) or why it stopped (the event limit).
  std::string error;
  TableState<S> state;   ///< where the shot ended (the start state if it was refused)
  ShotResult<S> result;  ///< its events, duration and whether it came to rest
};

/// Runs every shot from `start` on the pool's threads; outcomes are in the order of `shots`.
template <typename S>
std::vector<ShotOutcome<S>> simulateBatch(const Engine<S>& engine, const TableState<S>& start,
                                          const std::vector<BatchShot<S>>& shots, ThreadPool& pool);

}  // namespace physics
}  // namespace cue_sim

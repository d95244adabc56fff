// Tables drawn for a task's episode: the cue ball and object balls 1 to n, each uniformly where a
// ball in hand may go (clear of the cushions, the pockets' mouths and the other balls).
#pragma once

#include "cue_sim/learning/random.hpp"
#include "cue_sim/physics/engine.hpp"

namespace cue_sim
{
namespace learning
{
/// The cue ball and balls 1 to `count` at rest, drawn from `random` (drawn again until all fit).
physics::TableState<double> scatteredBalls(const physics::Engine<double>& engine, int count, Random& random);

}  // namespace learning
}  // namespace cue_sim

// The factory of every ruleset in rulesets.def, each defined in its own file
// (src/game/rules/<name>.cpp). Private to the referee.
#pragma once

#include <memory>

#include "cue_sim/game/referee.hpp"

namespace cue_sim
{
namespace game
{
#define CUE_SIM_RULES(name, ...) std::unique_ptr<Rules> make_rules_##name();
#include "cue_sim/game/rulesets.def"
#undef CUE_SIM_RULES

/// The cue ball's placement and the shooter's count after a standard foul by `shooter`: ball in
/// hand anywhere for the other player (WPA 1.5, 6).
Ruling standardFoul(int shooter, const std::string& rule, const std::string& reason);

/// The first standard foul of a shot, if any, under the general fouls every game shares (WPA
/// 6.1 scratch, 6.2 wrong ball first, 6.3 no rail after contact); `legal_first` the balls the
/// shooter may hit first. Empty rule if none.
Ruling generalFoul(int shooter, const ShotFacts& facts, const std::vector<int>& legal_first, bool check_first_and_rail);

/// Puts ball `id` back on the table at rest with its centre at p: spotted.
void spotAt(physics::TableState<double>& balls, int id, const Eigen::Vector2d& p, double ball_radius);

/// "balls 3, 5 and 9" for a ruling's text.
std::string ballList(const std::vector<int>& ids);

}  // namespace game
}  // namespace cue_sim

// 8-ball under the WPA World Standardized Rules (Rules of Play, 2016): section 3 (eight ball),
// 1.4-1.6 (spotting, ball in hand, call shot) and 6 (fouls). Clause letters of 3.3 are the
// break shot's. The rules' later clauses (continuing play, losing the rack) are cited by
// section and name: their numbers could not be checked here.
//
// Where the rules leave a choice to a player, the simulator takes one:
// - an illegal break (3.3(d)): the balls are re-racked and the incoming player breaks;
// - the 8-ball pocketed on the break (3.3(e), 3.3(f)): it is spotted (1.4) and play goes on;
// - a shot with no ball called (1.6: obvious balls need not be called): the simulator cannot
//   judge what is obvious, so an uncalled shot counts as called on the first of the shooter's
//   balls it pockets, in the pocket it drops into; so does an uncalled shot at the 8-ball.
#include <algorithm>

#include "game/rules/rules_factories.hpp"

namespace cue_sim
{
namespace game
{
namespace
{
bool contains(const std::vector<int>& ids, int id)
{
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

Group groupOf(int ball)
{
  return ball < 8 ? Group::Solids : Group::Stripes;
}
Group otherGroup(Group g)
{
  return g == Group::Solids ? Group::Stripes : Group::Solids;
}
bool inGroup(int ball, Group g)
{
  return ball != 8 && groupOf(ball) == g;
}

class EightBall : public Rules
{
public:
  std::string rack() const override { return "eight"; }
  bool callsShots() const override { return true; }
  bool playsGroups() const override { return true; }

  std::vector<int> legalFirst(const GameState& state, const std::vector<int>& on_table) const override
  {
    const Group group = state.groups[state.turn];
    std::vector<int> legal;
    for (const int id : on_table)
      if (state.break_shot || (group == Group::Open ? id != 8 : inGroup(id, group)))
        legal.push_back(id);
    if (legal.empty() && contains(on_table, 8))
      legal.push_back(8);  // the group is cleared: the 8-ball is the object ball
    return legal;
  }

  Ruling judge(const GameState& state, const std::vector<int>& on_table, const Shot& shot) const override
  {
    if (state.break_shot)
      return judgeBreak(state, shot.facts);
    const int shooter = state.turn;
    const ShotFacts& f = shot.facts;
    const std::vector<int> legal = legalFirst(state, on_table);
    Ruling foul = generalFoul(shooter, f, legal, true);
    foul.groups = state.groups;
    if (contains(f.off_table, 8))
      return eightOffTable(state, foul);
    spotJumped(f, foul);
    const auto eight = std::find(f.pocketed.begin(), f.pocketed.end(), 8);
    if (eight != f.pocketed.end())
      return eightPocketed(state, legal, foul, f, f.pockets[static_cast<std::size_t>(eight - f.pocketed.begin())]);
    if (foul.foul)
      return foul;
    return judgeLegalShot(state, f);
  }

private:
  /// Object balls driven off the table are spotted (WPA 1.4) after the shot, the 8-ball with them on
  /// the break: a group with a ball off the table could never be cleared.
  static void spotJumped(const ShotFacts& f, Ruling& r)
  {
    r.respot.insert(r.respot.end(), f.off_table.begin(), f.off_table.end());
    if (!f.off_table.empty())
      r.reason += "; " + ballList(f.off_table) + " spotted (WPA 1.4)";
  }

  /// After the break, driving the 8-ball off the table loses the rack (WPA 3, losing the rack).
  static Ruling eightOffTable(const GameState& state, const Ruling& foul)
  {
    Ruling r = foul;
    r.foul = true;
    r.rule = "WPA 6.5";
    r.game_over = true;
    r.winner = 1 - state.turn;
    r.next_player = 1 - state.turn;
    r.ball_in_hand = BallInHand::None;
    r.reason = "the 8-ball was driven off the table (WPA 6.5), which loses the rack (WPA 3, losing the rack)";
    return r;
  }

  /// WPA 3.3: the break shot. No ball is called and any ball may be hit first.
  Ruling judgeBreak(const GameState& state, const ShotFacts& f) const
  {
    const int breaker = state.turn;
    Ruling r;
    r.groups = {Group::Open, Group::Open};  // 3.4: the table is open after the break
    const bool eight = contains(f.pocketed, 8);
    if (eight)
      r.respot = {8};
    if ((f.cue_ball_off_table || !f.off_table.empty()) && !f.scratch)
    {
      Ruling jumped = generalFoul(breaker, f, {}, false);
      jumped.groups = r.groups;
      jumped.respot = r.respot;
      jumped.reason = "foul on the break: " + jumped.reason + "; the table is open";
      spotJumped(f, jumped);
      return jumped;
    }
    if (f.scratch)
    {
      r.foul = true;
      r.rule = eight ? "WPA 3.3(f)" : "WPA 3.3(h)";
      r.reason = std::string("foul (") + r.rule + ", scratch on the break): the cue ball was pocketed" +
                 (eight ? "; the 8-ball is spotted (the simulator takes that option)" : "") +
                 "; the table is open and the incoming player has the cue ball in hand behind the head string";
      r.next_player = 1 - breaker;
      r.ball_in_hand = BallInHand::BehindHeadString;
      return r;
    }
    if (f.pocketed.empty() && f.object_balls_to_rail < 4)
    {
      r.rule = "WPA 3.3(d)";
      r.reason = "illegal break (WPA 3.3(d)): nothing was pocketed and only " + std::to_string(f.object_balls_to_rail) +
                 " object balls reached a rail (4 needed); the balls are re-racked and the incoming player breaks "
                 "(the simulator takes that option)";
      r.rerack = true;
      r.next_player = 1 - breaker;
      return r;
    }
    if (eight)
    {
      r.rule = "WPA 3.3(e)";
      r.reason =
          "legal break with the 8-ball pocketed (WPA 3.3(e)): not a foul; the 8-ball is spotted (1.4) and the "
          "breaker continues on an open table";
      r.continues = true;
      r.next_player = breaker;
      return r;
    }
    r.rule = "WPA 3.3(c)";
    r.continues = !f.pocketed.empty();
    r.next_player = r.continues ? breaker : 1 - breaker;
    r.reason = r.continues ? "legal break (WPA 3.3(c)): " + ballList(f.pocketed) +
                                 " pocketed; the breaker continues and the table is open (3.4)"
                           : "legal break (WPA 3.3): " + std::to_string(f.object_balls_to_rail) +
                                 " object balls reached a rail, none pocketed; the turn passes";
    return r;
  }

  /// The 8-ball went down after the break: the shooter wins if it was the object ball (the group
  /// cleared before the shot), no foul was committed and it dropped in the called pocket;
  /// otherwise the shooter loses the rack (WPA 3, losing the rack).
  Ruling eightPocketed(const GameState& state, const std::vector<int>& legal, Ruling foul, const ShotFacts& f,
                       int pocket) const
  {
    const int shooter = state.turn;
    Ruling r;
    r.groups = state.groups;
    r.game_over = true;
    r.next_player = 1 - shooter;
    const bool object = legal.size() == 1 && legal.front() == 8;
    const bool in_called = state.called_pocket < 0 || pocket == state.called_pocket;
    if (object && !foul.foul && in_called)
    {
      r.rule = "WPA 3";
      r.winner = shooter;
      r.reason = "the 8-ball is pocketed legally in " + f.pocketName(pocket) + ": the shooter wins the rack";
      return r;
    }
    r.foul = foul.foul;
    r.winner = 1 - shooter;
    if (foul.foul)
    {
      r.rule = foul.rule;
      r.reason = "the 8-ball was pocketed on a foul, which loses the rack (WPA 3, losing the rack): " + foul.reason;
    }
    else if (!object)
    {
      r.rule = "WPA 3";
      r.reason =
          "the 8-ball was pocketed before the shooter's group was cleared (or with its last ball), which loses "
          "the rack (WPA 3, losing the rack)";
    }
    else
    {
      r.rule = "WPA 1.6";
      r.reason = "the 8-ball dropped in " + f.pocketName(pocket) + ", not the called " +
                 f.pocketName(state.called_pocket) + ", which loses the rack (WPA 1.6, WPA 3)";
    }
    return r;
  }

  /// A shot without a foul that did not pocket the 8-ball: the shooter continues if it pocketed
  /// the called ball (or, uncalled, one of its own) in the called pocket; on an open table that
  /// ball chooses the groups (WPA 3.4).
  Ruling judgeLegalShot(const GameState& state, const ShotFacts& f) const
  {
    const int shooter = state.turn;
    Ruling r;
    r.groups = state.groups;
    const Group group = state.groups[shooter];
    int counted = -1;
    for (std::size_t k = 0; k < f.pocketed.size() && counted < 0; ++k)
    {
      const int id = f.pocketed[k];
      const bool own = group == Group::Open ? id != 8 : inGroup(id, group);
      const bool as_called =
          state.called_ball < 0 ||
          (id == state.called_ball && (state.called_pocket < 0 || f.pockets[k] == state.called_pocket));
      if (own && as_called)
        counted = id;
    }
    if (counted < 0)
    {
      r.rule = "WPA 1.6";
      r.next_player = 1 - shooter;
      r.reason = f.pocketed.empty() ? "no foul, nothing pocketed: the turn passes"
                                    : "no foul, but " + ballList(f.pocketed) +
                                          " is not the shooter's called ball in its called pocket (WPA 1.6): the balls "
                                          "stay down and the turn passes";
      return r;
    }
    r.continues = true;
    r.next_player = shooter;
    if (group == Group::Open)
    {
      r.groups[shooter] = groupOf(counted);
      r.groups[1 - shooter] = otherGroup(groupOf(counted));
      r.rule = "WPA 3.4";
      r.reason = "ball " + std::to_string(counted) + " pocketed legally on an open table: the shooter takes the " +
                 groupName(groupOf(counted)) + " (WPA 3.4) and continues";
      return r;
    }
    r.rule = "WPA 1.6";
    r.reason = "ball " + std::to_string(counted) + " pocketed legally: the shooter continues";
    return r;
  }
};
}  // namespace

std::unique_ptr<Rules> make_rules_eight_ball()
{
  return std::make_unique<EightBall>();
}

}  // namespace game
}  // namespace cue_sim

// A game between two players, as data: whose turn it is, what each may hit, where the cue ball
// may be placed, the score where the game keeps one, and what the last shot's ruling said. The referee (referee.hpp)
// takes it with a shot's events and gives the ruling and the next state. No ROS.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace cue_sim
{
namespace game
{
/// 8-ball's groups (WPA 3.4): solids 1-7, stripes 9-15; open until a player legally pockets a
/// called ball after the break.
enum class Group
{
  Open,
  Solids,
  Stripes,
};

/// Where the incoming player may place the cue ball before the next shot.
enum class BallInHand
{
  None,              ///< play it where it lies
  Anywhere,          ///< anywhere on the cloth (WPA 1.5), after a standard foul
  BehindHeadString,  ///< its centre behind the head string (WPA Definitions), on a break
  InD,               ///< its centre in the D (snooker: WPBSA Section 3, Play from in-hand)
};

const char* groupName(Group group);
const char* ballInHandName(BallInHand place);

struct GameState
{
  std::string rules;  ///< a ruleset's name (rulesNames())
  std::array<std::string, 2> players{"player 1", "player 2"};
  int turn = 0;                   ///< whose shot is next: 0 or 1
  bool break_shot = true;         ///< the next shot breaks the rack
  bool push_out_allowed = false;  ///< 9- and 10-ball: the shot after a legal break may be a push-out
  std::array<Group, 2> groups{Group::Open, Group::Open};  ///< 8-ball
  int called_ball = -1;                                   ///< the ball called for the next shot, -1 for none
  int called_pocket = -1;  ///< the pocket called (TableModel::pockets index), -1 for none
  std::array<int, 2> consecutive_fouls{0, 0};
  BallInHand ball_in_hand = BallInHand::BehindHeadString;
  int shots = 0;  ///< shots played in this game
  /// Where the game keeps a score (three-cushion's points): each player's, and the points that
  /// win (0: the game keeps none).
  std::array<int, 2> score{0, 0};
  int target = 0;
  std::array<int, 2> innings{0, 0};  ///< the innings each player has begun (a turn at the table)
  /// What the rules did to the balls at rest before the next shot, and why (three-cushion
  /// re-spots a cue ball frozen to an object ball); empty for nothing.
  std::string before_shot;
  /// Snooker: a red has just been potted, so the ball on is a colour, the one the cue ball meets
  /// first (the simulator's nomination).
  bool colour_next = false;
  /// Snooker: a free ball (WPBSA Section 3, Free Ball): the last shot was a foul that left the
  /// incoming player snookered on every ball on, so any ball may be nominated as one.
  bool free_ball = false;
  bool last_shot_foul = false;  ///< the last shot's ruling was a foul
  bool over = false;
  int winner = -1;  ///< 0 or 1 once over; -1 for none (a game stopped by the shot cap)
};

/// What the referee decided about one shot.
struct Ruling
{
  bool foul = false;
  std::string rule;        ///< the rule the ruling rests on, e.g. "WPA 6.1"
  std::string reason;      ///< the rule and why, in a sentence
  bool continues = false;  ///< the shooter plays again
  int next_player = 0;
  BallInHand ball_in_hand = BallInHand::None;
  std::vector<int> respot;  ///< balls to spot on the long string (WPA 1.4), in this order
  bool rerack = false;      ///< rack again and break (an illegal 8-ball break)
  bool game_over = false;
  int winner = -1;
  std::array<Group, 2> groups{Group::Open, Group::Open};  ///< each player's group after the shot (8-ball)
  bool push_out_next = false;  ///< the next shot may be a push-out (9- and 10-ball, after a legal break)
  int points = 0;              ///< scored by the shooter (three-cushion: 1 for a carom)
  int penalty = 0;             ///< scored by the shooter's opponent for a foul (snooker)
  bool colour_next = false;    ///< snooker: the next ball on is a colour (a red was just potted)
};

}  // namespace game
}  // namespace cue_sim

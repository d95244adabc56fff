#include "node/game_messages.hpp"

namespace cue_sim
{
namespace
{
geometry_msgs::Point pointAt(const Eigen::Vector2d& p)
{
  geometry_msgs::Point point;
  point.x = p.x();
  point.y = p.y();
  return point;
}

std::string inHandName(game::BallInHand place)
{
  return place == game::BallInHand::None ? "" : game::ballInHandName(place);
}
}  // namespace

Ruling toRulingMsg(const game::Ruling& ruling, bool refereed)
{
  Ruling msg;
  msg.winner = -1;
  msg.refereed = refereed;
  if (!refereed)
    return msg;
  msg.foul = ruling.foul;
  msg.rule = ruling.rule;
  msg.reason = ruling.reason;
  msg.continues = ruling.continues;
  msg.next_player = ruling.next_player;
  msg.ball_in_hand = inHandName(ruling.ball_in_hand);
  msg.respot.assign(ruling.respot.begin(), ruling.respot.end());
  msg.rerack = ruling.rerack;
  msg.points = ruling.points;
  msg.penalty = ruling.penalty;
  msg.game_over = ruling.game_over;
  msg.winner = ruling.winner;
  return msg;
}

GameState toGameStateMsg(const session::LiveTable& table, const ros::Time& stamp, const std::string& frame)
{
  GameState msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = frame;
  msg.called_ball = -1;
  msg.winner = -1;
  msg.last_ruling = toRulingMsg(game::Ruling(), false);
  const game::GamePlay* play = table.game().play();
  msg.active = play != nullptr;
  if (!play)
    return msg;
  const game::GameState& state = play->state();
  msg.rules = state.rules;
  for (std::size_t i = 0; i < 2; ++i)
  {
    msg.players[i] = state.players[i];
    msg.groups[i] = game::groupName(state.groups[i]);
    msg.consecutive_fouls[i] = state.consecutive_fouls[i];
    msg.score[i] = state.score[i];
    msg.innings[i] = state.innings[i];
  }
  msg.turn = state.turn;
  msg.cue_ball = play->cueBall();
  msg.target = state.target;
  msg.before_shot = state.before_shot;
  msg.break_shot = state.break_shot;
  msg.push_out_allowed = state.push_out_allowed;
  msg.push_out_called = table.game().pushOutCalled();
  const std::vector<int> legal = play->legalFirst();
  msg.legal_first.assign(legal.begin(), legal.end());
  msg.must_call = play->rules().mustCall();
  msg.called_ball = state.called_ball;
  if (state.called_pocket >= 0)
    msg.called_pocket = table.table().pockets()[static_cast<std::size_t>(state.called_pocket)].name;
  msg.ball_in_hand = inHandName(state.ball_in_hand);
  Eigen::Vector2d low, high;
  if (!table.game().pendingTurn() &&
      game::inHandRegion(table.table(), table.engine().params().ball_radius, state.ball_in_hand, low, high))
  {
    msg.place_min = pointAt(low);
    msg.place_max = pointAt(high);
  }
  msg.shots = state.shots;
  msg.colour_next = state.colour_next;
  msg.free_ball = state.free_ball;
  msg.shot_in_progress = table.game().pendingTurn().has_value();
  msg.over = state.over;
  msg.winner = state.winner;
  if (table.game().pendingTurn())
    msg.last_ruling = toRulingMsg(table.game().pendingTurn()->ruling, true);
  else if (table.game().lastTurn())
    msg.last_ruling = toRulingMsg(table.game().lastTurn()->ruling, true);
  return msg;
}

}  // namespace cue_sim

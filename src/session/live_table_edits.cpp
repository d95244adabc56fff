// What is put on the live table: in free play through the edits (TableEdits checks each request
// in full first), in a game only through the game (LiveGame).
#include <sstream>

#include "cue_sim/session/live_table.hpp"

namespace cue_sim
{
namespace session
{
Outcome LiveTable::rack(const RackRequest& request, Stamp now)
{
  if (const std::string why = game_.whyNotFreeEdit(); !why.empty())
    return Outcome::refused(why);
  advanceTo(now);
  physics::TableState<double> layout;
  if (const std::string why = edits_.whyNotRack(request, engine(), layout); !why.empty())
    return Outcome::refused(why);
  edits_.racked(layout);
  startFrom(physics::atTimeZero(layout), now);
  return Outcome::done("racked '" + request.layout + "': " + std::to_string(layout.balls.size()) + " balls");
}

Outcome LiveTable::reset(Stamp now)
{
  if (const std::string why = game_.whyNotFreeEdit(); !why.empty())
    return Outcome::refused(why);
  advanceTo(now);
  if (const std::string why = edits_.whyNotReset(engine()); !why.empty())
    return Outcome::refused(why);
  startFrom(physics::atTimeZero(edits_.lastRack()), now);
  return Outcome::done("back to the last rack (" + std::to_string(edits_.lastRack().balls.size()) + " balls)");
}

Outcome LiveTable::setState(const std::vector<BallInput>& balls, Stamp now)
{
  if (const std::string why = game_.whyNotFreeEdit(); !why.empty())
    return Outcome::refused(why);
  physics::TableState<double> state;
  if (const std::string why = edits_.whyNotState(balls, engine(), state); !why.empty())
    return Outcome::refused(why);
  advanceTo(now);
  startFrom(state, now);  // every ball at time 0: now
  return Outcome::done("replaced the table by " + std::to_string(state.balls.size()) + " balls" +
                       (state.anyMoving() ? ", some moving" : ", all at rest"));
}

Outcome LiveTable::placeBall(const BallInput& input, Stamp now)
{
  if (const std::string why = game_.whyNotFreeEdit(); !why.empty())
    return Outcome::refused(why);
  physics::Ball<double> ball;
  if (const std::string why = ballFromInput(input, "ball", table(), engine().params().ball_radius, ball); !why.empty())
    return Outcome::refused(why);
  advanceTo(now);
  if (const std::string where = balls_.whyNotPlaceable(ball); !where.empty())
    return Outcome::refused("ball: " + where);
  const bool moved = balls_.state().indexOf(ball.id) >= 0;
  if (balls_.atRest())
    restartAtRest(now);
  balls_.place(ball);
  changed(now);
  advanceTo(now);
  return Outcome::done(std::string(moved ? "moved" : "placed") + " ball " + std::to_string(ball.id));
}

Outcome LiveTable::removeBall(int id, Stamp now)
{
  if (const std::string why = game_.whyNotFreeEdit(); !why.empty())
    return Outcome::refused(why);
  advanceTo(now);
  if (const std::string why = TableEdits::whyNotRemovable(id, balls_.state()); !why.empty())
    return Outcome::refused(why);
  balls_.remove(id);
  changed(now);
  advanceTo(now);
  return Outcome::done("removed ball " + std::to_string(id));
}

Outcome LiveTable::startGame(const GameRequest& request, Stamp now)
{
  std::optional<game::GamePlay> started;
  if (const std::string why = game_.whyNotStart(request, engine(), started); !why.empty())
    return Outcome::refused(why);
  advanceTo(now);
  game_.start(std::move(*started));
  startFrom(physics::atTimeZero(game_.play()->table()), now);
  const game::GameState& state = game_.play()->state();
  return Outcome::done("started " + request.rules + ": " + state.players[0] + " against " + state.players[1] + ", " +
                       state.players[static_cast<std::size_t>(state.turn)] +
                       (state.break_shot ? " to break" : " to shoot"));
}

Outcome LiveTable::endGame(Stamp now)
{
  if (!game_.on())
    return Outcome::refused("no game is on");
  advanceTo(now);  // a shot still rolling rolls on, in free play, unrefereed
  return Outcome::done("ended the game of " + game_.end() + "; free play, the balls where they are");
}

Outcome LiveTable::placeCueBall(const Eigen::Vector2d& p, Stamp now)
{
  if (!game_.on())
    return Outcome::refused("no game is on: ~place_ball moves any ball in free play");
  advanceTo(now);
  physics::Ball<double> cue;
  if (const std::string why = game_.placeCueBall(p, cue); !why.empty())
    return Outcome::refused(why);
  restartAtRest(now);
  balls_.place(cue);
  advanceTo(now);
  std::ostringstream message;
  message << "cue ball placed at (" << p.x() << ", " << p.y() << ")";
  return Outcome::done(message.str());
}

Outcome LiveTable::callShot(const GameCall& call, Stamp now)
{
  if (!game_.on())
    return Outcome::refused("no game is on: ~start_game first");
  advanceTo(now);
  if (const std::string why = game_.call(call, table()); !why.empty())
    return Outcome::refused(why);
  std::ostringstream message;
  message << (call.ball >= 0 ? "called ball " + std::to_string(call.ball) : std::string("no ball called"));
  if (!call.pocket.empty())
    message << " in " << call.pocket;
  if (call.push_out)
    message << ", a push-out";
  return Outcome::done(message.str());
}

}  // namespace session
}  // namespace cue_sim

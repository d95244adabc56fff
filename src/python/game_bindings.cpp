// cue_sim._core's games: game::GamePlay for Python, its state and rulings as the JSON `simulate`
// prints (shot_report.hpp), parsed into dicts by python/cue_sim/games.py.
#include "python/game_bindings.hpp"

#include <pybind11/stl.h>

#include <memory>
#include <stdexcept>

#include "cue_sim/game/game_play.hpp"
#include "cue_sim/scene/shot_report.hpp"
#include "python/state_arrays.hpp"

namespace py = pybind11;

namespace cue_sim
{
namespace python
{
namespace
{
/// A game and the engine it plays on (kept alive with it).
struct Game
{
  std::shared_ptr<const physics::Engine<double>> engine;
  game::GamePlay play;
};

void refuseIf(const std::string& why)
{
  if (!why.empty())
    throw std::invalid_argument(why);
}

Game startGame(std::shared_ptr<physics::Engine<double>> engine, const std::string& rules,
               const std::array<std::string, 2>& players, unsigned seed, int first_player, int target)
{
  if (first_player != 0 && first_player != 1)
    throw std::invalid_argument("first_player must be 0 or 1, got " + std::to_string(first_player));
  game::GamePlay play(*engine, rules, players, game::gameRack(seed), first_player);
  if (target != 0)
    if (const std::string why = play.setTarget(target); !why.empty())
      throw std::invalid_argument("target: " + why);
  return Game{engine, play};
}

void call(Game& g, int ball, const std::string& pocket)
{
  int index = -1;
  refuseIf(g.engine->table().whyNoPocket(pocket, index));
  refuseIf(g.play.call(ball, index));
}

/// The shot's ruling (as `simulate` prints it) and its events.
py::tuple shoot(Game& g, double speed, double phi, double theta, double a, double b, bool push_out, int ball)
{
  const int struck = ball < 0 ? g.play.cueBall() : ball;
  refuseIf(g.play.whyNotStrikable(struck));
  const physics::CueStrike<double> strike{speed, phi, theta, a, b};
  refuseIf(g.engine->whyNotStrikable(g.play.table(), struck, strike));
  game::Turn turn;
  {
    py::gil_scoped_release release;
    turn = g.play.shoot(strike, push_out, nullptr, struck);
  }
  return py::make_tuple(rulingJson(turn.ruling).dump(), eventArrays(g.engine->table(), turn.events, 0.0));
}
}  // namespace

void bindGames(py::module_& m)
{
  m.def("rules_names", &game::rulesNames);
  m.def("rules_table", &game::rulesTable);
  py::class_<Game>(m, "Game")
      .def(py::init(&startGame))
      .def("copy", [](const Game& g) { return Game(g); })
      .def("state_json", [](const Game& g) { return gameStateJson(g.play.state(), g.play.engine().table()).dump(); })
      .def("table", [](const Game& g) { return toArrays(g.play.table()); })
      .def("legal_first", [](const Game& g) { return g.play.legalFirst(); })
      .def("cue_ball", [](const Game& g) { return g.play.cueBall(); })
      .def("place_cue_ball",
           [](Game& g, double x, double y) {
             refuseIf(g.play.placeCueBall({x, y}));
           })
      .def("call", &call)
      .def("shoot", &shoot)
      .def("set_position",
           [](Game& g, const StateArrays& balls, bool break_shot) {
             refuseIf(g.play.setPosition(fromArrays(*g.engine, balls), break_shot));
           })
      .def("set_shot_cap", [](Game& g, int cap) { g.play.setShotCap(cap); });
}

}  // namespace python
}  // namespace cue_sim

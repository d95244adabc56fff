// What may be put on the live table: a rack (and the last one again, for a reset), a whole table
// of balls, one ball placed, moved or removed. Each request is checked in full, field by field,
// into the table state or ball it makes, before anything on the table changes. It keeps the last
// rack.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "cue_sim/physics/engine.hpp"
#include "cue_sim/session/ball_input.hpp"

namespace cue_sim
{
namespace session
{
struct RackRequest
{
  std::string layout;                      ///< "eight", "nine", "ten", "empty" or "custom"
  std::vector<int> ids;                    ///< custom: one per ball
  std::vector<Eigen::Vector2d> positions;  ///< custom: [m] in the table frame
  double jitter = 0;       ///< [m] standard layouts: each ball but the apex moved by up to this, in [0, rack_gap / 2]
  std::uint32_t seed = 0;  ///< of the jitter
};

class TableEdits
{
public:
  /// Racks leave `rack_gap` [m] between neighbouring balls.
  explicit TableEdits(double rack_gap) : rack_gap_(rack_gap) {}

  /// The rack a request makes on the engine's table, or why not (which field, or why it does not fit).
  std::string whyNotRack(const RackRequest& request, const physics::Engine<double>& engine,
                         physics::TableState<double>& rack) const;
  /// Remembers the rack the table was set to, for a reset.
  void racked(const physics::TableState<double>& rack) { last_rack_ = rack; }
  const physics::TableState<double>& lastRack() const { return last_rack_; }
  /// Empty if the last rack fits the engine (its physics may have changed since), else why not.
  std::string whyNotReset(const physics::Engine<double>& engine) const;
  /// A whole table from a request's balls (at least one), or why not.
  std::string whyNotState(const std::vector<BallInput>& balls, const physics::Engine<double>& engine,
                          physics::TableState<double>& state) const;
  /// Empty if a ball with this id is on the table, else why not (and which are).
  static std::string whyNotRemovable(int id, const physics::TableState<double>& table);
  /// The last rack sitting on the cloth under a new ball radius.
  void onCloth(double R);

private:
  double rack_gap_;
  physics::TableState<double> last_rack_;
};

}  // namespace session
}  // namespace cue_sim

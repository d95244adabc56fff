// The table seen from straight above, as a texture the camera's rays look up: what covers each
// point (cloth, cushion rubber, rail, pocket or floor) and its colour. Private to the camera.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "cue_sim/physics/snooker_markings.hpp"
#include "cue_sim/physics/table_model.hpp"

namespace cue_sim
{
namespace camera
{
enum class Surface : std::uint8_t
{
  Cloth,
  Chalk,  ///< a marking on the cloth: a snooker table's baulk line, D and spots
  Pocket,
  Cushion,  ///< raised: its top is at the cushion height
  Rail,     ///< raised
  Floor,
};

/// A colour as the renderer mixes it: blue, green, red in [0, 1].
struct Bgr
{
  float b = 0, g = 0, r = 0;
};

class TableTexture
{
public:
  /// With `snooker_markings`, the cloth carries the baulk line, the D and the six spots.
  explicit TableTexture(const physics::TableModel& table, bool snooker_markings = false);

  Surface surfaceAt(const Eigen::Vector2d& p) const;
  Bgr colourAt(const Eigen::Vector2d& p) const;
  static bool raised(Surface s) { return s == Surface::Cushion || s == Surface::Rail; }

private:
  Surface classify(const physics::TableModel& table, const Eigen::Vector2d& p) const;
  int index(const Eigen::Vector2d& p) const;

  Eigen::Vector2d origin_;  ///< [m] the corner of texel (0, 0)
  int columns_ = 0, rows_ = 0;
  std::vector<Surface> texels_;
  Eigen::Vector2d cloth_low_, cloth_high_;
  std::optional<physics::SnookerMarkings> markings_;
};

}  // namespace camera
}  // namespace cue_sim

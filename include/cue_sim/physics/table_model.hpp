// The table's geometry: built once (from URDF or in code), never changed by a simulation.
// All coordinates are in the table frame: origin at the centre of the playing surface, x along
// the long axis, y across, z up, the cloth at z = 0.
#pragma once

#include <Eigen/Core>
#include <array>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace cue_sim
{
namespace physics
{
/// A straight cushion: the line of the rubber nose, from start to end. The playing area lies
/// on the side of `normal` (pointing from the cushion into play).
struct CushionSegment
{
  std::string name;
  Eigen::Vector2d start;
  Eigen::Vector2d end;
  Eigen::Vector2d direction;  ///< unit, start -> end
  Eigen::Vector2d normal;     ///< unit, into the playing area
  double length = 0;
};

/// A circular cushion (a pocket jaw, or the rounded end of a straight cushion): a ball touches
/// it when its centre is radius + R from `centre`.
struct CircularCushion
{
  std::string name;
  Eigen::Vector2d centre;
  double radius = 0;
};

/// A pocket: a ball whose centre enters the capture circle drops and leaves play.
struct Pocket
{
  std::string name;
  Eigen::Vector2d centre;
  double radius = 0;
};

/// The table's top beyond its cushions: the rails a ball flying over a cushion lands on, and the
/// edge past which it falls to the floor (doc/physics.md, "Balls in the air").
struct TableEdge
{
  Eigen::Vector2d low, high;  ///< the table's outer edge, a level rectangle [m]
  /// The rails' top above the cloth [m]; NaN: flush with the cushions' nose
  /// (PhysicsParams::cushion_height), as on the tables in urdf/.
  double rail_height = std::numeric_limits<double>::quiet_NaN();
};

/// The balls a table is played with, as its description names them (a `balls` link in URDF): a
/// snooker table's 52.5 mm balls, a carom table's 61.5 mm. The engine's coefficients start from
/// them (tableDefaults in physics_params.hpp); a ball_radius or ball_mass set explicitly wins.
struct TableBalls
{
  double radius = 0;  ///< [m]
  double mass = 0;    ///< [kg]
  /// The set they are, for pictures (scene/ball_colours.hpp): one of kBallSetNames; empty: told
  /// by the table's pockets.
  std::string set;
};

/// The sets of balls a table may name (TableBalls::set), declared once: the table loader checks a
/// description's name against them, and the pictures' BallSet (scene/ball_colours.hpp) follows
/// this order.
constexpr std::array<const char*, 3> kBallSetNames = {"pool", "carom", "snooker"};
/// Whether `name` is one of kBallSetNames.
bool isBallSetName(const std::string& name);
/// kBallSetNames for a message: "pool, carom or snooker".
std::string ballSetNameList();

/// How far the table reaches beyond the cloth when its description does not say: a 5 cm
/// cushion and a 10 cm rail, as the tables in urdf/ (scripts/make_table_urdf.py).
constexpr double kCushionAndRailWidth = 0.15;  // [m]

class TableModel
{
public:
  /// The playing surface is the rectangle |x - cx| <= length/2, |y - cy| <= width/2. Without an
  /// `edge`, the table's edge is kCushionAndRailWidth beyond the cloth's and its rails are flush
  /// with the cushions. Without `balls`, the table names none and takes the pool ball.
  TableModel(std::string name, Eigen::Vector2d cloth_centre, double cloth_length, double cloth_width,
             std::vector<CushionSegment> segments, std::vector<CircularCushion> circles, std::vector<Pocket> pockets,
             std::optional<TableEdge> edge = std::nullopt, std::optional<TableBalls> balls = std::nullopt);

  /// A segment from start to end whose playing side is to the left of start -> end.
  static CushionSegment makeSegment(std::string name, const Eigen::Vector2d& start, const Eigen::Vector2d& end);

  /// A 7-ft or 9-ft six-pocket pool table or a pocketless carom table built in code, the same
  /// geometry the URDF files in urdf/ describe (for tests and benchmarks without urdfdom).
  /// Pockets have jaws of `jaw_radius` where the cushions end, and capture circles of
  /// `capture_radius` through each pocket's two jaw centres.
  static TableModel pool(const std::string& name, double cloth_length, double cloth_width, double corner_mouth,
                         double side_mouth, double jaw_radius = 0.01, double capture_radius = 0.15);
  static TableModel carom(const std::string& name, double cloth_length, double cloth_width);

  const std::string& name() const { return name_; }
  const Eigen::Vector2d& clothCentre() const { return cloth_centre_; }
  double clothLength() const { return cloth_length_; }
  double clothWidth() const { return cloth_width_; }
  const std::vector<CushionSegment>& segments() const { return segments_; }
  /// Jaws and segment end caps.
  const std::vector<CircularCushion>& circles() const { return circles_; }
  const std::vector<Pocket>& pockets() const { return pockets_; }
  /// The rails and the table's outer edge.
  const TableEdge& edge() const { return edge_; }
  /// The balls the table's description names, if it names them.
  const std::optional<TableBalls>& balls() const { return balls_; }
  /// The index of the pocket named `name` (an empty name: -1, no pocket), or why there is none,
  /// listing the pockets' names.
  std::string whyNoPocket(const std::string& name, int& index) const;
  /// The head string: the line across the cloth a quarter of its length from the head end
  /// (-x), behind which the break is played (WPA Definitions). Its x [m].
  double headStringX() const { return cloth_centre_.x() - cloth_length_ / 4; }
  /// The foot spot, where the rack's apex stands and balls are spotted: on the long string, a
  /// quarter of the cloth's length from the foot end (+x).
  Eigen::Vector2d footSpot() const { return cloth_centre_ + Eigen::Vector2d(cloth_length_ / 4, 0); }
  /// The head spot, where the cue ball starts: the head string's middle.
  Eigen::Vector2d headSpot() const { return Eigen::Vector2d(headStringX(), cloth_centre_.y()); }

  /// Empty if a ball of radius R can stand with its centre at p: at least R from every cushion's
  /// face and every jaw, outside every pocket's capture circle, and on the playing area they
  /// close, which is the cloth within R of its edges and the pockets' mouths (not the space
  /// behind a cushion, a jaw or a pocket); otherwise why not. Distances within `tolerance` [m]
  /// count as touching.
  std::string whyNotPlaceable(const Eigen::Vector2d& p, double ball_radius, double tolerance = 1e-9) const;
  /// Empty unless a ball of radius R in the air with its centre at `r` reaches into a wall by
  /// more than `tolerance` [m]: a straight cushion is the block behind its nose line, from the
  /// slate to the noses' height `nose_height`, along its length (its top running back to the
  /// table's edge where the rails are flush with the noses); a jaw or post the cylinder of its
  /// radius as high. Beyond the table's edge there is no wall. Where the rails are not flush only
  /// the faces and the noses' edges count.
  std::string whyInTheWalls(const Eigen::Vector3d& r, double ball_radius, double nose_height,
                            double tolerance = 1e-9) const;

  /// Empty if the cushions, jaws and pockets close the playing area (every way out from the
  /// cloth's centre across its edge meets one, within 1 m of the edge) and every straight
  /// cushion is at least 1 cm long; else where it is open, or which cushion is too short.
  std::string whyOpen() const;

private:
  std::string name_;
  Eigen::Vector2d cloth_centre_;
  double cloth_length_;
  double cloth_width_;
  std::vector<CushionSegment> segments_;
  std::vector<CircularCushion> circles_;
  std::vector<Pocket> pockets_;
  TableEdge edge_;
  std::optional<TableBalls> balls_;
};

}  // namespace physics
}  // namespace cue_sim

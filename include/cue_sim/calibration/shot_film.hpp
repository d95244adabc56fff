// A shot as the simulated camera films it: a frame at each asked instant, each the average of the
// balls' exact positions through its exposure (motion blur), with the ground truth at its middle.
// What a calibration is proven on end to end (the camera, the example detector, the fit), without
// ROS: the same camera the node publishes (camera::TableCamera), driven by the same exact engine.
// The balls' markings are drawn unturned (the engine's state carries no orientation).
#pragma once

#include <optional>
#include <string>

#include "cue_sim/calibration/track_prediction.hpp"
#include "cue_sim/camera/table_camera.hpp"
#include "cue_sim/physics/simulation.hpp"

namespace cue_sim
{
namespace calibration
{
struct FilmSettings
{
  camera::Intrinsics intrinsics;
  camera::Pose pose = camera::Pose::Identity();  ///< the optical frame in the table frame
  double exposure = 0.004;                       ///< [s] the shutter's time open, in [0, 0.1]
  camera::CameraOptions options;                 ///< sensor noise

  /// Empty if usable, else which field is wrong and why.
  std::string whyInvalid() const;
};

/// One camera over one table; a shot at a time, filmed forward.
class ShotFilm
{
public:
  /// Throws std::invalid_argument naming what is wrong with `settings`.
  ShotFilm(const physics::Engine<double>& engine, const FilmSettings& settings);

  /// Starts a shot: the balls of `start` standing until start.time, then struck as `strike` says.
  /// Throws std::invalid_argument naming the field that is wrong (as whyBadRequest does).
  void begin(const physics::TableState<double>& start, const std::optional<TrackStrike>& strike);
  /// The frame whose exposure is centred on `time` [s, the start's clock]. Times go forward: an
  /// exposure may not begin before the last one ended (std::invalid_argument).
  camera::Frame frame(double time);

  const FilmSettings& settings() const { return settings_; }

private:
  /// The balls at `t`: as they stood before the strike, or from the struck simulation after it.
  std::vector<camera::BallPose> posesAt(double t);
  /// How many instants the exposure from `t` needs (kBlurStep between two on the fastest surface).
  int instantsFrom(double t);

  const physics::Engine<double>* engine_;
  FilmSettings settings_;
  camera::TableCamera camera_;
  physics::TableState<double> standing_;
  std::optional<physics::Simulation<double>> struck_;
  double last_instant_ = 0;
  bool begun_ = false;
};

}  // namespace calibration
}  // namespace cue_sim

#include "cue_sim/calibration/shot_film.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "cue_sim/camera/exposure.hpp"

namespace cue_sim
{
namespace calibration
{
namespace
{
camera::BallPose poseOf(const physics::Ball<double>& ball)
{
  camera::BallPose pose;
  pose.id = ball.id;
  pose.centre = ball.r;
  pose.in_play = ball.inPlay();
  return pose;
}
}  // namespace

std::string FilmSettings::whyInvalid() const
{
  if (const std::string bad = intrinsics.whyInvalid(); !bad.empty())
    return "intrinsics: " + bad;
  if (!(exposure >= 0 && exposure <= kMaxExposure))
  {
    std::ostringstream why;
    why << "exposure: " << exposure << " s is outside [0, " << kMaxExposure << "]";
    return why.str();
  }
  if (!pose.matrix().allFinite())
    return "pose: not finite";
  return options.whyInvalid();
}

namespace
{
const FilmSettings& checked(const FilmSettings& settings)
{
  if (const std::string bad = settings.whyInvalid(); !bad.empty())
    throw std::invalid_argument(bad);
  return settings;
}
}  // namespace

ShotFilm::ShotFilm(const physics::Engine<double>& engine, const FilmSettings& settings)
  : engine_(&engine),
    settings_(checked(settings)),
    camera_(engine.table(), engine.params().ball_radius, engine.params().cushion_height, settings.intrinsics,
            settings.pose, settings.options)
{
}

void ShotFilm::begin(const physics::TableState<double>& start, const std::optional<TrackStrike>& strike)
{
  TrackRequest request{start, strike, {}};
  if (const std::string bad = whyBadRequest(*engine_, request); !bad.empty())
    throw std::invalid_argument(bad);
  standing_ = start;
  physics::TableState<double> struck = start;
  if (strike)
    engine_->strike(struck, strike->ball_id, strike->cue);
  struck_.emplace(*engine_, std::move(struck));
  last_instant_ = -INFINITY;
  begun_ = true;
}

std::vector<camera::BallPose> ShotFilm::posesAt(double t)
{
  std::vector<camera::BallPose> poses;
  if (t < standing_.time)
  {
    for (const physics::Ball<double>& ball : engine_->snapshot(standing_))
      poses.push_back(poseOf(ball));
    return poses;
  }
  struck_->advance(t);
  for (const physics::Ball<double>& ball : struck_->snapshot())
    poses.push_back(poseOf(ball));
  return poses;
}

int ShotFilm::instantsFrom(double t)
{
  if (t < standing_.time)  // the first instants stand still; those after the strike are sampled as fine
    t = standing_.time;
  struck_->advance(t);
  double fastest = 0;
  const double radius = engine_->params().ball_radius;
  for (const physics::Ball<double>& ball : struck_->snapshot())
    fastest = std::max(fastest, ball.v.norm() + radius * ball.w.norm());
  const double travel = fastest * settings_.exposure;
  return std::clamp(static_cast<int>(std::ceil(travel / camera::kBlurStep)), 1, camera::kMaxInstants);
}

camera::Frame ShotFilm::frame(double time)
{
  if (!begun_)
    throw std::invalid_argument("frame: no shot begun (begin first)");
  const double open = time - settings_.exposure / 2;
  if (!std::isfinite(time) || open < last_instant_)
  {
    std::ostringstream why;
    why << "time: " << time << " s opens the shutter before the last frame's closed (" << last_instant_
        << " s); frames go forward";
    throw std::invalid_argument(why.str());
  }
  const int n = settings_.exposure > 0 ? instantsFrom(open) : 1;
  // The slices' middles, and the ground truth at the exposure's middle among them in time order
  // (the simulation only goes forward).
  camera::Exposure exposure;
  std::vector<camera::BallPose> middle;
  bool middle_taken = false;
  for (int i = 0; i < n; ++i)
  {
    const double t = open + settings_.exposure * (i + 0.5) / n;
    if (!middle_taken && t >= time)
    {
      middle = posesAt(time);
      middle_taken = true;
    }
    exposure.instants.push_back(posesAt(t));
  }
  if (!middle_taken)
    middle = posesAt(time);
  last_instant_ = time + settings_.exposure / 2;
  camera::Frame out = camera_.render(exposure);
  out.balls = camera_.groundTruth(middle);
  return out;
}

}  // namespace calibration
}  // namespace cue_sim

// calibration::ShotFilm: each frame's ground truth is the camera's projection of the exact
// simulation at the exposure's middle (standing before the strike, struck after); a fast ball
// smears over what it travels while the shutter is open and a still one does not; frames that go
// back in time, bad settings and bad shots are refused naming what is wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <opencv2/core.hpp>

#include "cue_sim/calibration/shot_film.hpp"
#include "cue_sim/physics/simulation.hpp"
#include "engine_7ft.hpp"

namespace cue_sim
{
namespace calibration
{
namespace
{
using physics::Engine;
using physics::TableState;

FilmSettings overhead(const Engine<double>& engine, double exposure)
{
  FilmSettings s;
  s.intrinsics = s.intrinsics.scaled(960, 600);
  s.pose = camera::overheadPose(engine.table().clothCentre(), camera::kOverheadHeight);
  s.exposure = exposure;
  return s;
}

TableState<double> twoBalls(const Engine<double>& engine)
{
  const double r = engine.params().ball_radius;
  TableState<double> state;
  state.balls.resize(2);
  state.balls[0].id = 0;
  state.balls[0].r = {-0.5, 0.0, r};
  state.balls[1].id = 1;
  state.balls[1].r = {0.4, 0.2, r};
  return state;
}

/// How many pixels differ from `background` by more than a few levels.
int changed(const cv::Mat& image, const cv::Mat& background)
{
  cv::Mat difference;
  cv::absdiff(image, background, difference);
  cv::Mat grey;
  cv::transform(difference, grey, cv::Matx13f(1, 1, 1));
  return cv::countNonZero(grey > 12);
}

TEST(ShotFilm, GroundTruthIsTheExactSimulationAtEachMiddle)
{
  const auto engine = engine7ft();
  ShotFilm film(*engine, overhead(*engine, 0.004));
  camera::TableCamera reference(engine->table(), engine->params().ball_radius, engine->params().cushion_height,
                                film.settings().intrinsics, film.settings().pose);
  const TableState<double> start = twoBalls(*engine);
  const TrackStrike strike{0, {2.5, 0.2, 0.0, 0.0, 0.2}};
  film.begin(start, strike);
  TableState<double> struck = start;
  engine->strike(struck, 0, strike.cue);
  physics::Simulation<double> live(*engine, struck);
  for (double t : {-0.05, -0.01, 0.1, 0.5, 1.0, 2.0})
  {
    const camera::Frame frame = film.frame(t);
    std::vector<camera::BallPose> poses;
    if (t < 0)
      for (const auto& ball : engine->snapshot(start))
        poses.push_back({ball.id, ball.r, Eigen::Quaterniond::Identity(), true});
    else
    {
      live.advance(t);
      for (const auto& ball : live.snapshot())
        poses.push_back({ball.id, ball.r, Eigen::Quaterniond::Identity(), ball.inPlay()});
    }
    const auto expected = reference.groundTruth(poses);
    ASSERT_EQ(frame.balls.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i)
    {
      EXPECT_EQ(frame.balls[i].id, expected[i].id);
      EXPECT_EQ(frame.balls[i].pixel, expected[i].pixel) << "t " << t;
      EXPECT_EQ(frame.balls[i].visible, expected[i].visible);
    }
  }
}

TEST(ShotFilm, AFastBallSmearsAndAStillOneDoesNot)
{
  const auto engine = engine7ft();
  const TableState<double> start = twoBalls(*engine);
  const TrackStrike strike{0, {6.0, 0.0, 0.0, 0.0, 0.0}};
  TableState<double> empty;
  ShotFilm background(*engine, overhead(*engine, 0.0));
  background.begin(empty, std::nullopt);
  const cv::Mat table = background.frame(0.0).image;
  int still[2], moving[2];
  for (int blurred = 0; blurred < 2; ++blurred)
  {
    ShotFilm film(*engine, overhead(*engine, blurred ? 0.01 : 0.0));
    film.begin(start, strike);
    still[blurred] = changed(film.frame(-0.1).image, table);
    moving[blurred] = changed(film.frame(0.05).image, table);
  }
  EXPECT_EQ(still[0], still[1]);  // nothing moves before the strike: the shutter changes nothing
  // 10 ms at about 6 m/s: some 5 cm of smear, about 2 balls' widths more of changed pixels for the
  // cue ball (the smear is faint at its ends, hence the margin)
  EXPECT_GT(moving[1], moving[0] + still[0] / 2);
}

TEST(ShotFilm, RefusesWhatItCannotFilmNamingIt)
{
  const auto engine = engine7ft();
  FilmSettings bad = overhead(*engine, 0.5);
  EXPECT_THROW(
      {
        try
        {
          ShotFilm film(*engine, bad);
        }
        catch (const std::invalid_argument& e)
        {
          EXPECT_NE(std::string(e.what()).find("exposure"), std::string::npos) << e.what();
          throw;
        }
      },
      std::invalid_argument);
  ShotFilm film(*engine, overhead(*engine, 0.004));
  EXPECT_THROW(film.frame(0.0), std::invalid_argument);  // no shot begun
  TableState<double> overlapping = twoBalls(*engine);
  overlapping.balls[1].r = overlapping.balls[0].r;
  EXPECT_THROW(film.begin(overlapping, std::nullopt), std::invalid_argument);
  film.begin(twoBalls(*engine), TrackStrike{0, {2.0, 0.0, 0.0, 0.0, 0.0}});
  film.frame(0.5);
  try
  {
    film.frame(0.499);
    FAIL() << "a frame back in time was filmed";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("time"), std::string::npos) << e.what();
  }
  film.frame(0.6);  // still usable after the refusal
}

}  // namespace
}  // namespace calibration
}  // namespace cue_sim

// The simulated camera: its lens maps points as the plumb-bob model says and back; each ball's
// ground truth is where geometry puts it, and the drawn ball is there (a blob's centroid within
// a fraction of a pixel); a moving ball smears as far as it travels while the shutter is open;
// noise has the asked deviation; the exposure is the live table's exact motion.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <opencv2/imgproc.hpp>

#include "../session/live_table_fixtures.hpp"
#include "cue_sim/camera/calibration_file.hpp"
#include "cue_sim/camera/exposure.hpp"
#include "cue_sim/camera/table_camera.hpp"
#include "cue_sim/physics/snooker_markings.hpp"

namespace cue_sim
{
namespace camera
{
namespace
{
using session::fixtures::engineOn;
using session::fixtures::kSecond;
using session::fixtures::kStart;

constexpr double kHeight = kOverheadHeight;  ///< [m] the camera above the cloth

TableCamera overheadCamera(const physics::Engine<double>& engine, const Intrinsics& k = {},
                           const CameraOptions& options = {})
{
  return TableCamera(engine.table(), engine.params().ball_radius, engine.params().cushion_height, k,
                     overheadPose(engine.table().clothCentre(), kHeight), options);
}

/// Pixels that are not the cloth's colour: a ball's (cloth is dark green with little red).
cv::Mat notCloth(const cv::Mat& image, const cv::Mat& background)
{
  cv::Mat difference, grey, mask;
  cv::absdiff(image, background, difference);
  cv::cvtColor(difference, grey, cv::COLOR_BGR2GRAY);
  cv::threshold(grey, mask, 12, 255, cv::THRESH_BINARY);
  return mask;
}

Exposure still(const std::vector<BallPose>& balls)
{
  return Exposure{{balls}};
}

/// A ball turned so that its number discs face sideways: from above, its colour.
Eigen::Quaterniond sideways()
{
  return Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()));
}
}  // namespace

TEST(PinholeCamera, ProjectsAndUnprojectsThroughTheLens)
{
  Intrinsics k;
  k.distortion = {-0.12, 0.05, 0.001, -0.0008, -0.01};
  for (const Eigen::Vector2d& pixel :
       {Eigen::Vector2d(0, 0), Eigen::Vector2d(1919, 1199), Eigen::Vector2d(960, 10), Eigen::Vector2d(400.25, 777.5)})
  {
    const Eigen::Vector2d n = normalisedOf(k, pixel);
    Eigen::Vector2d back;
    ASSERT_TRUE(project(k, Eigen::Vector3d(n.x(), n.y(), 1) * 3.0, back));
    EXPECT_LT((back - pixel).norm(), 1e-8) << pixel.transpose();
  }
  // Without distortion, the plain pinhole.
  Eigen::Vector2d pixel;
  ASSERT_TRUE(project(Intrinsics{}, Eigen::Vector3d(0.3, -0.2, 2.0), pixel));
  EXPECT_NEAR(pixel.x(), 959.5 + 1365 * 0.15, 1e-12);
  EXPECT_NEAR(pixel.y(), 599.5 - 1365 * 0.1, 1e-12);
  EXPECT_FALSE(project(Intrinsics{}, Eigen::Vector3d(0, 0, -1), pixel)) << "behind the camera";
}

TEST(PinholeCamera, ScalingKeepsTheFieldOfView)
{
  const Intrinsics k = Intrinsics{}.scaled(1280, 800);
  EXPECT_EQ(k.width, 1280);
  EXPECT_NEAR(k.fx, 910, 1e-9);
  // The image's corners see the same rays.
  EXPECT_NEAR((-0.5 - k.cx) / k.fx, (-0.5 - 959.5) / 1365.0, 1e-12);
  EXPECT_NEAR((1279.5 - k.cx) / k.fx, (1919.5 - 959.5) / 1365.0, 1e-12);
}

TEST(CalibrationFile, TheDefaultIsFoundInTheConfigFolderGivenElseThePackages)
{
  const std::string packaged = defaultCalibrationPath();
  ASSERT_NE(packaged.find(kDefaultCalibrationFile), std::string::npos);
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "cue_sim_config_test";
  std::filesystem::create_directories(dir / "camera");
  std::filesystem::copy_file(packaged, dir / kDefaultCalibrationFile,
                             std::filesystem::copy_options::overwrite_existing);
  ::setenv("CUE_SIM_CONFIG_DIR", dir.c_str(), 1);
  EXPECT_EQ(defaultCalibrationPath(), (dir / kDefaultCalibrationFile).string());
  ::setenv("CUE_SIM_CONFIG_DIR", (dir / "nowhere").c_str(), 1);
  EXPECT_EQ(defaultCalibrationPath(), packaged) << "a folder without it is passed over";
  ::unsetenv("CUE_SIM_CONFIG_DIR");
  std::filesystem::remove_all(dir);
}

TEST(CalibrationFile, TheBundledOneIsTheDefaultCameraAndABadOneIsNamed)
{
  const Intrinsics k = intrinsicsFromFile(defaultCalibrationPath());
  EXPECT_EQ(k.width, 1920);
  EXPECT_EQ(k.height, 1200);
  EXPECT_EQ(k.fx, Intrinsics{}.fx);
  EXPECT_EQ(k.cx, Intrinsics{}.cx);
  EXPECT_EQ(k.distortion[0], -0.08);
  EXPECT_EQ(k.distortion[1], 0.03);
  try
  {
    intrinsicsFromFile("/nonexistent/calibration.yaml");
    FAIL() << "read a file that is not there";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/calibration.yaml"), std::string::npos) << e.what();
  }
}

TEST(TableCamera, RefusesBadIntrinsicsNamingThem)
{
  const auto engine = engineOn("7ft");
  Intrinsics k;
  k.fx = -3;
  try
  {
    overheadCamera(*engine, k);
    FAIL() << "accepted fx = -3";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("fx"), std::string::npos) << e.what();
  }
  CameraOptions noisy;
  noisy.noise_stddev = 400;
  EXPECT_THROW(overheadCamera(*engine, {}, noisy), std::invalid_argument);
}

TEST(TableCamera, GroundTruthIsWhereGeometryPutsTheBall)
{
  const auto engine = engineOn("7ft");
  const TableCamera camera = overheadCamera(*engine);
  const double R = engine->params().ball_radius;
  const Eigen::Vector2d c = engine->table().clothCentre();
  const auto truth =
      camera.groundTruth({{3, Eigen::Vector3d(c.x() + 0.5, c.y() + 0.25, R)},
                          {4, Eigen::Vector3d(c.x() + 0.5, c.y(), R), Eigen::Quaterniond::Identity(), false}});
  ASSERT_EQ(truth.size(), 2u);
  const double depth = kHeight - R;
  EXPECT_NEAR(truth[0].pixel.x(), 959.5 + 1365 * 0.5 / depth, 1e-9);
  EXPECT_NEAR(truth[0].pixel.y(), 599.5 - 1365 * 0.25 / depth, 1e-9) << "the table's +y is up in the image";
  EXPECT_NEAR(truth[0].radius, 1365 * R / depth, 1e-9);
  EXPECT_TRUE(truth[0].visible);
  EXPECT_FALSE(truth[1].visible) << "pocketed";
}

TEST(TableCamera, EachDrawnBallIsCentredOnItsGroundTruth)
{
  // A racked table seen through a distorting lens: each ball's blob (its pixels that differ
  // from the empty table) has its centroid within 0.3 px of the ground truth.
  const auto engine = engineOn("7ft");
  Intrinsics k;
  k.distortion = {-0.08, 0.03, 0, 0, 0};
  TableCamera camera = overheadCamera(*engine, k);
  const Frame empty = camera.render(still({}));
  std::vector<BallPose> balls;
  const double R = engine->params().ball_radius;
  const Eigen::Vector2d c = engine->table().clothCentre();
  int id = 1;
  for (double x : {-0.9, -0.3, 0.3, 0.9})
    for (double y : {-0.45, 0.0, 0.45})
      balls.push_back({id++, Eigen::Vector3d(c.x() + x, c.y() + y, R), sideways()});
  const Frame frame = camera.render(still(balls));
  const cv::Mat mask = notCloth(frame.image, empty.image);
  for (const auto& truth : frame.balls)
  {
    ASSERT_TRUE(truth.visible);
    const int half = static_cast<int>(std::ceil(1.5 * truth.radius));
    const cv::Rect box(static_cast<int>(truth.pixel.x()) - half, static_cast<int>(truth.pixel.y()) - half, 2 * half + 1,
                       2 * half + 1);
    const cv::Moments m = cv::moments(mask(box), true);
    ASSERT_GT(m.m00, 0.8 * M_PI * truth.radius * truth.radius) << "ball " << truth.id << " is drawn";
    EXPECT_LT(m.m00, 1.2 * M_PI * truth.radius * truth.radius) << "ball " << truth.id << " is its size";
    const Eigen::Vector2d centroid(box.x + m.m10 / m.m00, box.y + m.m01 / m.m00);
    EXPECT_LT((centroid - truth.pixel).norm(), 0.3) << "ball " << truth.id;
  }
}

TEST(TableCamera, BallsShowTheirColoursStripesAndNumbers)
{
  const auto engine = engineOn("7ft");
  TableCamera camera = overheadCamera(*engine);
  const double R = engine->params().ball_radius;
  const Eigen::Vector2d c = engine->table().clothCentre();
  // 1 (yellow) turned sideways shows yellow; 9 (yellow stripe) turned sideways shows its band
  // across the middle and white caps; 2 as it stands shows its number disc: white round black.
  const Frame frame = camera.render(still({{1, Eigen::Vector3d(c.x() - 0.3, c.y(), R), sideways()},
                                           {9, Eigen::Vector3d(c.x(), c.y(), R), sideways()},
                                           {2, Eigen::Vector3d(c.x() + 0.3, c.y(), R)}}));
  const auto at = [&](const Eigen::Vector2d& p) {
    return frame.image.at<cv::Vec3b>(static_cast<int>(std::lround(p.y())), static_cast<int>(std::lround(p.x())));
  };
  const cv::Vec3b yellow = at(frame.balls[0].pixel + Eigen::Vector2d(0, 0.6 * frame.balls[0].radius));
  EXPECT_GT(yellow[2], 150);
  EXPECT_GT(yellow[1], 120);
  EXPECT_LT(yellow[0], 80);
  // Ball 9's band runs along the image's x (its own z, the band's axis, points along the image's
  // y): its cap is white.
  const double r9 = frame.balls[1].radius;
  const cv::Vec3b cap = at(frame.balls[1].pixel + Eigen::Vector2d(0, 0.75 * r9));
  const cv::Vec3b band = at(frame.balls[1].pixel + Eigen::Vector2d(0.3 * r9, 0));
  EXPECT_GT(std::min({cap[0], cap[1], cap[2]}), 100) << "white cap, in its shade";
  EXPECT_LT(std::max({cap[0], cap[1], cap[2]}) - std::min({cap[0], cap[1], cap[2]}), 20) << "white cap, grey";
  EXPECT_LT(band[0], 80) << "yellow band";
  EXPECT_GT(band[2], 150);
  // Ball 2's number disc: white paper with black ink.
  const Eigen::Vector2d p2 = frame.balls[2].pixel;
  const double r2 = frame.balls[2].radius;
  int dark = 0, white = 0;
  for (int dy = -3; dy <= 3; ++dy)
    for (int dx = -3; dx <= 3; ++dx)
    {
      const cv::Vec3b v = at(p2 + Eigen::Vector2d(dx * 0.08 * r2, dy * 0.08 * r2));
      const int lightest = std::min({v[0], v[1], v[2]});
      dark += std::max({v[0], v[1], v[2]}) < 70;
      white += lightest > 150;
    }
  EXPECT_GT(dark, 3) << "the digit";
  EXPECT_GT(white, 10) << "the disc";
}

TEST(TableCamera, ACaromTablesBallsAreWhiteYellowAndRedWithoutNumbers)
{
  // On a table without pockets the balls are carom's: 2 is red (not pool's blue) and, seen from
  // straight above as it stands, shows no number disc: its centre is red, not white and black.
  const auto engine = engineOn("carom");
  TableCamera camera = overheadCamera(*engine);
  const double R = engine->params().ball_radius;
  const Eigen::Vector2d c = engine->table().clothCentre();
  const Frame frame = camera.render(still({{0, Eigen::Vector3d(c.x() - 0.3, c.y(), R)},
                                           {1, Eigen::Vector3d(c.x(), c.y(), R)},
                                           {2, Eigen::Vector3d(c.x() + 0.3, c.y(), R)}}));
  const auto at = [&](const Eigen::Vector2d& p) {
    return frame.image.at<cv::Vec3b>(static_cast<int>(std::lround(p.y())), static_cast<int>(std::lround(p.x())));
  };
  const cv::Vec3b white = at(frame.balls[0].pixel), yellow = at(frame.balls[1].pixel), red = at(frame.balls[2].pixel);
  EXPECT_GT(std::min({white[0], white[1], white[2]}), 150) << "the white";
  EXPECT_GT(yellow[2], 150);
  EXPECT_GT(yellow[1], 120);
  EXPECT_LT(yellow[0], 80) << "the yellow";
  EXPECT_GT(red[2], 120);
  EXPECT_LT(red[1], 60);
  EXPECT_LT(red[0], 60) << "the red, where a pool 2 would show its number disc";
}

TEST(TableCamera, TheSnookerTableShowsItsMarkingsAndItsBallsInSnookersColours)
{
  // The snooker table's balls (named by its description) are snooker's: every red red without a
  // number, the pink pink, the black black; and the cloth carries its chalk: the baulk line, the D
  // and the spots, white on the green.
  const auto table = std::make_shared<const physics::TableModel>(tableFromUrdfFile(tableUrdfPath("snooker")));
  const auto engine = std::make_shared<const physics::Engine<double>>(table, physics::tableDefaults(*table));
  TableCamera camera = overheadCamera(*engine);
  const double R = engine->params().ball_radius;
  const physics::SnookerMarkings m = physics::snookerMarkings(*table);
  const Frame frame = camera.render(still({{0, Eigen::Vector3d(-0.5, 0.3, R)},
                                           {7, Eigen::Vector3d(0.3, 0.2, R)},
                                           {20, Eigen::Vector3d(0.3, -0.2, R)},
                                           {21, Eigen::Vector3d(0.6, 0.0, R)}}));
  const auto pixelOf = [&](const Eigen::Vector2d& p) {
    Eigen::Vector2d uv;
    EXPECT_TRUE(project(camera.intrinsics(), camera.pose().inverse() * Eigen::Vector3d(p.x(), p.y(), 0), uv));
    return frame.image.at<cv::Vec3b>(static_cast<int>(std::lround(uv.y())), static_cast<int>(std::lround(uv.x())));
  };
  const auto at = [&](const Eigen::Vector2d& px) {
    return frame.image.at<cv::Vec3b>(static_cast<int>(std::lround(px.y())), static_cast<int>(std::lround(px.x())));
  };
  const cv::Vec3b red = at(frame.balls[1].pixel), pink = at(frame.balls[2].pixel), black = at(frame.balls[3].pixel);
  EXPECT_GT(red[2], 120);
  EXPECT_LT(red[1], 60);
  EXPECT_LT(red[0], 60) << "a red, with no number disc";
  EXPECT_GT(pink[2], 150);
  EXPECT_GT(pink[0], 90) << "the pink: red with blue in it";
  EXPECT_LT(std::max({black[0], black[1], black[2]}), 50) << "the black";
  // Chalk: the blue spot (no ball on it) and the baulk line away from the D; green cloth beside.
  const cv::Vec3b spot = pixelOf(m.spotOf(physics::SnookerColour::Blue));
  const cv::Vec3b line = pixelOf(Eigen::Vector2d(m.baulk_line_x, 0.6));
  const cv::Vec3b cloth = pixelOf(Eigen::Vector2d(m.baulk_line_x + 0.05, 0.6));
  EXPECT_GT(std::min({spot[0], spot[1], spot[2]}), 150) << "the blue spot";
  EXPECT_GT(std::min({line[0], line[1], line[2]}), 120) << "the baulk line";
  EXPECT_LT(cloth[2], 100);
  EXPECT_GT(cloth[1], cloth[2]) << "the cloth beside it";
  // A pool table's cloth has none.
  const auto pool = engineOn("7ft");
  TableCamera pool_camera = overheadCamera(*pool);
  const Frame pool_frame = pool_camera.render(still({}));
  Eigen::Vector2d uv;
  ASSERT_TRUE(project(pool_camera.intrinsics(), pool_camera.pose().inverse() * Eigen::Vector3d(0, 0, 0), uv));
  const cv::Vec3b centre =
      pool_frame.image.at<cv::Vec3b>(static_cast<int>(std::lround(uv.y())), static_cast<int>(std::lround(uv.x())));
  EXPECT_GT(centre[1], centre[2]) << "green at the centre of a pool table";
}

TEST(TableCamera, AMovingBallSmearsAsFarAsItTravels)
{
  // A black ball at 5 m/s in a 4 ms exposure travels L = 20 mm. Along a row through it at
  // half a radius from its centre (a chord c = 2 x 0.866 r long), the share of the exposure
  // each pixel sees the ball ramps from 0 to 1 over L at each end (L < c): it exceeds 1/2 over
  // c and 1/10 over c + 0.8 L. A still ball's profile is c wide at both.
  const auto engine = engineOn("7ft");
  TableCamera camera = overheadCamera(*engine);
  const Frame empty = camera.render(still({}));
  const double R = engine->params().ball_radius;
  const Eigen::Vector2d c = engine->table().clothCentre();
  const double speed = 5, exposure = 0.004;
  const int instants = static_cast<int>(std::ceil(speed * exposure / kBlurStep));
  Exposure moving;
  for (int i = 0; i < instants; ++i)
  {
    const double t = (i + 0.5) / instants * exposure - exposure / 2;
    moving.instants.push_back({{8, Eigen::Vector3d(c.x() + speed * t, c.y(), R), sideways()}});
  }
  const double travel = speed * exposure * 1365 / (kHeight - R);  // [px]
  for (const bool blurred : {false, true})
  {
    const Frame frame = camera.render(blurred ? moving : still(moving.instants[instants / 2]));
    const auto& truth = frame.balls[0];
    const int row = static_cast<int>(std::lround(truth.pixel.y() + truth.radius / 2));
    const double chord = 2 * std::sqrt(0.75) * truth.radius;
    const double cloth = empty.image.at<cv::Vec3b>(row, static_cast<int>(std::lround(truth.pixel.x())))[1];
    const double ball = frame.image.at<cv::Vec3b>(row, static_cast<int>(std::lround(truth.pixel.x())))[1];
    ASSERT_GT(cloth - ball, 60) << "the black ball throughout at the smear's middle";
    int over_half = 0, over_tenth = 0;
    const int centre = static_cast<int>(std::lround(truth.pixel.x()));
    for (int x = centre - 3 * static_cast<int>(truth.radius); x <= centre + 3 * static_cast<int>(truth.radius); ++x)
    {
      const double share = (cloth - frame.image.at<cv::Vec3b>(row, x)[1]) / (cloth - ball);
      over_half += share > 0.5;
      over_tenth += share > 0.1;
    }
    const double length = blurred ? travel : 0;
    EXPECT_NEAR(over_half, chord, 2.0) << (blurred ? "blurred" : "still");
    EXPECT_NEAR(over_tenth, chord + 0.8 * length, 2.0) << (blurred ? "blurred" : "still");
  }
  EXPECT_GT(travel, 10) << "a smear worth measuring";
}

TEST(TableCamera, NoiseHasTheAskedDeviationAndRepeatsWithItsSeed)
{
  const auto engine = engineOn("7ft");
  CameraOptions options;
  options.noise_stddev = 4;
  options.noise_seed = 7;
  TableCamera clean = overheadCamera(*engine);
  TableCamera noisy = overheadCamera(*engine, {}, options);
  TableCamera again = overheadCamera(*engine, {}, options);
  const cv::Mat a = clean.render(still({})).image;
  const cv::Mat b = noisy.render(still({})).image;
  cv::Mat difference;
  cv::subtract(b, a, difference, cv::noArray(), CV_32FC3);
  cv::Scalar mean, deviation;
  cv::meanStdDev(difference.reshape(1), mean, deviation);
  EXPECT_NEAR(deviation[0], 4.0, 0.2);  // a little under: 8-bit levels clip at 0
  EXPECT_NEAR(mean[0], 0.0, 0.2);
  EXPECT_EQ(cv::norm(b, again.render(still({})).image, cv::NORM_INF), 0.0) << "the same seed, the same noise";
}

TEST(CameraExposure, IsTheLiveTablesExactMotion)
{
  // A ball struck at 3 m/s, photographed 50 ms later for 4 ms: the exposure's instants are the
  // table's own poses at the slices' middles, 12 of them (3 m/s and its spin over 1 mm steps).
  session::LiveTable table(engineOn("7ft"), session::LiveTableOptions{}, "empty", kStart);
  ASSERT_TRUE(table.strike(session::fixtures::shot(0, 3.0, 0.3, 0.0, 0.0), kStart).success);
  const session::Stamp start = kStart + kSecond / 20;
  table.advanceTo(start);
  const double speed =
      table.motion().balls()[0].v.norm() + table.engine().params().ball_radius * table.motion().balls()[0].w.norm();
  const Exposure exposure = exposureOf(table.motion(), table.clock(), start, 0.004);
  ASSERT_EQ(exposure.instants.size(), static_cast<std::size_t>(std::ceil(speed * 0.004 / kBlurStep)));
  session::LiveTable reference = table;
  for (std::size_t i = 0; i < exposure.instants.size(); ++i)
  {
    reference.advanceTo(start + static_cast<session::Stamp>(std::llround((i + 0.5) * 4e6 / exposure.instants.size())));
    EXPECT_EQ(exposure.instants[i][0].centre, reference.motion().balls()[0].r) << "instant " << i;
    EXPECT_TRUE(exposure.instants[i][0].orientation.isApprox(reference.motion().orientations()[0], 0));
  }
  EXPECT_EQ(table.clock().lastStamp(), start) << "the table itself is not advanced";
  // At rest, one instant.
  session::LiveTable resting(engineOn("7ft"), session::LiveTableOptions{}, "eight", kStart);
  EXPECT_EQ(exposureOf(resting.motion(), resting.clock(), kStart, 0.004).instants.size(), 1u);
}

}  // namespace camera
}  // namespace cue_sim

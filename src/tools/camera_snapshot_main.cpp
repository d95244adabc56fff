// camera_snapshot: what the simulated camera sees of a rack, or of a break some milliseconds
// after the strike (its motion blur included), as a PNG, without ROS. The README's camera figure
// and the camera's own checks by eye come from it.
//   rosrun cue_sim camera_snapshot --rack eight --after-ms 40 --out break.png
#include <CLI/CLI.hpp>
#include <chrono>
#include <fstream>
#include <iostream>
#include <opencv2/imgcodecs.hpp>

#include "cue_sim/camera/calibration_file.hpp"
#include "cue_sim/camera/exposure.hpp"
#include "cue_sim/physics/rack.hpp"
#include "cue_sim/session/live_table.hpp"
#include "cue_sim/table_description/table_catalog.hpp"
#include "cue_sim/table_description/urdf_table_loader.hpp"

int main(int argc, char** argv)
{
  CLI::App app{"Renders the simulated overhead camera's picture of a rack or a break to a PNG."};
  std::string table_name = "7ft", rack = "eight", out = "camera.png";
  double after_ms = 0, speed = 8.0, phi = 0.002, theta = 0, exposure = 0.004, height = cue_sim::camera::kOverheadHeight,
         noise = 0;
  std::string cue_model;  // empty: the default
  int width = 0, image_height = 0;
  std::string calibration;  // empty: the package's default
  app.add_option("--table", table_name, "a bundled table (7ft, 9ft, carom, snooker) or a URDF file");
  app.add_option("--rack", rack, cue_sim::physics::rackNamesText());
  app.add_option("--after-ms", after_ms, "photograph this long after the break's strike; 0: the rack, not struck")
      ->check(CLI::Range(0.0, 60000.0));
  app.add_option("--speed", speed, "the break's cue speed [m/s]")->check(CLI::Range(0.01, 12.0));
  app.add_option("--phi", phi, "the break's heading [rad]");
  app.add_option("--theta", theta, "the cue's elevation [rad]")->check(CLI::Range(0.0, 1.5707963267948966));
  app.add_option("--cue-model", cue_model, "planar (the default) or sequential: an elevated cue makes the ball jump");
  app.add_option("--exposure", exposure, "[s] shutter open")->check(CLI::Range(0.0, 0.1));
  app.add_option("--height", height, "[m] the camera over the cloth's centre, looking down")
      ->check(CLI::Range(0.3, 20.0));
  app.add_option("--noise", noise, "Gaussian sensor noise [8-bit levels]")->check(CLI::Range(0.0, 50.0));
  app.add_option("--calibration", calibration,
                 "the camera's calibration file (camera_info_manager's YAML); default: the package's "
                 "config/camera/overhead_1920x1200.yaml, in the source tree or the install space");
  app.add_option("--width", width, "[px] the calibrated image read out this wide (with --image-height)")
      ->check(CLI::Range(16, 8192));
  app.add_option("--image-height", image_height, "[px] and this high")->check(CLI::Range(16, 8192));
  app.add_option("--out", out, "the PNG to write");
  std::string truth_file;
  int repeat = 1;
  app.add_option("--repeat", repeat, "render this many times and print the time per frame (exposure and picture)")
      ->check(CLI::Range(1, 100000));
  app.add_option("--truth", truth_file, "also write the ground truth here, as CSV: id,u,v,radius,visible,x,y,z");
  CLI11_PARSE(app, argc, argv);
  try
  {
    using namespace cue_sim;
    const auto table = std::make_shared<const physics::TableModel>(tableFromUrdfFile(tableUrdfPath(table_name)));
    const auto engine = std::make_shared<const physics::Engine<double>>(table, physics::tableDefaults(*table),
                                                                        physics::ModelChoice("", "", "", cue_model));
    session::LiveTable live(engine, {}, rack, 0);
    const session::Stamp after = static_cast<session::Stamp>(after_ms * 1e6);
    if (after > 0)
    {
      session::Shot shot;
      shot.strike.speed = speed;
      shot.strike.phi = phi;
      shot.strike.theta = theta;
      const session::StrikeOutcome outcome = live.strike(shot, 0);
      if (!outcome.success)
        throw std::invalid_argument(outcome.message);
      live.advanceTo(after);
    }
    camera::Intrinsics k =
        camera::intrinsicsFromFile(calibration.empty() ? camera::defaultCalibrationPath() : calibration);
    if ((width == 0) != (image_height == 0))
      throw std::invalid_argument("--width and --image-height: give both or neither");
    if (width > 0)
      k = k.scaled(width, image_height);
    camera::CameraOptions options;
    options.noise_stddev = noise;
    camera::TableCamera cam(*table, engine->params().ball_radius, engine->params().cushion_height, k,
                            camera::overheadPose(table->clothCentre(), height), options);
    camera::Exposure shutter;
    camera::Frame frame;
    const auto started = std::chrono::steady_clock::now();
    for (int i = 0; i < repeat; ++i)
    {
      shutter = camera::exposureOf(live.motion(), live.clock(), after, exposure);
      frame = cam.render(shutter);
    }
    const std::chrono::duration<double, std::milli> spent = std::chrono::steady_clock::now() - started;
    if (repeat > 1)
      std::cout << "camera_snapshot: " << spent.count() / repeat << " ms a frame (" << shutter.instants.size()
                << " instants), over " << repeat << " frames\n";
    if (!cv::imwrite(out, frame.image))
      throw std::runtime_error("cannot write " + out);
    if (!truth_file.empty())
    {
      std::ofstream csv(truth_file);
      csv << "id,u,v,radius,visible,x,y,z\n";
      const auto& middle = shutter.instants[shutter.instants.size() / 2];
      for (std::size_t i = 0; i < frame.balls.size(); ++i)
      {
        const auto& b = frame.balls[i];
        csv << b.id << "," << b.pixel.x() << "," << b.pixel.y() << "," << b.radius << "," << b.visible << ","
            << middle[i].centre.x() << "," << middle[i].centre.y() << "," << middle[i].centre.z() << "\n";
      }
      if (!csv)
        throw std::runtime_error("cannot write " + truth_file);
    }
    int visible = 0;
    for (const auto& b : frame.balls)
      visible += b.visible;
    std::cout << "camera_snapshot: " << out << ": " << k.width << "x" << k.height << ", " << visible
              << " balls visible\n";
  }
  catch (const std::exception& e)
  {
    std::cerr << "camera_snapshot: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

// A camera calibration file as camera_info_manager writes and reads it (image_width,
// image_height, camera_matrix, distortion_model plumb_bob, distortion_coefficients), read without
// ROS, for the programs that draw camera pictures outside the node.
#pragma once

#include <string>

#include "cue_sim/camera/pinhole_camera.hpp"

namespace cue_sim
{
namespace camera
{
/// The calibration the node uses by default (config/camera/overhead_1920x1200.yaml).
std::string defaultCalibrationPath();
/// The intrinsics in a calibration file. Throws std::invalid_argument naming the file and what
/// is missing or wrong in it.
Intrinsics intrinsicsFromFile(const std::string& path);

}  // namespace camera
}  // namespace cue_sim

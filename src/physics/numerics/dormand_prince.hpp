// Dormand and Prince's embedded Runge-Kutta 5(4) tableau (Dormand and Prince 1980; Hairer,
// Norsett and Wanner, "Solving Ordinary Differential Equations I", II.5), shared by the
// project's integrators: the resting contacts' (supports/support_step.cpp) and the work-precision
// chart's time stepper (evaluation/dormand_prince.cpp). The fifth-order solution's weights are
// the last row of kA (the method is "first same as last").
#pragma once

namespace cue_sim
{
namespace physics
{
namespace dormand_prince
{
constexpr int kStages = 7;
constexpr double kC[kStages] = {0, 1.0 / 5, 3.0 / 10, 4.0 / 5, 8.0 / 9, 1, 1};
constexpr double kA[kStages][kStages - 1] = {
    {0, 0, 0, 0, 0, 0},
    {1.0 / 5, 0, 0, 0, 0, 0},
    {3.0 / 40, 9.0 / 40, 0, 0, 0, 0},
    {44.0 / 45, -56.0 / 15, 32.0 / 9, 0, 0, 0},
    {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729, 0, 0},
    {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656, 0},
    {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84},
};
/// The fifth-order weights less the embedded fourth-order ones: the local error's estimate.
constexpr double kE[kStages] = {71.0 / 57600, 0, -71.0 / 16695, 71.0 / 1920, -17253.0 / 339200, 22.0 / 525, -1.0 / 40};
/// The order of the error estimate: a step's error scales as its length to the fifth.
constexpr int kErrorOrder = 5;
}  // namespace dormand_prince
}  // namespace physics
}  // namespace cue_sim

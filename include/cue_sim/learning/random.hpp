// An environment's random stream: the same draws on every machine (the standard library's
// distributions are not specified bit for bit, so the draws are made here from the raw bits).
#pragma once

#include <cstdint>
#include <random>

namespace cue_sim
{
namespace learning
{
class Random
{
public:
  explicit Random(std::uint64_t seed = 0) : engine_(seed) {}
  void seed(std::uint64_t seed) { engine_.seed(seed); }
  std::uint64_t bits() { return engine_(); }
  double unit() { return static_cast<double>(engine_() >> 11) * 0x1p-53; }  ///< [0, 1)
  double uniform(double low, double high) { return low + (high - low) * unit(); }
  int integer(int low, int high) { return low + static_cast<int>(unit() * (high - low + 1)); }  ///< [low, high]

private:
  std::mt19937_64 engine_;
};

}  // namespace learning
}  // namespace cue_sim

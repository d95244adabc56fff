// What the live table answers a request: done, with a message, or refused, saying why (the field,
// its value and its range). A refused request changes nothing.
#pragma once

#include <string>

namespace cue_sim
{
namespace session
{
struct Outcome
{
  bool success = false;
  std::string message;  ///< why not, when success is false

  static Outcome done(const std::string& message) { return {true, message}; }
  static Outcome refused(const std::string& why) { return {false, why}; }
};

}  // namespace session
}  // namespace cue_sim

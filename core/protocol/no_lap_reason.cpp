#include "core/protocol/no_lap_reason.h"

namespace ydscope {
namespace {

std::string counted(std::uint64_t n, const std::string& what) {
  return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}

}  // namespace

std::string no_lap_reason(std::string_view model, const LaplessCounts& counts) {
  const std::string name(model);
  if (counts.packets == 0) return "its bytes are not " + name + " scan packets";
  return "its " + counted(counts.packets, name + " scan packet") + " (" + counted(counts.bytes, "byte") +
         ") are too short for a lap, which runs from a zero packet to the next zero packet; they hold " +
         counted(counts.zero_packets, "zero packet");
}

}  // namespace ydscope

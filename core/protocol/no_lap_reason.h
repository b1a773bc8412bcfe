#pragma once
// Why bytes read to their end gave no lap, from what the decoder counted: bytes with no valid
// packet of the model are not its scan packets; valid packets without two zero packets are too
// short for a lap (a lap runs from a zero packet to the next). A user with a short capture once
// heard "its bytes are not G6 scan packets" and went looking for the wrong fault. ydscope-cli
// decode and replay and the app's replay say it in these words.
#include <cstdint>
#include <string>
#include <string_view>

namespace ydscope {

struct LaplessCounts {
  std::uint64_t bytes = 0;
  std::uint64_t packets = 0;       // valid scan packets
  std::uint64_t zero_packets = 0;  // of which CT bit 0 was set
};

// "its bytes are not G6 scan packets", or "its 3 G6 scan packets (72 bytes) are too short for a
// lap, which runs from a zero packet to the next zero packet; they hold 1 zero packet".
std::string no_lap_reason(std::string_view model, const LaplessCounts& counts);

}  // namespace ydscope

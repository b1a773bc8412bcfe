#pragma once
// Line settings through the Linux termios2 ioctls (TCGETS2/TCSETS2), the only way to ask for a
// rate without a Bxxx constant such as 512000 (G6/TG). Kept behind plain ints because
// <asm/termbits.h> cannot share a translation unit with <termios.h> (which Boost.Asio pulls in).
#include <cstdint>

namespace ydscope::termios2 {

// Raw 8N1, receiver on, modem lines ignored, no hardware or software flow control, no echo,
// no line editing, no character translation; reads return whatever has arrived (VMIN 1, VTIME 0).
// Baud is set as an arbitrary rate (BOTHER) for both directions. Returns 0 or an errno value.
int configure_raw(int fd, std::uint32_t baud);

// Changes only the rate (both directions), keeping every other setting. Returns 0 or an errno.
int set_baud(int fd, std::uint32_t baud);

// What the kernel holds for the line, read back with TCGETS2 (for checks and messages).
struct LineSettings {
  std::uint32_t input_baud = 0;
  std::uint32_t output_baud = 0;
  bool arbitrary_baud = false;  // CBAUD == BOTHER
  bool raw = false;             // no ICANON/ECHO/ISIG/OPOST/input translation
  bool eight_n_one = false;     // CS8, no PARENB, no CSTOPB
  bool flow_control = false;    // CRTSCTS or IXON/IXOFF
};
// Returns 0 or an errno value.
int read_settings(int fd, LineSettings& out);

}  // namespace ydscope::termios2

// termios2 only: this file must not include <termios.h> (its struct termios clashes with the
// kernel's). See termios2_baud.h.
#include "core/link/termios2_baud.h"

#include <asm/termbits.h>
#include <cerrno>
#include <sys/ioctl.h>

namespace ydscope::termios2 {
namespace {

constexpr tcflag_t kInputTranslation = IGNBRK | BRKINT | PARMRK | ISTRIP | INLCR | IGNCR | ICRNL;
constexpr tcflag_t kLocalEditing = ECHO | ECHONL | ICANON | ISIG | IEXTEN;

int get(int fd, struct termios2& tio) { return ::ioctl(fd, TCGETS2, &tio) == 0 ? 0 : errno; }
int put(int fd, const struct termios2& tio) { return ::ioctl(fd, TCSETS2, &tio) == 0 ? 0 : errno; }

void apply_baud(struct termios2& tio, std::uint32_t baud) {
  tio.c_cflag &= ~static_cast<tcflag_t>(CBAUD | (CBAUD << IBSHIFT));
  tio.c_cflag |= BOTHER | (BOTHER << IBSHIFT);
  tio.c_ispeed = baud;
  tio.c_ospeed = baud;
}

}  // namespace

int configure_raw(int fd, std::uint32_t baud) {
  struct termios2 tio {};
  if (const int error = get(fd, tio)) return error;
  // The cfmakeraw() recipe, plus no flow control of either kind and 8N1.
  tio.c_iflag &= ~(kInputTranslation | IXON | IXOFF | IXANY);
  tio.c_oflag &= ~static_cast<tcflag_t>(OPOST);
  tio.c_lflag &= ~kLocalEditing;
  tio.c_cflag &= ~static_cast<tcflag_t>(CSIZE | PARENB | CSTOPB | CRTSCTS);
  tio.c_cflag |= CS8 | CREAD | CLOCAL;
  tio.c_cc[VMIN] = 1;
  tio.c_cc[VTIME] = 0;
  apply_baud(tio, baud);
  return put(fd, tio);
}

int set_baud(int fd, std::uint32_t baud) {
  struct termios2 tio {};
  if (const int error = get(fd, tio)) return error;
  apply_baud(tio, baud);
  return put(fd, tio);
}

int read_settings(int fd, LineSettings& out) {
  struct termios2 tio {};
  if (const int error = get(fd, tio)) return error;
  out.input_baud = tio.c_ispeed;
  out.output_baud = tio.c_ospeed;
  out.arbitrary_baud = (tio.c_cflag & CBAUD) == BOTHER;
  out.raw = (tio.c_lflag & kLocalEditing) == 0 && (tio.c_oflag & OPOST) == 0 && (tio.c_iflag & kInputTranslation) == 0;
  out.eight_n_one = (tio.c_cflag & CSIZE) == CS8 && (tio.c_cflag & (PARENB | CSTOPB)) == 0;
  out.flow_control = (tio.c_cflag & CRTSCTS) != 0 || (tio.c_iflag & (IXON | IXOFF)) != 0;
  return 0;
}

}  // namespace ydscope::termios2

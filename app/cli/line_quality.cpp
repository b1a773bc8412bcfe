#include "app/cli/line_quality.h"

#include <cstdio>

namespace ydscope::cli {

std::string checksum_warning(const std::string& command, std::uint64_t good_packets, std::uint64_t checksum_errors) {
  const std::uint64_t packets = good_packets + checksum_errors;
  // At least ten: a short run's few packets must not turn two unlucky ones into a verdict.
  if (checksum_errors < 10 || checksum_errors * 20 <= packets) return {};
  char line[320];
  std::snprintf(line, sizeof line,
                "%s: warning: %llu of %llu packets (%.0f %%) failed their checksum and were dropped; check the "
                "cable and the power supply, and that no other program reads the port\n",
                command.c_str(), static_cast<unsigned long long>(checksum_errors),
                static_cast<unsigned long long>(packets),
                100.0 * static_cast<double>(checksum_errors) / static_cast<double>(packets));
  return line;
}

}  // namespace ydscope::cli

#pragma once
// A run's packets that failed their checksum, said on stderr when they are many: the odd bad
// packet is line noise the counters show, but one in twenty or more means a bad cable, a weak
// supply or another program on the port, and a user reading CSV or a recording's path would
// otherwise never learn of it.
#include <cstdint>
#include <string>

namespace ydscope::cli {

// The warning line (with its newline) for `command` when more than one packet in twenty, and at
// least ten, failed their checksum; empty otherwise. `good_packets` passed their checksum.
std::string checksum_warning(const std::string& command, std::uint64_t good_packets, std::uint64_t checksum_errors);

}  // namespace ydscope::cli

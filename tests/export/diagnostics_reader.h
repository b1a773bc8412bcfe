#pragma once
// What a test needs to know of a diagnostic_msgs/DiagnosticArray as ydscope writes it (one
// status; core/export/ros_encoding.h), read with the tests' own CDR reader.
#include <cstdint>
#include <string>
#include <vector>

#include "export/cdr_test_reader.h"

namespace ydscope::test {

struct DiagnosticSeen {
  std::uint8_t level = 0;
  std::string name;
  std::string message;
  std::string hardware_id;
};

inline DiagnosticSeen diagnostic_status(const std::vector<std::uint8_t>& cdr) {
  CdrReader r(cdr);
  r.i32();
  r.u32();
  r.str();  // frame_id
  if (r.u32() != 1) throw std::runtime_error("not one diagnostic status");
  DiagnosticSeen status;
  status.level = r.u8();
  status.name = r.str();
  status.message = r.str();
  status.hardware_id = r.str();
  return status;
}

}  // namespace ydscope::test

#pragma once
// A decoder that reads a stream as real units of the model write it: what the virtual lidar
// emits unless told to follow the manual (unit_conventions.h).
#include "core/protocol/model_profile.h"
#include "core/protocol/scan_decoder.h"
#include "core/protocol/unit_conventions.h"

namespace ydscope::test {

inline ScanDecoder field_decoder(Model model) {
  const ModelProfile& profile = profile_for(model);
  return ScanDecoder(profile, conventions_for(profile, std::nullopt, Reading::Field));
}

}  // namespace ydscope::test

namespace ydscope::test {

// Samples per second a real unit of the model sends at its default ranging code.
inline double field_samples_per_s(Model model) {
  const ModelProfile& profile = profile_for(model);
  return *conventions_for(profile, std::nullopt, Reading::Field).samples_per_s(profile, profile.default_ranging_khz);
}

}  // namespace ydscope::test

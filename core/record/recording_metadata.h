#pragma once
// The metadata of a recording (see recording_format.h for the key=value encoding and the keys).
// Every field is optional: a recording started before the device answered has no device info
// yet, and a later metadata record fills it in.
#include <cstdint>
#include <chrono>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/frame/pose.h"

namespace ydscope {

struct RecordingMetadata {
  std::optional<std::string> model;  // "G1", "G6", "TG15", ...
  std::optional<std::uint32_t> baud;
  std::optional<double> distance_scale;  // mm per count
  std::optional<std::string> port;
  std::optional<std::string> start_wall_time;  // ISO 8601 UTC
  std::optional<std::uint32_t> model_code;
  std::optional<std::string> firmware;  // "major.minor"
  std::optional<std::uint32_t> hardware;
  std::optional<std::string> serial;
  std::optional<std::string> software;
  // How the bytes were read when recorded (a UnitConventions id). Older recordings lack it:
  // ydscope then read every unit as its manual says.
  std::optional<std::string> conventions;
  // Version 2, per source: what the user called it and where it sits in the common frame. Written
  // with `pose_convention=rep103`; a pose without it is from before REP-103 and is converted on
  // parse, with one warning (core/frame/pose_convention.h).
  std::optional<std::string> name;
  std::optional<Pose> pose;
  std::map<std::string, std::string> extra;  // keys this version does not know, kept verbatim

  // key=value lines of the fields that are set (the payload of a metadata record).
  std::string encode() const;
  // Parses a payload. Lines without '=' and values that do not parse as their key's type are
  // skipped with a warning (a damaged field must not hide the rest).
  static RecordingMetadata parse(std::string_view text, std::vector<std::string>* warnings = nullptr);
  // Fields set in `later` replace ours; the others stay.
  void merge(const RecordingMetadata& later);

  friend bool operator==(const RecordingMetadata&, const RecordingMetadata&) = default;
};

// What source `id` of a recording is called: its name, else "source<id>".
std::string source_label(const RecordingMetadata& metadata, std::size_t id);

// "2026-11-22T02:20:00.123Z" for the current wall-clock time.
std::string iso8601_utc_now();
// The same for any moment: "2026-12-02T05:21:16.123Z".
std::string iso8601_utc(std::chrono::system_clock::time_point when);

}  // namespace ydscope

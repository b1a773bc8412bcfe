#include "core/record/recording_metadata.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <sstream>
#include <variant>

#include "core/frame/pose_convention.h"
#include "core/protocol/model_profile.h"
#include "core/text/quoted_text.h"

namespace ydscope {
namespace {

// One callable of several lambdas, for std::visit.
template <typename... Ts>
struct overloaded : Ts... {
  using Ts::operator()...;
};
template <typename... Ts>
overloaded(Ts...) -> overloaded<Ts...>;

std::string escape(std::string_view value) {
  std::string out;
  for (const char c : value) {
    if (c == '\\') {
      out += "\\\\";
    } else if (c == '\n') {
      out += "\\n";
    } else {
      out += c;
    }
  }
  return out;
}

std::string unescape(std::string_view value) {
  std::string out;
  for (std::size_t i = 0; i < value.size(); ++i) {
    if (value[i] == '\\' && i + 1 < value.size()) {
      ++i;
      out += value[i] == 'n' ? '\n' : value[i];
    } else {
      out += value[i];
    }
  }
  return out;
}

std::optional<std::uint32_t> parse_u32(std::string_view text) {
  std::uint32_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

std::optional<double> parse_double(std::string_view text) {
  double value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

std::string format_double(double value) {
  std::array<char, 64> buffer{};
  const auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return ec == std::errc() ? std::string(buffer.data(), end) : std::string("0");
}

template <typename T>
void take(std::optional<T>& mine, const std::optional<T>& theirs) {
  if (theirs) mine = theirs;
}

// The fields a key=value line holds as they are: text, a whole number, or the distance scale (a
// number within the --distance-scale bounds). One list, in the order encode() writes them, serves
// encode, parse and merge, so a field is named once; the pose, with its convention line, is apart.
using TextField = std::optional<std::string> RecordingMetadata::*;
using WholeField = std::optional<std::uint32_t> RecordingMetadata::*;
using ScaleField = std::optional<double> RecordingMetadata::*;
struct PlainField {
  std::string_view key;
  std::variant<TextField, WholeField, ScaleField> member;
};
const std::array<PlainField, 12> kPlainFields = {{
    {"model", &RecordingMetadata::model},
    {"baud", &RecordingMetadata::baud},
    {"distance_scale", &RecordingMetadata::distance_scale},
    {"port", &RecordingMetadata::port},
    {"start_wall_time", &RecordingMetadata::start_wall_time},
    {"model_code", &RecordingMetadata::model_code},
    {"firmware", &RecordingMetadata::firmware},
    {"hardware", &RecordingMetadata::hardware},
    {"serial", &RecordingMetadata::serial},
    {"software", &RecordingMetadata::software},
    {"conventions", &RecordingMetadata::conventions},
    {"name", &RecordingMetadata::name},
}};

std::string text_of(const std::string& value) { return value; }
std::string text_of(std::uint32_t value) { return std::to_string(value); }
std::string text_of(double value) { return format_double(value); }

}  // namespace

std::string RecordingMetadata::encode() const {
  std::string out;
  const auto line = [&out](std::string_view key, std::string_view value) {
    out.append(key).append("=").append(escape(value)).append("\n");
  };
  for (const PlainField& field : kPlainFields)
    std::visit(
        [&](auto member) {
          if (const auto& value = this->*member) line(field.key, text_of(*value));
        },
        field.member);
  if (pose) {
    line("pose", format_pose(*pose));
    line(kPoseConventionKey, kPoseConvention);
  }
  for (const auto& [key, value] : extra) line(key, value);
  return out;
}

RecordingMetadata RecordingMetadata::parse(std::string_view text, std::vector<std::string>* warnings) {
  RecordingMetadata metadata;
  const auto warn = [warnings](std::string message) {
    if (warnings) warnings->push_back(std::move(message));
  };
  bool pose_in_rep103 = false;
  while (!text.empty()) {
    const auto newline = text.find('\n');
    std::string_view line = text.substr(0, newline);
    text = newline == std::string_view::npos ? std::string_view{} : text.substr(newline + 1);
    if (line.empty()) continue;
    const auto eq = line.find('=');
    if (eq == std::string_view::npos || eq == 0) {
      warn("metadata line without key=value skipped: " + quote_file_text(line));
      continue;
    }
    const std::string key(line.substr(0, eq));
    const std::string value = unescape(line.substr(eq + 1));
    const auto read = overloaded{
        [&](TextField member) { metadata.*member = value; },
        [&](WholeField member) {
          if (const auto parsed = parse_u32(value)) {
            metadata.*member = parsed;
          } else {
            warn("metadata " + key + "=" + quote_file_text(value) + " is not a whole number; ignored");  // a known key
          }
        },
        [&](ScaleField member) {
          // The same bounds as --distance-scale: a damaged scale would make every range nonsense.
          if (const auto parsed = parse_double(value); parsed && distance_scale_in_range(*parsed)) {
            metadata.*member = parsed;
          } else {
            warn("metadata " + key + "=" + quote_file_text(value) + " is not a number from " +
                 format_double(kMinDistanceScale) + " to " + format_double(kMaxDistanceScale) +
                 " mm per count; ignored, the model's own scale is used");
          }
        }};
    const auto plain = std::find_if(kPlainFields.begin(), kPlainFields.end(),
                                    [&key](const PlainField& field) { return field.key == key; });
    if (plain != kPlainFields.end()) {
      std::visit(read, plain->member);
    } else if (key == "pose") {
      std::string why;
      if (auto parsed = parse_pose(value, why))
        metadata.pose = parsed;
      else
        warn("metadata pose ignored: " + why);
    } else if (key == kPoseConventionKey) {
      pose_in_rep103 = value == kPoseConvention;
    } else {
      metadata.extra[key] = value;
    }
  }
  if (metadata.pose && !pose_in_rep103) {
    metadata.pose = pose_from_pre_rep103(*metadata.pose);
    warn("metadata pose: " + std::string(kPreRep103Note));
  }
  return metadata;
}

void RecordingMetadata::merge(const RecordingMetadata& later) {
  for (const PlainField& field : kPlainFields)
    std::visit([&](auto member) { take(this->*member, later.*member); }, field.member);
  take(pose, later.pose);
  for (const auto& [key, value] : later.extra) extra[key] = value;
}

std::string source_label(const RecordingMetadata& metadata, std::size_t id) {
  return metadata.name && !metadata.name->empty() ? *metadata.name : "source" + std::to_string(id);
}

std::string iso8601_utc_now() { return iso8601_utc(std::chrono::system_clock::now()); }

std::string iso8601_utc(std::chrono::system_clock::time_point now) {
  const auto seconds = std::chrono::system_clock::to_time_t(now);
  const auto millis = std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
  std::tm utc{};
  ::gmtime_r(&seconds, &utc);
  std::array<char, 96> buffer{};  // room for any int the format could print
  std::snprintf(buffer.data(), buffer.size(), "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", utc.tm_year + 1900, utc.tm_mon + 1,
                utc.tm_mday, utc.tm_hour, utc.tm_min, utc.tm_sec, static_cast<int>(millis));
  return buffer.data();
}

}  // namespace ydscope

#pragma once
// The Foxglove WebSocket protocol (subprotocol foxglove.websocket.v1), the server's side, as
// plain functions: the JSON the server sends, the client requests it understands, and the
// binary Message Data header. No sockets here, so all of it is tested (and fuzzable) on strings.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/text/json_string.h"

namespace ydscope::foxglove {

inline constexpr std::string_view kSubprotocol = "foxglove.websocket.v1";
// Larger client messages are ignored with a status message (a subscribe or a parameter set is
// well under 1 KiB).
inline constexpr std::size_t kMaxClientMessage = 64 * 1024;

enum class StatusLevel : int { Info = 0, Warning = 1, Error = 2 };

struct ChannelAd {
  std::uint32_t id;
  std::string_view topic;
  std::string_view schema_name;
  std::string_view schema;  // ros2msg text
};

// A parameter as the protocol carries it: a number, a boolean or a string.
struct Parameter {
  std::string name;
  std::variant<double, bool, std::string> value;
};

std::string server_info_json(std::string_view name, std::string_view session_id);
std::string advertise_json(const std::vector<ChannelAd>& channels);
std::string status_json(StatusLevel level, std::string_view message, std::string_view id = {});
// Withdraws the status sent with `id` (Foxglove lists every status, even info, as a problem).
std::string remove_status_json(std::string_view id);
std::string parameter_values_json(const std::vector<Parameter>& parameters,
                                  const std::optional<std::string>& request_id);

// Message Data: opcode 1, u32 subscription id, u64 log time (ns), then the payload.
std::array<std::uint8_t, 13> message_data_header(std::uint32_t subscription_id, std::uint64_t log_time_ns);

struct Subscribe {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> subscriptions;  // (subscription id, channel id)
};
struct Unsubscribe {
  std::vector<std::uint32_t> subscription_ids;
};
struct GetParameters {
  std::vector<std::string> names;  // empty: all
  std::optional<std::string> id;
};
struct SetParameters {
  std::vector<Parameter> parameters;
  std::optional<std::string> id;
};
struct SubscribeParameterUpdates {
  std::vector<std::string> names;  // empty: all
};
struct UnsubscribeParameterUpdates {
  std::vector<std::string> names;  // empty: all
};
using ClientRequest = std::variant<Subscribe, Unsubscribe, GetParameters, SetParameters, SubscribeParameterUpdates,
                                   UnsubscribeParameterUpdates>;

// A text message from a client; empty plus one sentence in `error` when it is not JSON, has no
// known "op", or its fields have the wrong shape.
std::optional<ClientRequest> parse_client_message(std::string_view text, std::string& error);

// A client's text (an op, a parameter's name) as a status message quotes it: at most `limit`
// bytes of it and its length, so a client's 60 KiB name does not come back whole (and a slow
// client's queue hold it many times over).
std::string quoted_client_text(std::string_view text, std::size_t limit = 40);

// A JSON string literal, always valid UTF-8 (core/text/json_string.h): a WebSocket text frame
// that is not UTF-8 makes clients drop the connection.
using ydscope::append_json_string;

}  // namespace ydscope::foxglove

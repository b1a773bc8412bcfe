#include "core/bridge/foxglove_protocol.h"

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <charconv>
#include <cstdio>
#include <sstream>

#include "core/text/json_writer.h"

namespace ydscope::foxglove {
namespace {

namespace pt = boost::property_tree;

// property_tree keeps every JSON scalar as text: numbers, booleans and strings look alike, so a
// value is read back as the most specific thing it spells.
std::variant<double, bool, std::string> scalar(const std::string& text) {
  if (text == "true") return true;
  if (text == "false") return false;
  double number = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), number);
  if (ec == std::errc() && end == text.data() + text.size() && !text.empty()) return number;
  return text;
}

std::optional<std::uint32_t> u32(const std::string& text) {
  std::uint32_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
  return value;
}

// The children of an array field (empty keys), or empty with an error when it is not one.
const pt::ptree* array_field(const pt::ptree& tree, const char* name, std::string& error) {
  const auto child = tree.get_child_optional(name);
  if (!child) {
    error = std::string("\"") + name + "\" is missing";
    return nullptr;
  }
  // property_tree reads a string or a number as a node with data and no children, as it reads
  // an empty array but for the data; it must not pass for an empty array.
  bool array = child->empty() ? child->data().empty() : true;
  for (const auto& [key, _] : *child) array = array && key.empty();
  if (!array) {
    error = std::string("\"") + name + "\" must be an array";
    return nullptr;
  }
  return &*child;
}

// property_tree's JSON reader recurses once per level of nesting, so a client message of 64 KiB of
// "[" would overflow the server thread's stack. No request of the protocol nests deeper than 3.
constexpr int kMaxJsonDepth = 32;

bool nests_deeper_than(std::string_view text, int limit) {
  int depth = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > limit) return true;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return false;
}

std::vector<std::string> string_list(const pt::ptree* list) {
  std::vector<std::string> out;
  if (list)
    for (const auto& [_, item] : *list) out.push_back(item.data());
  return out;
}

}  // namespace

std::string server_info_json(std::string_view name, std::string_view session_id) {
  std::string out;
  JsonObject info(out);
  info.field("op", "serverInfo").field("name", name);
  info.array("capabilities").item("parameters").item("parametersSubscribe");
  info.array("supportedEncodings").close();
  info.object("metadata").close();
  info.field("sessionId", session_id);
  info.close();
  return out;
}

std::string advertise_json(const std::vector<ChannelAd>& channels) {
  std::string out;
  JsonObject advertise(out);
  advertise.field("op", "advertise");
  {
    JsonArray list = advertise.array("channels");
    for (const ChannelAd& c : channels)
      list.object()
          .field("id", c.id)
          .field("topic", c.topic)
          .field("encoding", "cdr")
          .field("schemaName", c.schema_name)
          .field("schemaEncoding", "ros2msg")
          .field("schema", c.schema);
  }
  advertise.close();
  return out;
}

std::string status_json(StatusLevel level, std::string_view message, std::string_view id) {
  std::string out;
  JsonObject status(out);
  status.field("op", "status").field("level", static_cast<int>(level)).field("message", message);
  if (!id.empty()) status.field("id", id);
  status.close();
  return out;
}

std::string remove_status_json(std::string_view id) {
  std::string out;
  JsonObject remove(out);
  remove.field("op", "removeStatus").array("statusIds").item(id);
  remove.close();
  return out;
}

std::string parameter_values_json(const std::vector<Parameter>& parameters,
                                  const std::optional<std::string>& request_id) {
  std::string out;
  JsonObject values(out);
  values.field("op", "parameterValues");
  {
    JsonArray list = values.array("parameters");
    for (const Parameter& p : parameters) {
      JsonObject parameter = list.object();
      parameter.field("name", p.name);
      std::visit([&parameter](const auto& value) { parameter.field("value", value); }, p.value);
      if (std::holds_alternative<double>(p.value)) parameter.field("type", "float64");
    }
  }
  if (request_id) values.field("id", *request_id);
  values.close();
  return out;
}

std::array<std::uint8_t, 13> message_data_header(std::uint32_t subscription_id, std::uint64_t log_time_ns) {
  std::array<std::uint8_t, 13> header{};
  header[0] = 0x01;
  for (int i = 0; i < 4; ++i) header[1 + i] = static_cast<std::uint8_t>(subscription_id >> (8 * i));
  for (int i = 0; i < 8; ++i) header[5 + i] = static_cast<std::uint8_t>(log_time_ns >> (8 * i));
  return header;
}

std::string quoted_client_text(std::string_view text, std::size_t limit) {
  std::string out = "\"" + std::string(text.substr(0, limit)) + "\"";
  if (text.size() > limit) out += "... (" + std::to_string(text.size()) + " bytes)";
  return out;
}

std::optional<ClientRequest> parse_client_message(std::string_view text, std::string& error) {
  if (nests_deeper_than(text, kMaxJsonDepth)) {
    error = "nested deeper than " + std::to_string(kMaxJsonDepth) + " levels";
    return std::nullopt;
  }
  pt::ptree tree;
  try {
    std::istringstream in{std::string(text)};
    pt::read_json(in, tree);
  } catch (const pt::json_parser_error& e) {
    error = "not JSON (" + e.message() + " at line " + std::to_string(e.line()) + ")";
    return std::nullopt;
  }
  const auto op_node = tree.get_child_optional("op");
  if (!op_node) {
    error = "no \"op\" field";
    return std::nullopt;
  }
  if (!op_node->empty()) {
    error = "\"op\" must be a string";
    return std::nullopt;
  }
  const std::string& op = op_node->data();
  std::optional<std::string> id;
  if (const auto given = tree.get_optional<std::string>("id")) id = *given;
  if (op == "subscribe") {
    const pt::ptree* list = array_field(tree, "subscriptions", error);
    if (!list) return std::nullopt;
    Subscribe request;
    for (const auto& [_, item] : *list) {
      const auto sub = u32(item.get<std::string>("id", ""));
      const auto channel = u32(item.get<std::string>("channelId", ""));
      if (!sub || !channel) {
        error = "each subscription needs a numeric \"id\" and \"channelId\"";
        return std::nullopt;
      }
      request.subscriptions.emplace_back(*sub, *channel);
    }
    return request;
  }
  if (op == "unsubscribe") {
    const pt::ptree* list = array_field(tree, "subscriptionIds", error);
    if (!list) return std::nullopt;
    Unsubscribe request;
    for (const auto& [_, item] : *list) {
      const auto sub = u32(item.data());
      if (!sub) {
        error = "\"subscriptionIds\" must hold numbers";
        return std::nullopt;
      }
      request.subscription_ids.push_back(*sub);
    }
    return request;
  }
  if (op == "getParameters") {
    std::string ignored;
    return GetParameters{string_list(array_field(tree, "parameterNames", ignored)), id};
  }
  if (op == "setParameters") {
    const pt::ptree* list = array_field(tree, "parameters", error);
    if (!list) return std::nullopt;
    SetParameters request;
    request.id = id;
    for (const auto& [_, item] : *list) {
      const auto name = item.get_optional<std::string>("name");
      const auto value = item.get_optional<std::string>("value");
      if (!name || !value) {
        error = "each parameter needs a \"name\" and a \"value\"";
        return std::nullopt;
      }
      request.parameters.push_back({*name, scalar(*value)});
    }
    return request;
  }
  if (op == "subscribeParameterUpdates" || op == "unsubscribeParameterUpdates") {
    std::string ignored;
    auto names = string_list(array_field(tree, "parameterNames", ignored));
    if (op == "subscribeParameterUpdates") return SubscribeParameterUpdates{std::move(names)};
    return UnsubscribeParameterUpdates{std::move(names)};
  }
  error = "op " + quoted_client_text(op) + " is not supported by this server";
  return std::nullopt;
}

}  // namespace ydscope::foxglove

// Fuzzes what the Foxglove WebSocket server does with a client's text message: the request
// parser on any text (as FoxgloveServer's handle_text calls it), then the replies the server
// builds from the outcome (a status carrying the parser's sentence, parameterValues echoing a
// request's names, values and id).
// Checks besides "no crash, no sanitizer report" (a deeply nested message must not exhaust the
// server thread's stack):
// - a message is either a request or one non-empty sentence, never both;
// - every reply is valid UTF-8 (a WebSocket text frame must be, or clients drop the connection)
//   and JSON that reads back with its "op";
// - a request never holds more items than its text could spell.
#include <cstdint>
#include <sstream>
#include <string>
#include <string_view>
#include <variant>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include "core/bridge/foxglove_protocol.h"
#include "core/text/json_string.h"
#include "fuzz/fuzz_input.h"

namespace {

using namespace ydscope;
using namespace ydscope::foxglove;
namespace pt = boost::property_tree;

void check_reply(const std::string& json, const char* op) {
  FUZZ_CHECK(is_valid_utf8(json), "a reply is not UTF-8");
  pt::ptree tree;
  try {
    std::istringstream in(json);
    pt::read_json(in, tree);
  } catch (const pt::json_parser_error& e) {
    FUZZ_CHECK(false, ("a reply is not JSON: " + json.substr(0, 200)).c_str());
  }
  FUZZ_CHECK(tree.get<std::string>("op", "") == op, "a reply lost its op");
}

std::size_t items(const ClientRequest& request) {
  return std::visit(
      [](const auto& r) -> std::size_t {
        using T = std::decay_t<decltype(r)>;
        if constexpr (std::is_same_v<T, Subscribe>)
          return r.subscriptions.size();
        else if constexpr (std::is_same_v<T, Unsubscribe>)
          return r.subscription_ids.size();
        else if constexpr (std::is_same_v<T, SetParameters>)
          return r.parameters.size();
        else
          return r.names.size();
      },
      request);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > kMaxClientMessage) return 0;  // the server never parses larger messages
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::string error;
  const auto request = parse_client_message(text, error);
  if (!request) {
    FUZZ_CHECK(!error.empty(), "a message was refused without a sentence");
    check_reply(status_json(StatusLevel::Error, "ignored a client message: " + error), "status");
    return 0;
  }
  FUZZ_CHECK(error.empty(), "a request was accepted with an error sentence");
  // Each item of a JSON array takes at least two bytes of text ("1," or "{}").
  FUZZ_CHECK(items(*request) <= size / 2 + 1, "more items than the text could spell");
  if (const auto* set = std::get_if<SetParameters>(&*request)) {
    check_reply(parameter_values_json(set->parameters, set->id), "parameterValues");
  } else if (const auto* get = std::get_if<GetParameters>(&*request)) {
    std::vector<Parameter> echoed;
    for (const std::string& name : get->names) echoed.push_back({name, name});
    check_reply(parameter_values_json(echoed, get->id), "parameterValues");
  }
  return 0;
}

// The client requests the server refuses, on strings alone: each refusal is one sentence that
// names the trouble and quotes no more than a few bytes of what the client sent.
#include <gtest/gtest.h>

#include "core/bridge/foxglove_protocol.h"

namespace ydscope::foxglove {
namespace {

std::string refusal(std::string_view text) {
  std::string error;
  EXPECT_FALSE(parse_client_message(text, error)) << text.substr(0, 80);
  return error;
}

// Regression: property_tree reads "all" as a node without children, as it reads [], so a
// subscribe whose subscriptions were a string was taken as a subscribe to nothing, in silence.
TEST(FoxgloveProtocol, AFieldThatMustBeAnArrayIsNotAStringOrANumber) {
  EXPECT_EQ(refusal(R"({"op":"subscribe","subscriptions":"all"})"), "\"subscriptions\" must be an array");
  EXPECT_EQ(refusal(R"({"op":"unsubscribe","subscriptionIds":7})"), "\"subscriptionIds\" must be an array");
  EXPECT_EQ(refusal(R"({"op":"setParameters","parameters":{"name":"scan_hz"}})"), "\"parameters\" must be an array");
  std::string error;
  const auto empty = parse_client_message(R"({"op":"subscribe","subscriptions":[]})", error);
  ASSERT_TRUE(empty) << error;
  EXPECT_TRUE(std::get<Subscribe>(*empty).subscriptions.empty());
}

TEST(FoxgloveProtocol, AnOpMustBeAString) {
  EXPECT_EQ(refusal(R"({"op":{"nested":1}})"), "\"op\" must be a string");
  EXPECT_EQ(refusal(R"({"op":["subscribe"]})"), "\"op\" must be a string");
  EXPECT_EQ(refusal(R"({"subscriptions":[]})"), "no \"op\" field");
}

// Regression: an unknown op came back whole in the status message, 60 KiB for 60 KiB.
TEST(FoxgloveProtocol, AnUnknownOpIsQuotedShort) {
  EXPECT_EQ(refusal(R"({"op":"fly"})"), "op \"fly\" is not supported by this server");
  const std::string error = refusal(R"({"op":")" + std::string(60'000, 'z') + R"("})");
  EXPECT_EQ(error, "op \"" + std::string(40, 'z') + "\"... (60000 bytes) is not supported by this server");
}

}  // namespace
}  // namespace ydscope::foxglove

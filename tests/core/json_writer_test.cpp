// The JSON field writer every hand-written JSON output uses (core/text/json_writer.h): commas,
// quoted and escaped keys, values by type, nesting, and numbers JSON can hold.
#include "core/text/json_writer.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <optional>
#include <string>

namespace ydscope {
namespace {

TEST(JsonWriter, FieldsGetCommasAndQuotedKeys) {
  std::string out;
  {
    JsonObject o(out);
    o.field("a", 1).field("b", "two").field("c", true).field("d", false).field("e", nullptr);
  }
  EXPECT_EQ(out, R"({"a":1,"b":"two","c":true,"d":false,"e":null})");
}

TEST(JsonWriter, EmptyContainers) {
  std::string out;
  JsonObject(out).close();
  JsonArray(out).close();
  JsonArray(out, "  ").close();
  EXPECT_EQ(out, "{}[][]");
}

TEST(JsonWriter, KeysAndStringsAreEscaped) {
  std::string out;
  {
    JsonObject o(out);
    o.field("quote\"back\\slash", "line\nbreak\ttab \x01");
    o.field("bad", std::string("\xff\xfe ok"));
  }
  EXPECT_EQ(out, R"({"quote\"back\\slash":"line\nbreak\u0009tab \u0001","bad":"\ufffd\ufffd ok"})");
}

TEST(JsonWriter, AStringLiteralIsAStringNotABool) {
  std::string out;
  JsonObject(out).field("verdict", "pass");
  EXPECT_EQ(out, R"({"verdict":"pass"})");
}

TEST(JsonWriter, Integers) {
  std::string out;
  {
    JsonArray a(out);
    a.item(0).item(std::uint8_t{255}).item(-1).item(std::numeric_limits<std::int64_t>::min());
    a.item(std::numeric_limits<std::uint64_t>::max());
  }
  EXPECT_EQ(out, "[0,255,-1,-9223372036854775808,18446744073709551615]");
}

TEST(JsonWriter, FixedDecimalsDropTrailingZeros) {
  std::string out;
  {
    JsonArray a(out);
    a.item(7161.25, 2).item(1000.0, 3).item(0.1, 6).item(-2.5, 1).item(-0.0001, 2).item(1.23456789, 6);
  }
  EXPECT_EQ(out, "[7161.25,1000,0.1,-2.5,0,1.234568]");
}

TEST(JsonWriter, ShortestDoublesReadBack) {
  std::string out;
  JsonArray(out).item(0.1).item(-3.0).item(1e300).item(5e-324);
  EXPECT_EQ(out, "[0.1,-3,1e+300,5e-324]");
}

TEST(JsonWriter, NumbersThatAreNotFiniteAreNull) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  std::string out;
  {
    JsonObject o(out);
    o.field("nan", nan).field("inf", inf).field("minus_inf", -inf);
    o.field("nan_fixed", nan, 2).field("inf_fixed", inf, 3);
  }
  EXPECT_EQ(out, R"({"nan":null,"inf":null,"minus_inf":null,"nan_fixed":null,"inf_fixed":null})");
}

TEST(JsonWriter, OptionalsAreTheirValueOrNull) {
  std::string out;
  {
    JsonObject o(out);
    o.field("hz", std::optional<double>(7.256), 2).field("no_hz", std::optional<double>(), 2);
    o.field("health", std::optional<std::uint8_t>(3)).field("no_health", std::optional<std::uint8_t>());
    o.field("name", std::optional<std::string>("x")).field("ok", std::optional<bool>(false));
  }
  EXPECT_EQ(out, R"({"hz":7.26,"no_hz":null,"health":3,"no_health":null,"name":"x","ok":false})");
}

TEST(JsonWriter, NestedContainersCloseInOrder) {
  std::string out;
  {
    JsonObject o(out);
    o.field("type", "check");
    {
      JsonArray list = o.array("failed");
      list.item("a").item("b");
    }
    {
      JsonObject device = o.object("device");
      device.field("baud", 230400);
      JsonArray deep = device.array("deep");
      JsonObject inner = deep.object();
      inner.field("x", 1);
      inner.close();
      deep.array().item(2);
    }
    o.field("after", 0);
  }
  EXPECT_EQ(out, R"({"type":"check","failed":["a","b"],"device":{"baud":230400,"deep":[{"x":1},[2]]},"after":0})");
}

TEST(JsonWriter, ValueTextTakesAValueWrittenElsewhere) {
  std::string out;
  {
    JsonObject o(out);
    o.value_text("points") += "[[1,2]]";
    JsonArray a = o.array("more");
    a.item_text() += "{}";
    a.item_text() += "[]";
  }
  EXPECT_EQ(out, R"({"points":[[1,2]],"more":[{},[]]})");
}

TEST(JsonWriter, IndentedArrayPutsEachItemOnALine) {
  std::string out;
  {
    JsonArray a(out, "  ");
    a.object().field("path", "/dev/ttyUSB0");
    a.object().field("path", "/dev/ttyUSB1");
  }
  EXPECT_EQ(out, "[\n  {\"path\":\"/dev/ttyUSB0\"},\n  {\"path\":\"/dev/ttyUSB1\"}\n]");
}

TEST(JsonWriter, CloseTwiceAndMovedFromWriteNothingMore) {
  std::string out;
  {
    JsonObject first(out);
    JsonObject moved(std::move(first));
    moved.field("k", 1);
    moved.close();
    moved.close();
  }
  EXPECT_EQ(out, R"({"k":1})");
}

}  // namespace
}  // namespace ydscope

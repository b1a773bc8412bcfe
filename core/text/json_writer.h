#pragma once
// JSON objects and arrays written field by field into a string. The writer puts the commas, quotes
// the keys and writes each value by its type, so the code that prints a record names its fields and
// nothing more. Every JSON text the project writes by hand (the CLI's lines, the Foxglove protocol)
// goes through here, and is always valid JSON: strings as json_string.h writes them, numbers
// locale-free (number_text.h), and a number that is not finite as null (JSON has no NaN).
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "core/text/number_text.h"

namespace ydscope {

template <class T>
concept JsonInteger = std::integral<T> && !std::same_as<T, bool>;

// The values a field or an item may hold, each appended to `out` as JSON text.
void append_json_value(std::string& out, std::string_view text);  // a string literal, escaped
void append_json_value(std::string& out, const char* text);       // (not a bool)
void append_json_value(std::string& out, bool value);
void append_json_value(std::string& out, std::nullptr_t);  // null
// The shortest text that reads back as the same double.
void append_json_value(std::string& out, double value);
// `decimals` places at most, trailing zeros removed (append_fixed): 7161.25, 1000.
void append_json_value(std::string& out, double value, int decimals);
template <JsonInteger T>
void append_json_value(std::string& out, T value) {
  if constexpr (std::signed_integral<T>) {
    if (value < 0) {
      out.push_back('-');
      return append_integer(out, 0 - static_cast<std::uint64_t>(value));
    }
  }
  append_integer(out, static_cast<std::uint64_t>(value));
}
// The value as its type writes it, or null when there is none.
template <class T, class... Format>
void append_json_value(std::string& out, const std::optional<T>& value, Format... format) {
  if (value)
    append_json_value(out, *value, format...);
  else
    append_json_value(out, nullptr);
}

// A text that says nothing when empty: field("by_id", text_or_null(port.by_id)) writes null then.
inline std::optional<std::string_view> text_or_null(std::string_view text) {
  return text.empty() ? std::nullopt : std::optional(text);
}

class JsonObject;
class JsonArray;

// What objects and arrays share: where they write, whether anything stands in them yet, and their
// closing bracket. A container must be closed (close(), or its end of scope) before the one it
// stands in writes again.
class JsonContainer {
 public:
  JsonContainer(const JsonContainer&) = delete;
  JsonContainer& operator=(const JsonContainer&) = delete;
  JsonContainer(JsonContainer&& other) noexcept;
  JsonContainer& operator=(JsonContainer&&) = delete;
  ~JsonContainer() { close(); }

  // Writes the closing bracket; a second call does nothing.
  void close();

 protected:
  JsonContainer(std::string& out, char open, char close, std::string_view item_indent);
  // The comma (and indent) before the next member; returns the text to append it to.
  std::string& next_member();

 private:
  std::string* out_;
  std::string_view item_indent_;
  char close_;
  bool empty_ = true;
};

// {"key":value,...}: the constructor writes '{', close() '}'.
class JsonObject : public JsonContainer {
 public:
  explicit JsonObject(std::string& out) : JsonContainer(out, '{', '}', {}) {}

  // field("laps", 12), field("scan_hz", 7.25, 2), field("serial", text), field("health", optional)
  template <class... Value>
  JsonObject& field(std::string_view key, Value&&... value) {
    append_json_value(value_text(key), std::forward<Value>(value)...);
    return *this;
  }
  JsonObject object(std::string_view key);
  // item_indent: as JsonArray's (text that outlives the array, such as a literal).
  JsonArray array(std::string_view key, std::string_view item_indent = {});
  // Writes the key; the caller appends one JSON value to the text returned (a value some other
  // writer formats, such as a lap's point fields).
  std::string& value_text(std::string_view key);
};

// [value,...]: the constructor writes '[', close() ']'. With an item_indent, each item starts on a
// line of its own after that indent, and the ']' on a line of its own when there are items.
class JsonArray : public JsonContainer {
 public:
  explicit JsonArray(std::string& out, std::string_view item_indent = {}) : JsonContainer(out, '[', ']', item_indent) {}

  template <class... Value>
  JsonArray& item(Value&&... value) {
    append_json_value(item_text(), std::forward<Value>(value)...);
    return *this;
  }
  JsonObject object();
  JsonArray array(std::string_view item_indent = {});
  // The separator before the next item; the caller appends one JSON value to the text returned.
  std::string& item_text() { return next_member(); }
};

}  // namespace ydscope

#include "core/text/json_writer.h"

#include <array>
#include <charconv>
#include <cmath>

#include "core/text/json_string.h"

namespace ydscope {

void append_json_value(std::string& out, std::string_view text) { append_json_string(out, text); }

void append_json_value(std::string& out, const char* text) { append_json_string(out, text); }

void append_json_value(std::string& out, bool value) { out += value ? "true" : "false"; }

void append_json_value(std::string& out, std::nullptr_t) { out += "null"; }

void append_json_value(std::string& out, double value) {
  if (!std::isfinite(value)) return append_json_value(out, nullptr);
  std::array<char, 32> text;  // the shortest round trip of a double takes at most 24
  const auto end = std::to_chars(text.data(), text.data() + text.size(), value).ptr;
  out.append(text.data(), end);
}

void append_json_value(std::string& out, double value, int decimals) {
  if (!std::isfinite(value)) return append_json_value(out, nullptr);
  append_fixed(out, value, decimals);
}

JsonContainer::JsonContainer(std::string& out, char open, char close, std::string_view item_indent)
    : out_(&out), item_indent_(item_indent), close_(close) {
  out.push_back(open);
}

JsonContainer::JsonContainer(JsonContainer&& other) noexcept
    : out_(std::exchange(other.out_, nullptr)),
      item_indent_(other.item_indent_),
      close_(other.close_),
      empty_(other.empty_) {}

void JsonContainer::close() {
  if (!out_) return;
  if (!empty_ && !item_indent_.empty()) out_->push_back('\n');
  out_->push_back(close_);
  out_ = nullptr;
}

std::string& JsonContainer::next_member() {
  if (!empty_) out_->push_back(',');
  if (!item_indent_.empty()) {
    out_->push_back('\n');
    out_->append(item_indent_);
  }
  empty_ = false;
  return *out_;
}

std::string& JsonObject::value_text(std::string_view key) {
  std::string& out = next_member();
  append_json_string(out, key);
  out.push_back(':');
  return out;
}

JsonObject JsonObject::object(std::string_view key) { return JsonObject(value_text(key)); }

JsonArray JsonObject::array(std::string_view key, std::string_view item_indent) {
  return JsonArray(value_text(key), item_indent);
}

JsonObject JsonArray::object() { return JsonObject(item_text()); }

JsonArray JsonArray::array(std::string_view item_indent) { return JsonArray(item_text(), item_indent); }

}  // namespace ydscope

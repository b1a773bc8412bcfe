#include "core/text/quoted_text.h"

#include <cstdio>

#include "core/text/json_string.h"

namespace ydscope {
namespace {

void append_escaped(std::string& out, const char* format, unsigned value) {
  char escaped[8];
  std::snprintf(escaped, sizeof escaped, format, value);
  out += escaped;
}

}  // namespace

std::string quote_file_text(std::string_view text) {
  const bool cut = text.size() > kMaxQuotedBytes;
  const std::string_view shown = cut ? text.substr(0, kMaxQuotedBytes) : text;
  std::string out = "'";
  for (std::size_t i = 0; i < shown.size();) {
    const auto byte = static_cast<unsigned char>(shown[i]);
    const std::size_t length = utf8_sequence_length(shown, i);
    if (byte == '\\') {
      out += "\\\\";
    } else if (byte == '\n') {
      out += "\\n";
    } else if (byte == '\t') {
      out += "\\t";
    } else if (byte < 0x20 || byte == 0x7F || length == 0) {
      append_escaped(out, "\\x%02x", byte);
    } else if (length == 2 && byte == 0xC2 && static_cast<unsigned char>(shown[i + 1]) < 0xA0) {
      append_escaped(out, "\\u%04x", static_cast<unsigned char>(shown[i + 1]));  // C1: U+0080..U+009F
    } else {
      out.append(shown.substr(i, length));
      i += length;
      continue;
    }
    i += length == 0 ? 1 : length;
  }
  out += cut ? "...' (" + std::to_string(text.size()) + " bytes)" : "'";
  return out;
}

}  // namespace ydscope

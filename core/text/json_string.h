#pragma once
// JSON string literals that are always valid JSON text: quotes and backslashes escaped, control
// bytes (and DEL) as \u00XX, and every byte that does not start a valid UTF-8 sequence as one
// \ufffd. Text from devices (serials), files and network clients can hold any bytes; what we write
// for a JSON reader or into a WebSocket text frame (which must be UTF-8) never does.
#include <cstddef>
#include <string>
#include <string_view>

namespace ydscope {

// Length of the valid UTF-8 sequence starting at text[i] (no overlongs, no surrogates, at most
// U+10FFFF), or 0 when the bytes there are not one. ASCII bytes have length 1.
std::size_t utf8_sequence_length(std::string_view text, std::size_t i);

bool is_valid_utf8(std::string_view text);

// Appends `text` as a JSON string literal, quotes included.
void append_json_string(std::string& out, std::string_view text);

}  // namespace ydscope

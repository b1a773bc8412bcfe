#pragma once
// Text from a file (a recording's metadata) quoted in a message for a terminal: a file can hold
// any bytes, and an ESC sequence or a stray C1 byte copied to stderr would drive the terminal
// (clear it, retitle it, hide the rest of the line). Every message that quotes file text quotes it
// here, so what the user sees is the bytes, never their effect.
#include <string>
#include <string_view>

namespace ydscope {

// 'text' in single quotes: a backslash as \\, a newline as \n, a tab as \t, other control bytes
// (C0, DEL) and bytes that are not valid UTF-8 as \xHH, C1 control characters (U+0080..U+009F)
// as \u0080..\u009f; valid UTF-8 stays as it is. Over kMaxQuotedBytes, the head is quoted and the
// size said: 'abc...' (1048576 bytes), so one damaged field keeps a message to one line.
std::string quote_file_text(std::string_view text);

inline constexpr std::size_t kMaxQuotedBytes = 80;

}  // namespace ydscope

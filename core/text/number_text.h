#pragma once
// Numbers as the project's text outputs print them (JSON lines, CSV, the app's exports):
// locale-free, byte-for-byte deterministic, and fast enough for a point stream.
#include <cstdint>
#include <string>

namespace ydscope {

void append_integer(std::string& out, std::uint64_t value);
// `value` rounded to `decimals` places (0..6), trailing zeros and a bare point removed: 7161.25,
// 1000, 0.1. Ties round to even, as std::to_chars does.
void append_fixed(std::string& out, double value, int decimals);

}  // namespace ydscope

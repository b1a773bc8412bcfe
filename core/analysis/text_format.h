#pragma once
// printf-style formatting into a std::string (GCC 12 has no <format>), for the criteria's
// measured and limit texts and the report.
#include <string>

namespace ydscope {

[[gnu::format(printf, 1, 2)]] std::string format_text(const char* format, ...);

}  // namespace ydscope

#include "core/text/number_text.h"

#include <array>
#include <charconv>
#include <cmath>

namespace ydscope {

void append_integer(std::string& out, std::uint64_t value) {
  std::array<char, 24> digits;
  const auto end = std::to_chars(digits.data(), digits.data() + digits.size(), value).ptr;
  out.append(digits.data(), end);
}

void append_fixed(std::string& out, double value, int decimals) {
  // Scaled-integer formatting: to_chars' exact fixed-precision path dominated jsonl output time,
  // and points need only a few decimals.
  static constexpr std::array<double, 7> kScale{1, 10, 100, 1e3, 1e4, 1e5, 1e6};
  const int places = decimals < 0 ? 0 : (decimals > 6 ? 6 : decimals);
  const double scaled = std::nearbyint(std::fabs(value) * kScale[static_cast<std::size_t>(places)]);
  if (!std::isfinite(value) || scaled >= 9e15) {  // beyond exact integers: let to_chars handle it
    std::array<char, 352> digits;
    const auto end =
        std::to_chars(digits.data(), digits.data() + digits.size(), value, std::chars_format::fixed, places).ptr;
    out.append(digits.data(), end);
    return;
  }
  auto units = static_cast<std::uint64_t>(scaled);
  if (units == 0) {
    out.push_back('0');
    return;
  }
  if (value < 0) out.push_back('-');
  std::array<char, 8> fraction{};
  int fraction_digits = places;
  for (int i = places - 1; i >= 0; --i) {
    fraction[static_cast<std::size_t>(i)] = static_cast<char>('0' + units % 10);
    units /= 10;
  }
  while (fraction_digits > 0 && fraction[static_cast<std::size_t>(fraction_digits - 1)] == '0') --fraction_digits;
  append_integer(out, units);
  if (fraction_digits > 0) {
    out.push_back('.');
    out.append(fraction.data(), static_cast<std::size_t>(fraction_digits));
  }
}

}  // namespace ydscope

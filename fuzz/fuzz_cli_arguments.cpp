// Fuzzes ydscope-cli's option parser with arbitrary command lines (arguments split at NUL bytes),
// using the options the subcommands really declare. Anything but a UsageError escaping, or a
// value outside the range asked for, is a failure.
#include <cmath>
#include <cstdint>
#include <set>
#include <string>

#include "app/common/arguments.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using ydscope::Arguments;
  using ydscope::UsageError;
  const auto args = ydscope::fuzz::split_arguments(data, size);
  try {
    const Arguments parsed(args, {"port", "model", "baud", "seconds", "out", "laps", "distance-scale", "scan-hz"},
                           {"force", "json", "summary", "verbose"}, /*max_positionals=*/1);
    if (const auto seconds = parsed.number("seconds", 0.001, 86400.0)) {
      FUZZ_CHECK(std::isfinite(*seconds) && *seconds >= 0.001 && *seconds <= 86400.0, "--seconds out of its range");
    }
    if (const auto laps = parsed.integer("laps", 1, 1000000)) {
      FUZZ_CHECK(*laps >= 1 && *laps <= 1000000, "--laps out of its range");
    }
    (void)parsed.value("model");
    (void)parsed.has("force");
    (void)parsed.required("port");
    (void)parsed.single_positional("FILE");
  } catch (const UsageError& error) {
    FUZZ_CHECK(*error.what() != '\0', "a usage error without a sentence");
  }
  return 0;
}

// Fuzzes the ydscope window's command line (arguments split at NUL bytes). A bad command line
// must end in one UsageError sentence; a good one must satisfy the parser's own rules.
#include <cstdint>
#include <string>

#include "app/gui/app_options.h"
#include "core/protocol/model_profile.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ydscope::gui;
  const auto args = ydscope::fuzz::split_arguments(data, size);
  try {
    const AppOptions options = parse_app_options(args);
    FUZZ_CHECK(options.frames >= 1, "--frames accepted below 1");
    FUZZ_CHECK(!options.baud || *options.baud > 0, "--baud accepted 0");
    if (options.model && *options.model != "auto") {
      FUZZ_CHECK(ydscope::find_profile(*options.model) != nullptr, "an unknown model was accepted");
    }
  } catch (const ydscope::UsageError& error) {
    FUZZ_CHECK(*error.what() != '\0', "an options error without a sentence");
  }
  return 0;
}

#include "app/cli/cli_command.h"

#include <csignal>
#include <algorithm>

namespace ydscope::cli {

namespace {
// Function-local so registration from other translation units never sees it uninitialised.
std::vector<CliCommand>& registry() {
  static std::vector<CliCommand> commands;
  return commands;
}
}  // namespace

std::span<const CliCommand> registered_commands() {
  auto& commands = registry();
  std::sort(commands.begin(), commands.end(), [](const CliCommand& a, const CliCommand& b) { return a.name < b.name; });
  return commands;
}

RegisterCliCommand::RegisterCliCommand(const CliCommand& command) { registry().push_back(command); }

void end_on_signals(void (*handler)(int)) {
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) std::signal(signal, handler);
}

}  // namespace ydscope::cli

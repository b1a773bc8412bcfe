// ydscope-cli: the headless twin of the ydscope window. Dispatches to the registered subcommands.
#include <iostream>
#include <string>
#include <vector>

#include "app/cli/arguments.h"
#include "app/cli/cli_command.h"
#include "core/version.h"

namespace {

void print_overview(std::ostream& out) {
  out << "ydscope-cli: headless toolkit for YDLIDAR G1, G6 and TG15/TG30/TG50 lidars.\n\n"
         "usage: ydscope-cli COMMAND [options]\n"
         "       ydscope-cli COMMAND --help   (options and examples of one command)\n\n"
         "commands:\n";
  for (const auto& command : ydscope::cli::registered_commands())
    out << "  " << command.name << std::string(10 - std::min<std::size_t>(9, command.name.size()), ' ')
        << command.summary << "\n";
  out << "\nexit status: 0 success, 1 device or I/O failure, 2 usage error.\n";
}

}  // namespace

int main(int argc, char** argv) {
  using namespace ydscope::cli;
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) {
    print_overview(std::cerr);
    return kExitUsage;
  }
  if (args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    print_overview(std::cout);
    return kExitOk;
  }
  if (args[0] == "--version" || args[0] == "-V") {
    std::cout << "ydscope-cli " << ydscope::kVersion << "\n";
    return kExitOk;
  }
  for (const auto& command : registered_commands()) {
    if (command.name != args[0]) continue;
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    try {
      return command.run(rest);
    } catch (const UsageError& error) {
      std::cerr << "ydscope-cli " << command.name << ": " << error.what() << "\n";
      return kExitUsage;
    } catch (const std::exception& error) {
      std::cerr << "ydscope-cli " << command.name << ": " << error.what() << "\n";
      return kExitFailure;
    }
  }
  std::cerr << "ydscope-cli: unknown command '" << args[0] << "'; run 'ydscope-cli --help' for the list.\n";
  return kExitUsage;
}

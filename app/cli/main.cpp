// ydscope-cli: the headless twin of the ydscope window. Dispatches to the registered subcommands.
#include <iostream>
#include <span>
#include <string>
#include <vector>

#include "app/cli/cli_command.h"
#include "app/common/arguments.h"
#include "core/version.h"

namespace {

using ydscope::cli::CliCommand;

void print_overview(std::ostream& out) {
  out << "ydscope-cli: headless toolkit for YDLIDAR G1, G6 and TG15/TG30/TG50 lidars.\n\n"
         "usage: ydscope-cli COMMAND [options]\n"
         "       ydscope-cli COMMAND --help   (options and examples of one command; also help COMMAND)\n"
         "       ydscope-cli -V|--version\n\n"
         "commands:\n";
  for (const auto& command : ydscope::cli::registered_commands())
    out << "  " << command.name << std::string(10 - std::min<std::size_t>(9, command.name.size()), ' ')
        << command.summary << "\n";
  out << "\nexit status: 0 success, 1 device or I/O failure, 2 usage error, 3 the command ran to the end but the\n"
         "lidar is not right (scan, record: it reported a health error; check: a criterion failed).\n";
}

const CliCommand* find_command(const std::string& name) {
  for (const auto& command : ydscope::cli::registered_commands())
    if (command.name == name) return &command;
  return nullptr;
}

// "unknown command 'scna'; did you mean scan?" -- or where the list is.
int unknown_command(const std::string& name) {
  std::vector<std::string> names;
  for (const auto& command : ydscope::cli::registered_commands()) names.emplace_back(command.name);
  std::cerr << "ydscope-cli: ";
  if (name.rfind('-', 0) == 0) {
    std::cerr << "'" << name << "' is not a command; options go after the command (ydscope-cli COMMAND " << name
              << " ...); run 'ydscope-cli --help' for the commands.\n";
  } else if (const auto guess = ydscope::closest_match(name, names)) {
    std::cerr << "unknown command '" << name << "'; did you mean " << *guess << "?\n";
  } else {
    std::cerr << "unknown command '" << name << "'; run 'ydscope-cli --help' for the list.\n";
  }
  return ydscope::cli::kExitUsage;
}

int print_help(const CliCommand& command) {
  std::cout << command.help;
  return ydscope::cli::kExitOk;
}

int print_version() {
  std::cout << "ydscope-cli " << ydscope::kVersion << "\n";
  return ydscope::cli::kExitOk;
}

int run_command(const CliCommand& command, std::span<const std::string> args) {
  using namespace ydscope::cli;
  // Help and version win over everything else on the line, as in every other command-line tool.
  if (ydscope::asks_for_help(args)) return print_help(command);
  if (ydscope::asks_for_version(args)) return print_version();
  try {
    return command.run(args);
  } catch (const ydscope::UsageError& error) {
    std::cerr << "ydscope-cli " << command.name << ": " << error.what() << "\n";
    return kExitUsage;
  } catch (const std::exception& error) {
    std::cerr << "ydscope-cli " << command.name << ": " << error.what() << "\n";
    return kExitFailure;
  }
}

}  // namespace

int main(int argc, char** argv) {
  using namespace ydscope::cli;
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) {
    print_overview(std::cerr);
    return kExitUsage;
  }
  const std::string& first = args[0];
  if (first == "--help" || first == "-h" || (first == "help" && args.size() == 1)) {
    print_overview(std::cout);
    return kExitOk;
  }
  if (first == "help") {  // help COMMAND
    if (args.size() > 2) {
      std::cerr << "ydscope-cli help: give one command, not '" << args[2] << "' as well.\n";
      return kExitUsage;
    }
    const CliCommand* command = find_command(args[1]);
    return command ? print_help(*command) : unknown_command(args[1]);
  }
  if (first == "--version" || first == "-V") return print_version();
  const CliCommand* command = find_command(first);
  if (!command) return unknown_command(first);
  return run_command(*command, std::span<const std::string>(args).subspan(1));
}

#pragma once
// ydscope-cli subcommands register themselves here, one file each (cmd_*.cpp), so adding a
// command never touches main or another command.
#include <atomic>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace ydscope::cli {

// Exit codes of every subcommand (docs/architecture.md): 0 success, 1 device or I/O failure, 2 usage error.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;
// The command ran to the end, but the lidar is not right: it reported a health error (scan,
// record) or failed a criterion (check). What it produced is complete.
inline constexpr int kExitLidarFault = 3;
// Ctrl-C cut the run short (check): what was printed covers only the time measured.
inline constexpr int kExitInterrupted = 130;

struct CliCommand {
  std::string_view name;
  std::string_view summary;                       // one line for the command list
  std::string_view help;                          // full help text; main prints it for --help, -h and `help COMMAND`
  int (*run)(std::span<const std::string> args);  // args exclude the subcommand name; parse them with Arguments
};

std::span<const CliCommand> registered_commands();

// The signals that end a command as Ctrl-C does (so a device command stops the lidar and keeps
// what it recorded): SIGINT, SIGTERM and SIGHUP, a closed terminal or ssh session. Once called,
// any of them sets end_requested(), which the command polls. With `interrupt_writes` a write the
// command is blocked in (a reader that stopped reading) fails with EINTR instead of going on
// waiting, so the command can stop the lidar and end.
void end_on_signals(bool interrupt_writes = false);
const std::atomic<bool>& end_requested();

// While it lives, threads this one starts (a session's I/O thread) never take those signals, so
// they reach this thread and interrupt what it is blocked in.
class EndSignalsStayHere {
 public:
  EndSignalsStayHere();
  ~EndSignalsStayHere();
  EndSignalsStayHere(const EndSignalsStayHere&) = delete;
  EndSignalsStayHere& operator=(const EndSignalsStayHere&) = delete;
};

struct RegisterCliCommand {
  explicit RegisterCliCommand(const CliCommand& command);
};

}  // namespace ydscope::cli

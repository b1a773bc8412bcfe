#include "app/cli/cli_command.h"

#include <pthread.h>

#include <algorithm>
#include <csignal>

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

namespace {
std::atomic<bool> end_signalled{false};
extern "C" void on_end_signal(int) { end_signalled.store(true); }
}  // namespace

const std::atomic<bool>& end_requested() { return end_signalled; }

void end_on_signals(bool interrupt_writes) {
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction action {};
    action.sa_handler = on_end_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = interrupt_writes ? 0 : SA_RESTART;  // std::signal's restarting semantics otherwise
    sigaction(signal, &action, nullptr);
  }
}

namespace {
sigset_t end_signals() {
  sigset_t set;
  sigemptyset(&set);
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&set, signal);
  return set;
}
}  // namespace

EndSignalsStayHere::EndSignalsStayHere() {
  const sigset_t set = end_signals();
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
}

EndSignalsStayHere::~EndSignalsStayHere() {
  const sigset_t set = end_signals();
  pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
}

}  // namespace ydscope::cli

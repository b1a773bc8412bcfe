// Both programs' command lines as a user meets them: every ydscope-cli command (read from the
// overview, so a new command is covered too) follows the same rules and exit codes.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "support/program_run.h"

namespace ydscope {
namespace {

using test::run_program;

test::ProgramRun cli(const std::string& arguments) {
  return run_program(YDSCOPE_CLI_PATH, arguments, {.stdin_from_null = true});
}

// The names under "commands:" in `ydscope-cli --help`.
std::vector<std::string> listed_commands() {
  std::istringstream overview(cli("--help").out);
  std::vector<std::string> names;
  std::string line;
  bool in_list = false;
  while (std::getline(overview, line)) {
    if (line == "commands:")
      in_list = true;
    else if (in_list && line.rfind("  ", 0) == 0)
      names.push_back(line.substr(2, line.find(' ', 2) - 2));
    else if (in_list)
      break;
  }
  return names;
}

TEST(CommandLine, OverviewListsTheCommands) {
  const auto names = listed_commands();
  EXPECT_GE(names.size(), 8u);
  for (const char* expected : {"decode", "info", "ports", "record", "replay", "scan", "set", "sim"})
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
}

TEST(CommandLine, EveryCommandHasHelpTwoWaysAndTheVersion) {
  for (const auto& name : listed_commands()) {
    const auto help = cli(name + " --help");
    EXPECT_EQ(help.status, 0) << name << ": " << help.err;
    EXPECT_EQ(help.out.rfind("usage: ydscope-cli " + name, 0), 0u) << name << ": " << help.out;
    EXPECT_EQ(cli(name + " -h").out, help.out) << name;
    EXPECT_EQ(cli("help " + name).out, help.out) << name;
    EXPECT_EQ(cli(name + " --port x --help --nonsense").out, help.out) << name << ": help wins over mistakes";
    const auto version = cli(name + " -V");
    EXPECT_EQ(version.status, 0) << name;
    EXPECT_EQ(version.out, cli("--version").out) << name;
  }
}

TEST(CommandLine, TheSameMistakeGivesTheSameExitCodeInEveryCommand) {
  for (const auto& name : listed_commands()) {
    const auto unknown = cli(name + " --bogus-option 1");
    EXPECT_EQ(unknown.status, 2) << name << ": " << unknown.err;
    EXPECT_NE(unknown.err.find("ydscope-cli " + name + ": unknown option --bogus-option; see --help"),
              std::string::npos)
        << name << ": " << unknown.err;
    const auto stray = cli(name + " stray-one stray-two");
    EXPECT_EQ(stray.status, 2) << name << ": " << stray.err;
    EXPECT_NE(stray.err.find("unexpected argument 'stray-"), std::string::npos) << name << ": " << stray.err;
    const auto format = cli(name + " --fromat json");
    EXPECT_EQ(format.status, 2) << name;
    EXPECT_EQ(std::count(format.err.begin(), format.err.end(), '\n'), 1) << name << ": one sentence: " << format.err;
  }
}

TEST(CommandLine, StrayArgumentsAreRefusedNotIgnored) {
  const auto info = cli("info --port /dev/ydscope-no-such-port garbage");
  EXPECT_EQ(info.status, 2) << info.err;
  EXPECT_EQ(info.err,
            "ydscope-cli info: unexpected argument 'garbage': this command takes only options (see --help)\n");
  const auto decode = cli("decode --model G6 a.bin b.bin");
  EXPECT_EQ(decode.status, 2);
  EXPECT_EQ(decode.err, "ydscope-cli decode: unexpected argument 'b.bin' after 'a.bin' (see --help)\n");
}

TEST(CommandLine, NearMissesAreNamed) {
  EXPECT_EQ(cli("decode --fromat summary x.bin").err,
            "ydscope-cli decode: unknown option --fromat; did you mean --format?\n");
  EXPECT_EQ(cli("info -p /dev/ttyUSB0").err, "ydscope-cli info: unknown option -p; did you mean --port?\n");
  EXPECT_EQ(cli("scan --port x --laps").err,
            "ydscope-cli scan: option --laps needs a value (--laps VALUE or --laps=VALUE)\n");
  const auto command = cli("scna --port x");
  EXPECT_EQ(command.status, 2);
  EXPECT_EQ(command.err, "ydscope-cli: unknown command 'scna'; did you mean scan?\n");
  EXPECT_EQ(cli("help scna").err, command.err);
  EXPECT_EQ(cli("--port x info").status, 2);
  EXPECT_NE(cli("--port x info").err.find("options go after the command"), std::string::npos);
}

TEST(CommandLine, EqualsAndDoubleDashWork) {
  const auto equals = cli("decode --model=G6 --format=summary -- -");
  EXPECT_EQ(equals.status, 0) << equals.err;
  EXPECT_EQ(equals.out.rfind("{\"type\":\"summary\",\"bytes\":0,", 0), 0u) << equals.out;
  // After "--" a name that looks like an option is a file name.
  const auto dashed = cli("decode --model G6 -- --help");
  EXPECT_EQ(dashed.status, 2);
  EXPECT_NE(dashed.err.find("'--help' was not found"), std::string::npos) << dashed.err;
}

// The window shows a missing recording as its state (exit 1 in --screenshot mode, asserted by
// AppSmoke.MissingRecordingFailsWithASentence); in ydscope-cli it is a usage error like any bad path.
TEST(CommandLine, AMissingRecordingIsAUsageErrorInEveryCommand) {
  const std::string missing = "/nonexistent/ydscope-missing.ydrec";
  EXPECT_EQ(cli("decode " + missing).status, 2);
  const auto replay = cli("replay " + missing);
  EXPECT_EQ(replay.status, 2) << replay.err;
  EXPECT_NE(replay.err.find("'" + missing + "' was not found"), std::string::npos) << replay.err;
}

#ifdef YDSCOPE_APP_PATH
TEST(CommandLine, TheAppFollowsTheSameRules) {
  const auto app = [](const std::string& arguments) {
    return run_program(YDSCOPE_APP_PATH, arguments, {.stdin_from_null = true});
  };
  const auto help = app("--help");
  EXPECT_EQ(help.status, 0);
  EXPECT_EQ(help.out.rfind("usage: ydscope ", 0), 0u) << help.out;
  EXPECT_EQ(app("-h --bogus").out, help.out);
  EXPECT_EQ(app("--fulscreen").err, "ydscope: unknown option --fulscreen; did you mean --fullscreen?\n");
  EXPECT_EQ(app("--fulscreen").status, 2);
  EXPECT_EQ(app("stray").status, 2);
  EXPECT_EQ(app("stray").err, "ydscope: unexpected argument 'stray': this command takes only options (see --help)\n");
  EXPECT_EQ(app("-p /dev/ttyUSB0").err, "ydscope: unknown option -p; did you mean --port?\n");
  EXPECT_EQ(app("--sim=G9").status, 2);
  EXPECT_EQ(app("--sim G1 --replay x.ydrec").status, 2);
  // A screenshot with nowhere to go is said before the window opens, not after its frames.
  const auto nowhere = app("--sim G6 --screenshot /nonexistent-folder/shot.png");
  EXPECT_EQ(nowhere.status, 2);
  EXPECT_EQ(nowhere.err,
            "ydscope: --screenshot: there is no folder /nonexistent-folder to save /nonexistent-folder/shot.png in.\n");
  EXPECT_EQ(nowhere.out, "");
}

// Share and record from the command line: a mistake is one sentence and exit 2, before any window.
TEST(CommandLine, TheAppsShareAndRecordOptionsRefuseMistakes) {
  const auto app = [](const std::string& arguments) { return run_program(YDSCOPE_APP_PATH, arguments); };
  EXPECT_EQ(app("--record mov").err, "ydscope: --record takes ydrec, mcap or both, not 'mov'.\n");
  EXPECT_EQ(app("--record mov").status, 2);
  const auto port = app("--share --share-port 70000");
  EXPECT_EQ(port.status, 2);
  EXPECT_NE(port.err.find("--share-port"), std::string::npos) << port.err;
  EXPECT_EQ(port.err.find('\n'), port.err.size() - 1) << "one line: " << port.err;
  EXPECT_EQ(app("--shares").err, "ydscope: unknown option --shares; did you mean --share?\n");
  const auto help = app("--help").out;
  for (const char* option :
       {"--share ", "--share-port N", "--record FORMAT", "W share on/off", "M the shown laps as MCAP"})
    EXPECT_NE(help.find(option), std::string::npos) << option;
}

// Several sources on the app's command line: the record command's syntax, and a mistake is one
// sentence and exit 2 before any window opens.
TEST(CommandLine, TheAppsSeveralSourcesRefuseMistakesInOneSentence) {
  const auto app = [](const std::string& arguments) { return run_program(YDSCOPE_APP_PATH, arguments); };
  const std::pair<const char*, const char*> cases[] = {
      {"--sim G1,G9",
       "ydscope: --sim: unknown model 'G9'; list models from G1, G6, TG15, TG30, TG50 with commas, e.g. --sim "
       "G1,G6,TG30.\n"},
      {"--sim G1,,G6",
       "ydscope: --sim: unknown model ''; list models from G1, G6, TG15, TG30, TG50 with commas, e.g. --sim "
       "G1,G6,TG30.\n"},
      {"--port /tmp/a --port /tmp/b --pose 1,2,0", "ydscope: give --pose once per --port (2 ports), not 1 times\n"},
      {"--port /tmp/a --port /tmp/b --name a --name a", "ydscope: --name a is given to two ports\n"},
      {"--sim G1,G6 --pose 0,0,0",
       "ydscope: --name and --pose go with --port, once per port; name and place virtual lidars in the Sources "
       "panel.\n"},
      {"--port /tmp/a --model G6 --model G1", "ydscope: --model is given twice; give it once (or once per --port).\n"},
      {"--sim G6 --split",
       "ydscope: --split puts several sources side by side; give --sim with several models or --port more than "
       "once.\n"},
  };
  for (const auto& [arguments, said] : cases) {
    const auto run = app(arguments);
    EXPECT_EQ(run.status, 2) << arguments;
    EXPECT_EQ(run.err, said) << arguments;
  }
  const auto bad_pose = app("--port /tmp/a --pose 1,2,x");
  EXPECT_EQ(bad_pose.status, 2);
  EXPECT_EQ(bad_pose.err.rfind("ydscope: --pose: ", 0), 0u) << bad_pose.err;
  const auto help = app("--help").out;
  for (const char* option : {"--sim G1,G6,TG30", "--name N", "--pose X,Y,YAW"})
    EXPECT_NE(help.find(option), std::string::npos) << option;
}
#endif

}  // namespace
}  // namespace ydscope

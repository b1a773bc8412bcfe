// Both programs report the one version CMake's project(VERSION) sets, under -V and --version.
#include <gtest/gtest.h>

#include "support/program_run.h"

namespace ydscope {
namespace {

TEST(Version, CliReportsTheProjectVersion) {
  for (const char* flag : {"--version", "-V"}) {
    const auto run = test::run_program(YDSCOPE_CLI_PATH, flag, {.stdin_from_null = true});
    EXPECT_EQ(run.status, 0) << flag << ": " << run.err;
    EXPECT_EQ(run.out, std::string("ydscope-cli " YDSCOPE_PROJECT_VERSION "\n")) << flag;
  }
}

#ifdef YDSCOPE_APP_PATH
TEST(Version, AppReportsTheProjectVersion) {
  for (const char* flag : {"--version", "-V"}) {
    const auto run = test::run_program(YDSCOPE_APP_PATH, flag, {.stdin_from_null = true});
    EXPECT_EQ(run.status, 0) << flag << ": " << run.err;
    EXPECT_EQ(run.out, std::string("ydscope " YDSCOPE_PROJECT_VERSION "\n")) << flag;
  }
}
#endif

}  // namespace
}  // namespace ydscope

// Command outcomes are shown beside the control that issued them, for a while, and only theirs.
#include <filesystem>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>

#include "ui/view/status/command_feedback.h"
#include "ui/view/export/file_names.h"

namespace ydscope::ui {
namespace {

TEST(CommandFeedback, PendingThenOutcomeThenGone) {
  CommandFeedback f;
  EXPECT_FALSE(f.shown(CommandControl::ScanFrequency, 0.0));
  const auto ticket = f.issued(CommandControl::ScanFrequency);
  auto shown = f.shown(CommandControl::ScanFrequency, 1.0);
  ASSERT_TRUE(shown);
  EXPECT_TRUE(shown->pending);
  EXPECT_FALSE(f.shown(CommandControl::Health, 1.0)) << "another control shows nothing";

  f.finished(CommandControl::ScanFrequency, ticket, true, "set scan frequency to 8.0 Hz: read back 8.00 Hz");
  shown = f.shown(CommandControl::ScanFrequency, 50.0);  // the clock starts when the UI first sees it
  ASSERT_TRUE(shown);
  EXPECT_FALSE(shown->pending);
  EXPECT_TRUE(shown->ok);
  EXPECT_EQ(shown->text, "set scan frequency to 8.0 Hz: read back 8.00 Hz");
  EXPECT_TRUE(f.shown(CommandControl::ScanFrequency, 50.0 + CommandFeedback::kShowSeconds - 0.1));
  EXPECT_FALSE(f.shown(CommandControl::ScanFrequency, 50.0 + CommandFeedback::kShowSeconds + 0.1));
  EXPECT_FALSE(f.shown(CommandControl::ScanFrequency, 50.0)) << "once gone it stays gone";
}

TEST(CommandFeedback, LateOutcomesOfAnOldSourceOrAnOlderPressAreDropped) {
  CommandFeedback f;
  const auto old_ticket = f.issued(CommandControl::Health);
  f.clear();  // a new source
  f.finished(CommandControl::Health, old_ticket, false, "no reply");
  EXPECT_FALSE(f.shown(CommandControl::Health, 0.0));

  const auto first = f.issued(CommandControl::Health);
  const auto second = f.issued(CommandControl::Health);
  f.finished(CommandControl::Health, first, false, "first");
  auto shown = f.shown(CommandControl::Health, 0.0);
  ASSERT_TRUE(shown);
  EXPECT_TRUE(shown->pending) << "the second press is still running";
  f.finished(CommandControl::Health, second, true, "second");
  shown = f.shown(CommandControl::Health, 0.0);
  ASSERT_TRUE(shown);
  EXPECT_EQ(shown->text, "second");
}

TEST(CommandFeedback, OutcomesMayArriveFromAnotherThread) {
  CommandFeedback f;
  const auto ticket = f.issued(CommandControl::Recording);
  std::thread io([&] { f.finished(CommandControl::Recording, ticket, false, "could not create x.ydrec"); });
  io.join();
  const auto shown = f.shown(CommandControl::Recording, 0.0);
  ASSERT_TRUE(shown);
  EXPECT_FALSE(shown->ok);
}

TEST(FileNames, TimestampedNamesNeverNameAnExistingFile) {
  const std::filesystem::path dir = std::filesystem::path(testing::TempDir()) / "ydscope-names";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::time_t when = 1'800'000'000;
  const std::string first = timestamped_name_at(when, "ydrec", dir);
  EXPECT_EQ(std::filesystem::path(first).extension(), ".ydrec");
  EXPECT_EQ(std::filesystem::path(first).filename().string().rfind("ydscope-", 0), 0u);
  std::ofstream(first) << "x";
  const std::string second = timestamped_name_at(when, "ydrec", dir);
  EXPECT_NE(second, first);
  EXPECT_NE(second.find("-2.ydrec"), std::string::npos) << second;
  std::ofstream(second) << "x";
  EXPECT_NE(timestamped_name_at(when, "ydrec", dir).find("-3.ydrec"), std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace ydscope::ui

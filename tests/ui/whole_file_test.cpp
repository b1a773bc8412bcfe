// A file saved in one go appears whole under its name, or not at all.
#include "ui/view/export/whole_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/temp_dir.h"

namespace ydscope::ui {
namespace {

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(WholeFile, AFinishedPartTakesItsName) {
  const test::TempDir dir("whole-file");
  const std::string path = dir.file("export.csv");
  write(part_name(path), "a,b\n1,2\n");
  EXPECT_FALSE(std::filesystem::exists(path)) << "the name is there before the file is whole";
  EXPECT_EQ(finish_whole_file(path, {}), "");
  EXPECT_EQ(read(path), "a,b\n1,2\n");
  EXPECT_FALSE(std::filesystem::exists(part_name(path)));
}

TEST(WholeFile, AFailedSaveLeavesNothingAndSpeaksOfTheFinalName) {
  const test::TempDir dir("whole-file");
  const std::string path = dir.file("shot.png");
  write(part_name(path), "half a pic");
  const std::string error = finish_whole_file(path, "could not write " + part_name(path) + ": No space left on device");
  EXPECT_EQ(error, "could not write " + path + ": No space left on device");
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_FALSE(std::filesystem::exists(part_name(path)));
}

TEST(WholeFile, ARenameThatFailsIsOneSentenceNamingTheFile) {
  const test::TempDir dir("whole-file");
  const std::string path = dir.file("never-written.mcap");  // no part to rename
  const std::string error = finish_whole_file(path, {});
  EXPECT_NE(error.find(path), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
}  // namespace ydscope::ui

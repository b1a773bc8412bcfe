// What settings.ini remembers of the lidars across runs, and what a new run gets back.
#include "ui/view/settings/remembered_sources.h"

#include <gtest/gtest.h>

namespace ydscope::ui {
namespace {

SourceLook look_of(const std::string& name, Rgba8 colour, Pose pose = {}) {
  SourceLook look;
  look.name = name;
  look.colour = colour;
  look.pose = pose;
  return look;
}

TEST(RememberedSources, SeveralAreRememberedLiveAndByNameAndALoneLidarLeavesNothing) {
  ViewSettings settings;
  SourceLook front = look_of("front", source_colour(1), {1.0, 0.5, 90.0, false});
  front.hidden = true;
  const SourceLook back = look_of("back", source_colour(2));
  remember_looks(settings, {front, back});
  EXPECT_EQ(settings.last_sources, (std::vector<std::string>{"front", "back"}));
  ASSERT_EQ(settings.sources.size(), 2u);
  EXPECT_FALSE(settings.sources[0].hidden);  // a new run shows everything
  EXPECT_EQ(settings.sources[0].pose, front.pose);

  // The same name again replaces its old look instead of adding another.
  front.pose = {2.0, 0.0, 0.0, false};
  remember_looks(settings, {front, back});
  ASSERT_EQ(settings.sources.size(), 2u);
  EXPECT_EQ(settings.sources[0].name, "front");
  EXPECT_EQ(settings.sources[0].pose, front.pose);

  remember_looks(settings, {front});
  EXPECT_TRUE(settings.last_sources.empty());
  EXPECT_EQ(settings.sources.size(), 2u);  // the looks stay for the next run of several
}

TEST(RememberedSources, AtMost32LooksAreKeptTheOldestGoingFirst) {
  ViewSettings settings;
  for (int i = 0; i < 40; i += 2)
    remember_looks(settings, {look_of("l" + std::to_string(i), source_colour(0)),
                              look_of("l" + std::to_string(i + 1), source_colour(1))});
  ASSERT_EQ(settings.sources.size(), 32u);
  EXPECT_EQ(settings.sources.front().name, "l8");
  EXPECT_EQ(settings.sources.back().name, "l39");
}

TEST(RememberedSources, ARememberedNameGetsItsPoseAndColourUnlessGivenOrTaken) {
  ViewSettings settings;
  const Pose placed{3.0, -1.0, 45.0, true};
  remember_looks(settings, {look_of("front", source_colour(3), placed), look_of("back", source_colour(4))});

  SourceLook front = look_of("front", source_colour(0));
  recall_look(settings, {}, front, false);
  EXPECT_EQ(front.pose, placed);
  EXPECT_EQ(front.colour, source_colour(3));

  SourceLook given = look_of("front", source_colour(0), {0.5, 0.5, 0.0, false});
  recall_look(settings, {}, given, true);  // --pose given: it wins over the remembered one
  EXPECT_EQ(given.pose, (Pose{0.5, 0.5, 0.0, false}));

  // Another running source has its colour now: it keeps the one it was given.
  SourceLook again = look_of("front", source_colour(0));
  recall_look(settings, {look_of("other", source_colour(3))}, again, false);
  EXPECT_EQ(again.colour, source_colour(0));

  SourceLook stranger = look_of("side", source_colour(5));
  recall_look(settings, {}, stranger, false);
  EXPECT_EQ(stranger.pose, Pose{});
  EXPECT_EQ(stranger.colour, source_colour(5));
}

TEST(RememberedSources, AUnitsSerialIsKeptOnAUnitLineAndRecalledWithItsName) {
  ViewSettings settings;
  SourceLook front = look_of("front", source_colour(1), {0.3, 0.0, 0.0, false});
  front.serial = "1111222233334444";
  remember_looks(settings, {front, look_of("rear", source_colour(2))});
  const std::string text = format_settings(settings);
  EXPECT_NE(text.find("\nunit = 1111222233334444; front\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("; rear\n"), std::string::npos) << "rear was never read, so it has no unit line";

  std::vector<std::string> notes;
  const ViewSettings read = parse_settings(text, &notes);
  EXPECT_TRUE(notes.empty());
  SourceLook recalled = look_of("front", source_colour(0));
  recall_look(read, {}, recalled, false);
  EXPECT_EQ(recalled.serial, "1111222233334444");
  EXPECT_EQ(recalled.pose, front.pose);

  // The unit renamed: its serial moves to the new name, and the old name is bound by name again.
  SourceLook renamed = look_of("left", source_colour(3));
  renamed.serial = front.serial;
  ViewSettings later = read;
  remember_looks(later, {renamed, look_of("rear", source_colour(2))});
  const std::string again = format_settings(later);
  EXPECT_NE(again.find("unit = 1111222233334444; left\n"), std::string::npos) << again;
  EXPECT_EQ(again.find("; front\n"), std::string::npos) << again;
}

TEST(RememberedSources, AFileWithoutUnitLinesBindsByNameAsBeforeAndAStrayUnitLineIsSaid) {
  std::vector<std::string> notes;
  const ViewSettings read =
      parse_settings("pose_convention = rep103\nsource = front; 0.3,0,0; #FF8800\nunit = 9999; ghost\n", &notes);
  ASSERT_EQ(read.sources.size(), 1u);
  EXPECT_TRUE(read.sources[0].serial.empty());
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0], "unit = 9999; ghost is left out: no source = line has the name 'ghost'");
}

}  // namespace
}  // namespace ydscope::ui

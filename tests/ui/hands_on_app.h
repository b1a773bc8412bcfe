#pragma once
// The fixture of the UI tests that type or point at the app: an Xvfb of the test's own (so its
// pointer and keys reach only its app, private_display.h) and a person's hands on it (x11_input.h).
// A machine without Xvfb skips the test, saying so.
#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>

#include "private_display.h"
#include "x11_input.h"

namespace ydscope::test {

class HandsOnApp : public testing::Test {
 protected:
  void SetUp() override {
    if (std::system("command -v Xvfb >/dev/null 2>&1") != 0) GTEST_SKIP() << "Xvfb is not installed";
    display_.emplace();  // before the hands: they open it
    ASSERT_TRUE(*display_) << "could not start an Xvfb of the test's own";
    hands_.emplace();
    ASSERT_TRUE(*hands_) << "cannot open the X display";
  }
  X11Hands& hands() { return *hands_; }

 private:
  std::optional<PrivateDisplay> display_;
  std::optional<X11Hands> hands_;  // declared after the display: closed before it goes
};

}  // namespace ydscope::test

// Issue 26: a warning that quotes a recording's metadata copied its bytes to the terminal, so a
// file could clear the screen or retitle the window through ydscope-cli's stderr. Every quote of
// file text goes through quote_file_text() (core/text/quoted_text.h).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/frame/pose.h"
#include "core/record/recording_metadata.h"
#include "core/text/quoted_text.h"

namespace ydscope {
namespace {

// No byte a terminal acts on: C0 controls, DEL, and the C1 CSI (raw, or inside its UTF-8).
bool terminal_safe(const std::string& text) {
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7F) return false;
  }
  return text.find('\x9b') == std::string::npos;  // CSI, raw or as the second byte of its UTF-8
}

TEST(QuotedText, ShowsControlBytesInsteadOfSendingThem) {
  EXPECT_EQ(quote_file_text("G6"), "'G6'");
  EXPECT_EQ(quote_file_text("\x1b]0;owned\x07\x1b[2J"), "'\\x1b]0;owned\\x07\\x1b[2J'");
  EXPECT_EQ(quote_file_text("a\nb\tc\\d\x7f"), "'a\\nb\\tc\\\\d\\x7f'");
  EXPECT_EQ(quote_file_text("\xc2\x9b"
                            "31m"),
            "'\\u009b31m'");  // C1 CSI as UTF-8
  EXPECT_EQ(quote_file_text("\x9b"
                            "31m"),
            "'\\x9b31m'");                                                               // and as a raw byte
  EXPECT_EQ(quote_file_text("caf\xc3\xa9 \xe2\x82\xac"), "'caf\xc3\xa9 \xe2\x82\xac'");  // text stays text
  const std::string huge(1 << 20, 'x');
  EXPECT_EQ(quote_file_text(huge), "'" + std::string(kMaxQuotedBytes, 'x') + "...' (1048576 bytes)");
}

TEST(QuotedText, EveryMetadataWarningQuotesThroughIt) {
  const std::string esc = "\x1b[2J\x1b]0;owned\x07";
  std::vector<std::string> warnings;
  const auto metadata = RecordingMetadata::parse(
      "baud=" + esc + "\ndistance_scale=" + esc + "\npose=" + esc + "\n" + esc + "\nmodel=G6\n", &warnings);
  EXPECT_EQ(metadata.model, "G6");
  ASSERT_EQ(warnings.size(), 4u);
  const std::string shown = "'\\x1b[2J\\x1b]0;owned\\x07'";
  for (const std::string& warning : warnings) {
    EXPECT_TRUE(terminal_safe(warning)) << warning;
    EXPECT_NE(warning.find(shown), std::string::npos) << warning;
  }
  EXPECT_EQ(warnings[0], "metadata baud=" + shown + " is not a whole number; ignored");
  std::string error;
  EXPECT_FALSE(parse_pose("1,2,\x1b[2J", error));
  EXPECT_TRUE(terminal_safe(error)) << error;
}

}  // namespace
}  // namespace ydscope

// Names shown on a terminal cannot act on it.
#include <gtest/gtest.h>

#include <feran/core/text.hpp>

namespace feran::test_text {
namespace {

TEST(Printable, ControlCharactersBecomeVisible) {
  EXPECT_EQ(printable("bearing 1"), "bearing 1");
  EXPECT_EQ(printable("red\x1b[31mtext"), "red\\e[31mtext");
  EXPECT_EQ(printable("a\nb\tc\rd"), "a\\nb\\tc\\rd");
  EXPECT_EQ(printable(std::string("nul\0bel\a del\x7f", 13)), "nul\\x00bel\\x07 del\\x7f");
  // C1 controls in UTF-8 (U+009B is a one-character CSI to some terminals); other
  // non-ASCII text stays as it is.
  EXPECT_EQ(printable("csi\xc2\x9b"
                      "31m"),
            "csi\\u009b31m");
  EXPECT_EQ(printable("Lager \xc3\xa4 \xc2\xb5m"), "Lager \xc3\xa4 \xc2\xb5m");
  // Messages of several lines keep their lines, and nothing else.
  EXPECT_EQ(printable("line 1\nline\x1b 2", true), "line 1\nline\\e 2");
  // Idempotent: printing a printed text again changes nothing.
  const std::string once = printable("x\x1by\n\xc2\x85z");
  EXPECT_EQ(printable(once), once);
}

}  // namespace
}  // namespace feran::test_text

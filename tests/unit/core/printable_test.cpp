// printable(): a user's text as a message quotes it, one line of valid UTF-8 -
// control characters and bytes that are not UTF-8 escaped (\xNN), well-formed
// characters of any length kept, a cut never splitting a character.

#include <string>

#include <gtest/gtest.h>

#include "stockbridge/core/error.hpp"

namespace stockbridge {
namespace {

TEST(Printable, ControlCharactersAreEscapes) {
  EXPECT_EQ(printable("a\nb\rc\td"), "a\\nb\\rc\\td");
  EXPECT_EQ(printable("\x1b[31m\x7f"), "\\x1b[31m\\x7f");
  EXPECT_EQ(printable("plain text"), "plain text");
}

TEST(Printable, WellFormedCharactersOfEveryLengthAreKept) {
  EXPECT_EQ(printable("caf\xC3\xA9"), "caf\xC3\xA9");                  // U+00E9, two bytes
  EXPECT_EQ(printable("\xE2\x82\xAC 5"), "\xE2\x82\xAC 5");            // U+20AC, three
  EXPECT_EQ(printable("\xF0\x9F\x98\x80"), "\xF0\x9F\x98\x80");        // U+1F600, four
  EXPECT_EQ(printable("\xF4\x8F\xBF\xBF"), "\xF4\x8F\xBF\xBF");        // U+10FFFF, the last
  EXPECT_EQ(printable("\xED\x9F\xBF"), "\xED\x9F\xBF");                // U+D7FF, below the surrogates
}

TEST(Printable, BytesThatAreNotUtf8AreEscaped) {
  EXPECT_EQ(printable("ab\xFF"), "ab\\xff");
  EXPECT_EQ(printable("\x80x"), "\\x80x");                     // a stray continuation byte
  EXPECT_EQ(printable("caf\xE9"), "caf\\xe9");                 // Latin-1's e-acute
  EXPECT_EQ(printable("\xC3"), "\\xc3");                       // a sequence cut short by the end
  EXPECT_EQ(printable("\xC3x"), "\\xc3x");                     // ... or by a byte that does not continue it
  EXPECT_EQ(printable("\xE2\x82"), "\\xe2\\x82");
}

// Overlong forms (a character in more bytes than it needs: '/' as C0 AF), UTF-16's
// surrogates (U+D800 to U+DFFF, as CESU-8 writes them) and code points beyond
// U+10FFFF are not UTF-8: every byte escaped.
TEST(Printable, OverlongFormsSurrogatesAndCodePointsBeyondUnicodeAreEscaped) {
  EXPECT_EQ(printable("\xC0\xAF"), "\\xc0\\xaf");
  EXPECT_EQ(printable("\xC1\xBF"), "\\xc1\\xbf");
  EXPECT_EQ(printable("\xE0\x80\xAF"), "\\xe0\\x80\\xaf");
  EXPECT_EQ(printable("\xE0\x9F\xBF"), "\\xe0\\x9f\\xbf");    // U+07FF in three bytes
  EXPECT_EQ(printable("\xF0\x80\x80\xAF"), "\\xf0\\x80\\x80\\xaf");
  EXPECT_EQ(printable("\xF0\x8F\xBF\xBF"), "\\xf0\\x8f\\xbf\\xbf");  // U+FFFF in four bytes
  EXPECT_EQ(printable("\xED\xA0\x80"), "\\xed\\xa0\\x80");    // U+D800
  EXPECT_EQ(printable("\xED\xBF\xBF"), "\\xed\\xbf\\xbf");    // U+DFFF
  EXPECT_EQ(printable("\xF4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80");  // U+110000
  EXPECT_EQ(printable("\xF5\x80\x80\x80"), "\\xf5\\x80\\x80\\x80");
}

// max_bytes counts the text's own bytes; a character that would pass it is left
// out whole, and "..." says something was.
TEST(Printable, ACutNeverSplitsACharacter) {
  EXPECT_EQ(printable("abcdef", 4), "abcd...");
  EXPECT_EQ(printable("abcd", 4), "abcd");
  EXPECT_EQ(printable("a\xC3\xA9", 2), "a...");                 // the 2-byte e-acute would end at byte 3
  EXPECT_EQ(printable("a\xC3\xA9", 3), "a\xC3\xA9");
  EXPECT_EQ(printable("a\xC3\xA9" "b", 3), "a\xC3\xA9...");
  EXPECT_EQ(printable("ab\xF0\x9F\x98\x80", 5), "ab...");       // the 4-byte emoji would end at byte 6
  EXPECT_EQ(printable("ab\xF0\x9F\x98\x80", 6), "ab\xF0\x9F\x98\x80");
  EXPECT_EQ(printable("\xFF\xFF\xFF", 2), "\\xff\\xff...");     // escaped bytes count as one each
  const std::string long_text(100, 'x');
  EXPECT_EQ(printable(long_text), std::string(60, 'x') + "...");  // 60 bytes by default
}

}  // namespace
}  // namespace stockbridge

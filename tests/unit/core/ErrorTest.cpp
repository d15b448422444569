// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <string>

namespace mpm {
namespace {

TEST(EscapeBytes, KeepsPrintableAsciiAndValidUtf8) {
    const std::string text = "phi = 30\xc2\xb0, \xce\xbc(I), \xce\xbe < r_p, \xe2\x80\x94 "
                             "\xf0\x9f\x98\x80\nnext\tline";
    EXPECT_EQ(escapeBytes(text), text);
    EXPECT_EQ(escapeBytes(""), "");
}

TEST(EscapeBytes, EscapesControlAndInvalidBytes) {
    EXPECT_EQ(escapeBytes(std::string("a\xff"
                                      "b")),
              "a\\xffb");
    EXPECT_EQ(escapeBytes(std::string("\x1b[31mred\r\x7f\x01", 11)), "\\x1b[31mred\\x0d\\x7f\\x01");
    EXPECT_EQ(escapeBytes(std::string("nul\0end", 7)), "nul\\x00end");
    // C1 control U+009B (a terminal's CSI) is valid UTF-8 but not printable.
    EXPECT_EQ(escapeBytes("x\xc2\x9b"
                          "y"),
              "x\\xc2\\x9by");
    // Overlong '/', a surrogate, above U+10FFFF, a stray continuation, truncated sequences.
    EXPECT_EQ(escapeBytes("\xc0\xaf"), "\\xc0\\xaf");
    EXPECT_EQ(escapeBytes("\xed\xa0\x80"), "\\xed\\xa0\\x80");
    EXPECT_EQ(escapeBytes("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80");
    EXPECT_EQ(escapeBytes("\x80"
                          "a"),
              "\\x80a");
    EXPECT_EQ(escapeBytes("\xce"), "\\xce");
    EXPECT_EQ(escapeBytes("\xe2\x80"
                          "a"),
              "\\xe2\\x80a");
    // A valid character right after an invalid byte survives.
    EXPECT_EQ(escapeBytes("\xff\xc2\xb0"), "\\xff\xc2\xb0");
}

TEST(EscapeBytes, IsIdempotent) {
    const std::string once = escapeBytes("k\xff\x01\xc2\x9b\xce\xbc\\x41");
    EXPECT_EQ(escapeBytes(once), once);
}

TEST(InputError, WhatIsEscapedFileAndKeyAreNot) {
    const InputError e("constant/mat\xff", 3, "rho\x01", "expected a number, got '\x1b\xfe'");
    EXPECT_STREQ(e.what(), "constant/mat\\xff:3: key 'rho\\x01': expected a number, got "
                           "'\\x1b\\xfe'");
    EXPECT_EQ(e.file(), "constant/mat\xff");
    EXPECT_EQ(e.key(), "rho\x01");
}

} // namespace
} // namespace mpm

// The number and byte scanners every text reader shares, against expectations built
// independently of them: hand-written values, and the C library's strtoll / strtoull.
#include <gtest/gtest.h>

#include <cerrno>
#include <cstdlib>
#include <random>
#include <string>

#include "mesh/text_scan.hpp"

namespace convray::mesh {
namespace {

// What parse_integer promises, through strtoll: an optional single sign, then only digits,
// and a value within int64_t.
bool expected_integer(const std::string& token, int64_t& value) {
  size_t digits_from = !token.empty() && (token[0] == '+' || token[0] == '-') ? 1 : 0;
  if (token.size() == digits_from) return false;
  for (size_t k = digits_from; k < token.size(); ++k)
    if (token[k] < '0' || token[k] > '9') return false;
  errno = 0;
  const long long parsed = std::strtoll(token.c_str(), nullptr, 10);
  if (errno == ERANGE) return false;
  value = parsed;
  return true;
}

bool expected_digits(const std::string& token, uint64_t& value) {
  if (token.empty()) return false;
  for (char c : token)
    if (c < '0' || c > '9') return false;
  errno = 0;
  const unsigned long long parsed = std::strtoull(token.c_str(), nullptr, 10);
  if (errno == ERANGE) return false;
  value = parsed;
  return true;
}

void expect_integer_as_expected(const std::string& token) {
  int64_t expected = 0, parsed = 0;
  const bool expected_ok = expected_integer(token, expected);
  ASSERT_EQ(parse_integer(token, parsed), expected_ok) << "'" << token << "'";
  if (expected_ok) EXPECT_EQ(parsed, expected) << "'" << token << "'";
  uint64_t expected_unsigned = 0, parsed_unsigned = 0;
  const bool digits_ok = expected_digits(token, expected_unsigned);
  ASSERT_EQ(parse_digits(token, parsed_unsigned), digits_ok) << "'" << token << "'";
  if (digits_ok) EXPECT_EQ(parsed_unsigned, expected_unsigned) << "'" << token << "'";
}

TEST(TextScan, IntegersByHand) {
  int64_t v = 0;
  EXPECT_TRUE(parse_integer("0", v) && v == 0);
  EXPECT_TRUE(parse_integer("-0", v) && v == 0);
  EXPECT_TRUE(parse_integer("+17", v) && v == 17);
  EXPECT_TRUE(parse_integer("-17", v) && v == -17);
  EXPECT_TRUE(parse_integer("007", v) && v == 7);
  EXPECT_TRUE(parse_integer("999999999999999999", v) && v == 999999999999999999);     // 18 digits
  EXPECT_TRUE(parse_integer("-999999999999999999", v) && v == -999999999999999999);
  EXPECT_TRUE(parse_integer("9223372036854775807", v) && v == INT64_MAX);
  EXPECT_TRUE(parse_integer("-9223372036854775808", v) && v == INT64_MIN);
  EXPECT_TRUE(parse_integer("0000000000000000000000042", v) && v == 42);             // 25 digits
  for (const char* refused : {"", "+", "-", "++1", "+-1", "-+1", "--1", "1.0", "1e2", " 1", "1 ", "0x10", "1a",
                              "9223372036854775808", "-9223372036854775809", "99999999999999999999", "nan", "\t"})
    EXPECT_FALSE(parse_integer(refused, v)) << "'" << refused << "'";
  uint64_t u = 0;
  EXPECT_TRUE(parse_digits("18446744073709551615", u) && u == UINT64_MAX);
  EXPECT_FALSE(parse_digits("18446744073709551616", u));
  EXPECT_FALSE(parse_digits("+1", u));
  EXPECT_FALSE(parse_digits("-1", u));
}

TEST(TextScan, RandomIntegersAsTheCLibraryReadsThem) {
  std::mt19937_64 random(12345);
  const std::string alphabet = "0123456789+-.e x";
  for (int trial = 0; trial < 200000; ++trial) {
    std::string token;
    const int length = static_cast<int>(random() % 24);
    const bool only_digits = random() % 2 == 0;
    for (int k = 0; k < length; ++k) {
      if (only_digits) token += static_cast<char>('0' + random() % 10);
      else token += alphabet[random() % alphabet.size()];
    }
    if (only_digits && random() % 2 == 0) token.insert(token.begin(), random() % 2 ? '-' : '+');
    expect_integer_as_expected(token);
    if (testing::Test::HasFatalFailure()) return;
  }
}

TEST(TextScan, EveryLengthAroundTheLimitsOfSixtyFourBits) {
  // Lengths 1..22 of nines, and the extremes of int64_t and uint64_t give or take one.
  std::string nines;
  for (int k = 0; k < 22; ++k) {
    nines += '9';
    expect_integer_as_expected(nines);
    expect_integer_as_expected("-" + nines);
    expect_integer_as_expected("1" + std::string(k, '0'));
  }
  for (const char* edge : {"9223372036854775806", "9223372036854775807", "9223372036854775808",
                           "-9223372036854775807", "-9223372036854775808", "-9223372036854775809",
                           "18446744073709551614", "18446744073709551615", "18446744073709551616"})
    expect_integer_as_expected(edge);
}

}  // namespace
}  // namespace convray::mesh

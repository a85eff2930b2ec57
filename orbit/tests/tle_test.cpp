// The TLE parser: fields read from their columns (expected values read off the lines by hand), and each
// kind of malformed line refused with an error naming its line and column.
#include <gtest/gtest.h>

#include <string>

#include "orbit/tle.hpp"

namespace {

// Satellite 00005 (Vanguard 1) of the SGP4 verification set (Vallado et al. 2006, SGP4-VER.TLE).
const std::string kLine1 = "1 00005U 58002B   00179.78495062  .00000023  00000-0  28098-4 0  4753";
const std::string kLine2 = "2 00005  34.2682 348.7242 1859667 331.7664  19.3264 10.82419157413667";
// A deep-space set of the same file (08195, Molniya, 2.005 rev/day).
const std::string kDeep1 = "1 08195U 75081A   06176.33215444  .00000099  00000-0  11873-3 0   813";
const std::string kDeep2 = "2 08195  64.1586 279.0717 6877146 264.7651  20.2257  2.00491383225656";

// The line with column `column` (1-based) replaced and the checksum recomputed, so that only the
// intended fault is left.
std::string with(std::string line, int column, char ch) {
    line[static_cast<std::size_t>(column - 1)] = ch;
    line[68] = static_cast<char>('0' + orbit::tle_checksum(line));
    return line;
}

// Runs the parser and returns the error's line and column (or {0, 0} when it parses).
std::pair<int, int> error_at(const std::string& l1, const std::string& l2) {
    try {
        orbit::parse_tle(l1, l2);
    } catch (const orbit::TleError& e) {
        return {e.line(), e.column()};
    }
    return {0, 0};
}

TEST(Tle, ReadsEveryFieldFromItsColumns) {
    const orbit::Tle t = orbit::parse_tle(kLine1, kLine2);
    EXPECT_EQ(t.catalog_number, 5);
    EXPECT_EQ(t.epoch_year, 2000);
    EXPECT_DOUBLE_EQ(t.epoch_day, 179.78495062);
    // 2000-01-01 00:00 UTC is JD 2451544.5; day 179.78495062 is 178.78495062 days later.
    EXPECT_NEAR(t.epoch_jd_utc, 2451544.5 + 178.78495062, 1e-8);
    EXPECT_DOUBLE_EQ(t.inclination_deg, 34.2682);
    EXPECT_DOUBLE_EQ(t.raan_deg, 348.7242);
    EXPECT_DOUBLE_EQ(t.eccentricity, 0.1859667);
    EXPECT_DOUBLE_EQ(t.arg_perigee_deg, 331.7664);
    EXPECT_DOUBLE_EQ(t.mean_anomaly_deg, 19.3264);
    EXPECT_DOUBLE_EQ(t.mean_motion_rev_per_day, 10.82419157);
    EXPECT_DOUBLE_EQ(t.bstar_per_earth_radius, 0.28098e-4);
}

TEST(Tle, ConvertsToSgp4Units) {
    const orbit::MeanElements<double> e = orbit::parse_tle(kLine1, kLine2).mean_elements<double>();
    constexpr double pi = 3.14159265358979323846;
    EXPECT_NEAR(e.mean_motion_rad_per_min, 10.82419157 * 2.0 * pi / 1440.0, 1e-15);
    EXPECT_NEAR(e.inclination_rad, 34.2682 * pi / 180.0, 1e-15);
    EXPECT_NEAR(e.bstar_per_earth_radius, 2.8098e-5, 1e-18);
}

TEST(Tle, TwoDigitYearsFollowNoradsConvention) {
    // 57-99 are 19xx, 00-56 are 20xx.
    EXPECT_EQ(orbit::parse_tle(with(with(kLine1, 19, '5'), 20, '7'), kLine2).epoch_year, 1957);
    EXPECT_EQ(orbit::parse_tle(with(with(kLine1, 19, '5'), 20, '6'), kLine2).epoch_year, 2056);
}

TEST(Tle, Alpha5CatalogNumbers) {
    // "A0005" is 100005; "J0005" is 180005 (I is skipped); "P0005" is 230005 (I and O skipped).
    const auto catalog = [](char letter) {
        return orbit::parse_tle(with(kLine1, 3, letter), with(kLine2, 3, letter)).catalog_number;
    };
    EXPECT_EQ(catalog('A'), 100005);
    EXPECT_EQ(catalog('J'), 180005);
    EXPECT_EQ(catalog('P'), 230005);
    EXPECT_EQ(error_at(with(kLine1, 3, 'I'), with(kLine2, 3, 'I')), std::make_pair(1, 3));
}

TEST(Tle, TrailingBlanksAndCarriageReturnAreAllowed) {
    EXPECT_NO_THROW(orbit::parse_tle(kLine1 + "  \r", kLine2 + "\r\n"));
}

TEST(Tle, ChecksumMismatchNamesLineAndColumn69) {
    std::string bad = kLine2;
    bad[68] = bad[68] == '9' ? '0' : static_cast<char>(bad[68] + 1);
    try {
        orbit::parse_tle(kLine1, bad);
        FAIL() << "a wrong checksum was accepted";
    } catch (const orbit::TleError& e) {
        EXPECT_EQ(e.line(), 2);
        EXPECT_EQ(e.column(), 69);
        EXPECT_NE(std::string(e.what()).find("checksum"), std::string::npos) << e.what();
    }
    // An altered digit without a new checksum: the checksum catches it.
    std::string typo = kLine1;
    typo[30] = '9';
    EXPECT_EQ(error_at(typo, kLine2), std::make_pair(1, 69));
}

TEST(Tle, RefusesEachMalformedField) {
    EXPECT_EQ(error_at(kLine2, kLine1), std::make_pair(1, 1));                                 // swapped lines
    EXPECT_EQ(error_at(kLine1.substr(0, 60), kLine2), std::make_pair(1, 61));                  // truncated
    EXPECT_EQ(error_at(kLine1 + "x", kLine2), std::make_pair(1, 70));                          // too long
    EXPECT_EQ(error_at(with(kLine1, 18, '1'), kLine2), std::make_pair(1, 18));                 // a blank column filled
    EXPECT_EQ(error_at(kLine1, with(kLine2, 7, '6')), std::make_pair(2, 3));                   // catalog numbers differ
    EXPECT_EQ(error_at(with(kLine1, 25, 'x'), kLine2), std::make_pair(1, 21));                 // epoch day not a number
    EXPECT_EQ(error_at(kLine1, with(kLine2, 30, 'e')), std::make_pair(2, 30));                 // eccentricity digit
    EXPECT_EQ(error_at(with(kLine1, 61, '?'), kLine2), std::make_pair(1, 61));                 // B* exponent
    EXPECT_EQ(error_at(kLine1, with(kLine2, 9, '2')), std::make_pair(2, 9));                   // inclination 234 deg
    EXPECT_EQ(error_at(with(kLine1, 21, '0'), kLine2), std::make_pair(0, 0));                  // day 079 is fine...
    EXPECT_EQ(error_at(with(with(kLine1, 21, '3'), 22, '9'), kLine2), std::make_pair(1, 21));  // ...day 399 not
}

// Issue 38: a character beyond ASCII is reported at its own column, not at a byte count (a UTF-8 minus
// sign, three bytes, in column 54 made a 69-character line 71 bytes long, refused as "text after column 69").
TEST(Tle, NonAsciiCharacterIsReportedAtItsColumn) {
    std::string line = kLine1;
    line.replace(53, 1, "\xE2\x88\x92");  // U+2212 MINUS SIGN in place of the blank at column 54
    EXPECT_EQ(error_at(line, kLine2), std::make_pair(1, 54));
    std::string last = kLine2;
    last.replace(68, 1, "\xC3\xA9");  // a two-byte letter as the checksum, column 69
    EXPECT_EQ(error_at(kLine1, last), std::make_pair(2, 69));
    try {
        orbit::parse_tle(line, kLine2);
    } catch (const orbit::TleError& e) {
        EXPECT_NE(std::string(e.what()).find("non-ASCII"), std::string::npos) << e.what();
    }
}

TEST(Tle, DeepSpaceSetIsRefusedNamingSdp4) {
    try {
        orbit::parse_tle(kDeep1, kDeep2);
        FAIL() << "a deep-space set was accepted";
    } catch (const orbit::TleError& e) {
        EXPECT_EQ(e.line(), 2);
        EXPECT_EQ(e.column(), 53);
        EXPECT_NE(std::string(e.what()).find("SDP4"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("225"), std::string::npos) << e.what();
    }
}

TEST(Tle, ErrorIsAnInvalidArgument) {
    EXPECT_THROW(orbit::parse_tle("", kLine2), std::invalid_argument);
}

}  // namespace

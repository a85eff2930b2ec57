#include "orbit/tle.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>

#include "orbit/calendar.hpp"

namespace orbit {

namespace {

constexpr std::size_t kLineLength = 69;

std::string located(int line, int column, const std::string& reason) {
    std::string where = "TLE line " + std::to_string(line);
    if (column > 0) where += ", column " + std::to_string(column);
    return where + ": " + reason;
}

// One line of the set: its text and number, with column-addressed field readers that throw TleError.
class Line {
public:
    Line(std::string_view text, int number) : text_(text), number_(number) {
        // A TLE is ASCII. A character beyond it (a pasted minus sign, a UTF-8 letter) is refused first, at
        // its own column: counted in bytes, a two-byte character makes a 69-column line 70 long.
        for (std::size_t i = 0; i < text_.size(); ++i) {
            const auto byte = static_cast<unsigned char>(text_[i]);
            if (byte < 0x80) continue;
            char hex[8];
            std::snprintf(hex, sizeof hex, "0x%02X", byte);
            // Every byte before this one is ASCII: one byte, one character, so its column is i + 1.
            fail(static_cast<int>(i) + 1, std::string("a non-ASCII character (first byte ") + hex +
                                              "); a TLE line holds ASCII only (a pasted dash or quote?)");
        }
        // Trailing blanks and a carriage return (a file from another system) are allowed past column 69.
        std::size_t end = text_.size();
        while (end > 0 && (text_[end - 1] == ' ' || text_[end - 1] == '\r' || text_[end - 1] == '\n')) --end;
        if (end < kLineLength) {
            fail(static_cast<int>(end) + 1, "the line ends after " + std::to_string(end) +
                                                " columns; a TLE line has 69 (a truncated or wrapped line?)");
        }
        if (end > kLineLength) fail(70, "text after column 69; a TLE line has 69 columns");
        text_ = text_.substr(0, kLineLength);
        if (text_[0] != static_cast<char>('0' + number_)) {
            fail(1, std::string("line number '") + text_[0] + "', expected '" + std::to_string(number_) +
                        "' (are the two lines swapped?)");
        }
    }

    [[noreturn]] void fail(int column, const std::string& reason) const { throw TleError(number_, column, reason); }

    // Columns first..last (1-based, inclusive).
    std::string_view field(int first, int last) const {
        return text_.substr(static_cast<std::size_t>(first - 1), static_cast<std::size_t>(last - first + 1));
    }
    char at(int column) const { return text_[static_cast<std::size_t>(column - 1)]; }

    void blank(int column) const {
        if (at(column) != ' ') fail(column, std::string("'") + at(column) + "' where the format has a blank");
    }

    // A decimal number in columns first..last, blanks around it allowed, e.g. " 98.7300" or "-.00000054".
    double number(int first, int last, const char* what) const {
        std::string_view f = field(first, last);
        while (!f.empty() && f.front() == ' ') f.remove_prefix(1);
        while (!f.empty() && f.back() == ' ') f.remove_suffix(1);
        std::string s(f);
        if (!s.empty() && s.front() == '+') s.erase(0, 1);
        // from_chars wants a digit before the point: ".00000054" and "-.00000054" are the format's.
        if (!s.empty() && s.front() == '.') s.insert(0, "0");
        if (s.size() >= 2 && s[0] == '-' && s[1] == '.') s.insert(1, "0");
        double value = 0.0;
        const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value, std::chars_format::fixed);
        if (s.empty() || ec != std::errc() || end != s.data() + s.size()) {
            fail(first, std::string(what) + " '" + std::string(field(first, last)) + "' (columns " +
                            std::to_string(first) + "-" + std::to_string(last) + ") is not a number");
        }
        return value;
    }

    // Digits only (leading blanks allowed), e.g. the eccentricity's "0001234" or a catalog number.
    long digits(int first, int last, const char* what) const {
        long value = 0;
        bool any = false;
        for (int c = first; c <= last; ++c) {
            const char ch = at(c);
            if (ch == ' ' && !any) continue;
            if (ch < '0' || ch > '9') fail(c, std::string(what) + ": '" + ch + "' is not a digit");
            value = value * 10 + (ch - '0');
            any = true;
        }
        if (!any) fail(first, std::string(what) + " is blank");
        return value;
    }

    // The exponent notation with an implied leading decimal point, 8 columns: " 12345-4" is 0.12345e-4.
    double implied_decimal(int first, const char* what) const {
        const char sign = at(first);
        if (sign != ' ' && sign != '+' && sign != '-') fail(first, std::string(what) + ": sign '" + sign + "'");
        double mantissa = 0.0;
        for (int c = first + 1; c <= first + 5; ++c) {
            const char ch = at(c);
            if (ch == ' ') continue;  // some producers blank-pad a zero mantissa
            if (ch < '0' || ch > '9') fail(c, std::string(what) + ": '" + ch + "' is not a digit");
            mantissa = mantissa * 10.0 + (ch - '0');
        }
        mantissa /= 1.0e5;
        const char exp_sign = at(first + 6);
        if (exp_sign != '+' && exp_sign != '-' && exp_sign != ' ') {
            fail(first + 6, std::string(what) + ": exponent sign '" + exp_sign + "'");
        }
        const char exp_digit = at(first + 7);
        if (exp_digit < '0' || exp_digit > '9') fail(first + 7, std::string(what) + ": exponent '" + exp_digit + "'");
        const int exponent = (exp_sign == '-' ? -1 : 1) * (exp_digit - '0');
        return (sign == '-' ? -1.0 : 1.0) * mantissa * std::pow(10.0, exponent);
    }

    // Columns 3-7: five digits, or Alpha-5 (a letter for the ten-thousands, I and O left out).
    int catalog_number() const {
        const char first = at(3);
        int high = 0;
        if (first >= '0' && first <= '9') {
            high = first - '0';
        } else if (first >= 'A' && first <= 'Z' && first != 'I' && first != 'O') {
            high = 10 + (first - 'A') - (first > 'I' ? 1 : 0) - (first > 'O' ? 1 : 0);
        } else if (first != ' ') {
            fail(3, std::string("catalog number: '") + first + "' is neither a digit nor an Alpha-5 letter");
        }
        return high * 10000 + static_cast<int>(digits(4, 7, "catalog number"));
    }

    void check_checksum() const {
        const char ch = at(69);
        if (ch < '0' || ch > '9') fail(69, std::string("checksum '") + ch + "' is not a digit");
        const int expected = tle_checksum(text_);
        if (ch - '0' != expected) {
            fail(69, std::string("checksum ") + ch + " does not match the modulo-10 sum " + std::to_string(expected) +
                         " of columns 1-68 (a mistyped or altered line?)");
        }
    }

    void check_range(double value, double low, double high, int column, const char* what) const {
        if (!(value >= low && value <= high)) {
            fail(column, std::string(what) + " " + std::to_string(value) + " outside [" + std::to_string(low) + ", " +
                             std::to_string(high) + "]");
        }
    }

private:
    std::string_view text_;
    int number_;
};

bool is_leap_year(int y) {
    return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
}

}  // namespace

TleError::TleError(int line, int column, const std::string& reason)
    : std::invalid_argument(located(line, column, reason)), line_(line), column_(column) {}

int tle_checksum(std::string_view line) {
    int sum = 0;
    for (std::size_t i = 0; i < line.size() && i < kLineLength - 1; ++i) {
        const char ch = line[i];
        if (ch >= '0' && ch <= '9') sum += ch - '0';
        if (ch == '-') sum += 1;
    }
    return sum % 10;
}

TleElementsError::TleElementsError(int element, const std::string& reason)
    : std::invalid_argument(element > 0 ? "[" + std::to_string(element) + "] " + reason : reason), element_(element) {}

Tle checked_tle_from_elements(const TleElements& e) {
    static constexpr const char* names[kTleElementCount] = {
        "epoch (Julian date, UTC)",          "mean motion (rev/day)",     "eccentricity",       "inclination (deg)",
        "right ascension of the node (deg)", "argument of perigee (deg)", "mean anomaly (deg)", "B* (1/Earth radii)"};
    auto fail = [&](std::size_t k, const std::string& reason) -> void {
        throw TleElementsError(static_cast<int>(k + 1),
                               std::string(names[k]) + " " + std::to_string(e[k]) + " " + reason);
    };
    for (std::size_t k = 0; k < kTleElementCount; ++k)
        if (!std::isfinite(e[k])) fail(k, "is not a finite number");
    // The text's two-digit years: 1957-01-01 to 2056-12-31.
    const double first = julian_date_at_midnight(1957, 1, 1), last = julian_date_at_midnight(2057, 1, 1);
    if (!(e[0] >= first && e[0] < last))
        fail(0, "outside the element sets' years 1957-2056 (JD " + std::to_string(first) + " to " +
                    std::to_string(last) + ")");
    if (!(e[1] > 0.0)) fail(1, "must be positive (revolutions per day)");
    if (!(e[2] >= 0.0 && e[2] < 1.0)) fail(2, "outside [0, 1)");
    if (!(e[3] >= 0.0 && e[3] <= 180.0)) fail(3, "outside [0, 180]");
    for (std::size_t k = 4; k <= 6; ++k)
        if (!(e[k] >= 0.0 && e[k] <= 360.0)) fail(k, "outside [0, 360]");
    const Tle tle = tle_from_elements(e);
    Sgp4<double> sgp4;
    const Sgp4Status status = sgp4.initialize(tle.mean_elements<double>());
    if (status == Sgp4Status::deep_space)
        fail(1, "is a period of " + std::to_string(sgp4.period_minutes()) +
                    " min >= 225 min: a deep-space element set, which needs SDP4 (not implemented; near-Earth sets "
                    "only)");
    if (status != Sgp4Status::ok)
        throw TleElementsError(0, std::string("SGP4 cannot start from this set: ") + describe(status));
    return tle;
}

Tle parse_tle(std::string_view line1_text, std::string_view line2_text) {
    const Line l1(line1_text, 1);
    const Line l2(line2_text, 2);
    for (int c : {2, 9, 18, 33, 44, 53, 62, 64}) l1.blank(c);
    for (int c : {2, 8, 17, 26, 34, 43, 52}) l2.blank(c);
    l1.check_checksum();
    l2.check_checksum();

    Tle tle;
    tle.catalog_number = l1.catalog_number();
    const int catalog2 = l2.catalog_number();
    if (catalog2 != tle.catalog_number) {
        l2.fail(3, "catalog number " + std::to_string(catalog2) + " differs from line 1's " +
                       std::to_string(tle.catalog_number) + " (lines of two different sets?)");
    }

    // Epoch: two-digit year (57-99 are 19xx, as NORAD's convention), day of year with fraction.
    const int yy = static_cast<int>(l1.digits(19, 20, "epoch year"));
    tle.epoch_year = yy < 57 ? 2000 + yy : 1900 + yy;
    tle.epoch_day = l1.number(21, 32, "epoch day");
    const double days_in_year = is_leap_year(tle.epoch_year) ? 366.0 : 365.0;
    if (!(tle.epoch_day >= 1.0 && tle.epoch_day < days_in_year + 1.0)) {
        l1.fail(21, "epoch day " + std::to_string(tle.epoch_day) + " outside [1, " +
                        std::to_string(days_in_year + 1.0) + ") of year " + std::to_string(tle.epoch_year));
    }
    tle.epoch_jd_utc = julian_date_at_midnight(tle.epoch_year, 1, 1) + (tle.epoch_day - 1.0);
    // The mean motion's derivatives are read for validation only: SGP4 does not use them.
    l1.number(34, 43, "first derivative of the mean motion");
    l1.implied_decimal(45, "second derivative of the mean motion");
    tle.bstar_per_earth_radius = l1.implied_decimal(54, "B*");

    tle.inclination_deg = l2.number(9, 16, "inclination");
    l2.check_range(tle.inclination_deg, 0.0, 180.0, 9, "inclination (deg)");
    tle.raan_deg = l2.number(18, 25, "right ascension of the ascending node");
    l2.check_range(tle.raan_deg, 0.0, 360.0, 18, "right ascension of the ascending node (deg)");
    tle.eccentricity = static_cast<double>(l2.digits(27, 33, "eccentricity")) * 1.0e-7;
    tle.arg_perigee_deg = l2.number(35, 42, "argument of perigee");
    l2.check_range(tle.arg_perigee_deg, 0.0, 360.0, 35, "argument of perigee (deg)");
    tle.mean_anomaly_deg = l2.number(44, 51, "mean anomaly");
    l2.check_range(tle.mean_anomaly_deg, 0.0, 360.0, 44, "mean anomaly (deg)");
    tle.mean_motion_rev_per_day = l2.number(53, 63, "mean motion");
    if (!(tle.mean_motion_rev_per_day > 0.0)) l2.fail(53, "mean motion must be positive (revolutions per day)");
    l2.digits(64, 68, "revolution number");

    // Can SGP4 start from it? Deep space (SDP4) and an epoch state below the surface are refused here.
    Sgp4<double> sgp4;
    const Sgp4Status status = sgp4.initialize(tle.mean_elements<double>());
    if (status == Sgp4Status::deep_space) {
        l2.fail(53, "mean motion " + std::to_string(tle.mean_motion_rev_per_day) + " rev/day is a period of " +
                        std::to_string(sgp4.period_minutes()) +
                        " min >= 225 min: a deep-space element set, which needs SDP4 (not implemented; "
                        "near-Earth sets only)");
    }
    if (status != Sgp4Status::ok) l2.fail(0, std::string("SGP4 cannot start from this set: ") + describe(status));
    return tle;
}

}  // namespace orbit

// Values as text on the command line and in CSV: strict parsing (the whole text must be a number)
// and round-trip formatting of Reals.
#pragma once

#include <string>
#include <string_view>

namespace cosim {

double parse_real(std::string_view text, const std::string& what);
int parse_integer(std::string_view text, const std::string& what);
bool parse_boolean(std::string_view text, const std::string& what);
std::string format_real(double x);

}  // namespace cosim

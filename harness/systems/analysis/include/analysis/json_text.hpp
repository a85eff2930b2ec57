// JSON text for what the C API hands out as JSON (a run's measures, a campaign's aims): a number (null when
// not finite, as JSON has no NaN) and a quoted string with its quotes, backslashes and control characters
// escaped.
#pragma once

#include <string>

namespace analysis {

std::string json_number(double x);
std::string json_string(const std::string& text);

}  // namespace analysis

// Values as text on the command line and in CSV: strict parsing (the whole text must be a number)
// and round-trip formatting of Reals.
#pragma once

#include <string>
#include <string_view>

#include "fmi_loader/model_description.hpp"

namespace cosim {

double parse_real(std::string_view text, const std::string& what);
int parse_integer(std::string_view text, const std::string& what);
bool parse_boolean(std::string_view text, const std::string& what);
// An Enumeration's value from an item name of its declared type ("cones") or an item's number ("3"):
// the master accepts either wherever it takes text (--set, .ssd ssv:Enumeration, ssv:String and
// ssv:Integer bindings). Refuses anything that is not an item, naming the items.
int parse_enumeration(const fmi_loader::ModelDescription& md, const fmi_loader::ScalarVariable& v,
                      std::string_view text, const std::string& what);
std::string format_real(double x);
// Refuses a number the variable cannot hold, naming `what` (the variable and who gave the value): a Real
// that is not finite; an Integer that is not a whole 32-bit number; an Enumeration that is not one of
// its items; a Boolean other than 0 or 1; any value outside the variable's declared min/max. For values
// that arrive as doubles (a callback component's outputs, the C API's numbers): never coerced.
void check_value(const fmi_loader::ModelDescription& md, const fmi_loader::ScalarVariable& v, double x,
                 const std::string& what);

}  // namespace cosim

// The two kinds of failure a block or the runtime can raise. The C boundary turns them into
// fmi2Status: Discard for a request the FMU refuses but survives (the standard's fmi2Discard),
// Error for everything else. Nothing else may cross that boundary.
#pragma once

#include <stdexcept>
#include <string>

namespace fmu {

class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class Discard : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace fmu

// The master's one exception type: what failed and why, in a sentence a user can act on. Loader
// failures keep their own type (fmi_loader::LoaderError); main() prints either and sets the exit code.
#pragma once

#include <stdexcept>
#include <string>

namespace cosim {

class CosimError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A setting (--set, a campaign's [set] or draw) naming no variable of its component or holding no value
// of its type: a front end may say where the setting came from.
class SettingError : public CosimError {
public:
    using CosimError::CosimError;
};

// Why the last failed read or write failed (strerror of errno), for messages that name the file.
std::string io_reason();

}  // namespace cosim

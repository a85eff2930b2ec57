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

// Why the last failed read or write failed (strerror of errno), for messages that name the file.
std::string io_reason();

}  // namespace cosim

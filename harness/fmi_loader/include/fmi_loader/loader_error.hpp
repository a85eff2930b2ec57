// The one exception type of the loader: a code saying which step failed, a message naming the file
// and the cause.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace fmi_loader {

enum class LoaderErrc {
    archive_open,    // the .fmu is missing or not a readable zip
    unsafe_entry,    // an entry would land outside the extraction directory (.., absolute, symlink)
    extract_io,      // reading an entry or writing it to disk failed
    xml_parse,       // modelDescription.xml is not well-formed
    xml_invalid,     // well-formed but breaks the FMI 2.0 schema rules the loader relies on
    dl_open,         // dlopen of the binary failed
    missing_symbol,  // the binary lacks FMI 2.0 functions it must export
    limit,           // a size or count beyond fmi_loader::Limits (the message names the limit)
    cancelled,       // request_cancel() was called (a signal) while extracting
    unsupported,     // a valid FMU using a feature the master does not run (FMI 3.0 clocks, Scheduled Execution)
};

std::string_view to_string(LoaderErrc code) noexcept;

class LoaderError : public std::runtime_error {
public:
    LoaderError(LoaderErrc code, const std::string& message);
    LoaderErrc code() const noexcept { return code_; }

private:
    LoaderErrc code_;
};

}  // namespace fmi_loader

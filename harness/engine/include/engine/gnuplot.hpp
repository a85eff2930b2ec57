// gnuplot run without a shell and without any path in its script: it starts in the figure's folder
// (posix_spawn with a chdir), reads its script from a file there and writes a PNG named by the caller
// from letters, digits, '-' and '_'; titles pass through gnuplot_string. A folder of any name
// (quotes, `system(...)`, line breaks) is never text gnuplot interprets.
#pragma once

#include <filesystem>
#include <string>

namespace cosim {

// A gnuplot single-quoted string of `text`: quotes doubled, line breaks and other control characters
// (which would end gnuplot's command) made spaces.
std::string gnuplot_string(const std::string& text);

// A file name from `text`: letters, digits, '-' and '_' kept, every other character '_'.
std::string safe_file_name(const std::string& text);

// Runs `script` (which names its files relative to `folder`) with gnuplot in `folder`; the script must
// set output to `png` (a name relative to `folder`). Throws CosimError with gnuplot's message when it
// fails or writes no PNG, and then leaves no PNG of that name (an empty or partial one is removed).
void run_gnuplot(const std::filesystem::path& folder, const std::string& script, const std::string& png);

}  // namespace cosim

#include "engine/gnuplot.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include "engine/cosim_error.hpp"
#include "engine/output_file.hpp"

extern char** environ;

namespace cosim {

namespace fs = std::filesystem;

std::string gnuplot_string(const std::string& text) {
    std::string out = "'";
    for (const char c : text) {
        if (c == '\'')
            out += "''";
        else if (std::iscntrl(static_cast<unsigned char>(c)))
            out += ' ';
        else
            out += c;
    }
    return out + "'";
}

std::string safe_file_name(const std::string& text) {
    std::string out;
    for (const char c : text) out += std::isalnum(static_cast<unsigned char>(c)) || c == '-' ? c : '_';
    return out;
}

void run_gnuplot(const fs::path& folder, const std::string& script, const std::string& png) {
    const fs::path target = folder / png;
    // The script and gnuplot's remarks live beside the figure only while it is drawn.
    PendingFile script_file(folder / (png + ".gp"));
    PendingFile log(folder / (png + ".log"));
    {
        std::ofstream out(script_file.path());
        out << script;
        out.close();
        if (!out) throw CosimError("cannot write " + script_file.path().string());
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addchdir_np(&actions, folder.c_str());
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.path().c_str(), O_WRONLY | O_TRUNC, 0);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    std::string program = "gnuplot", script_name = script_file.path().filename().string();
    std::vector<char*> argv{program.data(), script_name.data(), nullptr};
    pid_t pid = -1;
    const int spawned = posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0)
        throw CosimError("cannot start gnuplot (" + std::string(std::strerror(spawned)) +
                         "; install the Debian package gnuplot-nox)");
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
    std::error_code ec;
    const bool drawn = WIFEXITED(status) && WEXITSTATUS(status) == 0 && fs::is_regular_file(target, ec) &&
                       fs::file_size(target, ec) > 0;
    if (!drawn) {
        fs::remove(target, ec);
        std::ifstream in(log.path());
        std::stringstream text;
        text << in.rdbuf();
        throw CosimError("gnuplot failed drawing " + target.string() + (text.str().empty() ? "" : ": " + text.str()));
    }
}

}  // namespace cosim

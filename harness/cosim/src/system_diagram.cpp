#include "system_diagram.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "engine/cosim_error.hpp"
#include "engine/output_file.hpp"
#include "engine/value_text.hpp"

extern char** environ;

namespace cosim {

namespace {

// A Graphviz double-quoted string: quotes and backslashes escaped, control characters made spaces.
std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        out += static_cast<unsigned char>(c) < 0x20 ? ' ' : c;
    }
    return out + "\"";
}

// Lines of a label as one quoted Graphviz string, each line escaped, joined by dot's \n.
std::string lines(const std::vector<std::string>& parts) {
    std::string out;
    for (const auto& p : parts) {
        const std::string q = quoted(p);
        out += (out.empty() ? "" : "\\n") + q.substr(1, q.size() - 2);
    }
    return "\"" + out + "\"";
}

// "sun_body[1]" -> "sun_body[]": the elements of one array gather under one name.
std::string base_of(const std::string& connector) {
    const auto open = connector.rfind('[');
    return open != std::string::npos && connector.back() == ']' ? connector.substr(0, open) : connector;
}

std::string how_it_runs(const ComponentDescription& c) {
    if (c.bridge) return "hardware bridge (" + c.bridge->transport + ")";
    if (c.execution && c.execution->co_simulation)
        return "Co-Simulation" + (c.execution->communication_step
                                      ? ", step " + format_real(*c.execution->communication_step) + " s"
                                      : std::string());
    return "Model Exchange";
}

}  // namespace

std::string system_dot(const SystemDescription& system) {
    std::ostringstream dot;
    dot << "digraph " << quoted(system.name) << " {\n  rankdir=LR;\n  node [shape=box, style=rounded, "
        << "fontname=\"sans\"];\n  edge [fontname=\"sans\", fontsize=9];\n";
    for (const auto& c : system.components)
        dot << "  " << quoted(c.name) << " [label=" << lines({c.name, c.source, how_it_runs(c)}) << "];\n";
    // One arrow per ordered pair of components, listing what it carries ("a -> b" once per array).
    std::map<std::pair<std::string, std::string>, std::vector<std::string>> edges;
    for (const auto& k : system.connections) {
        auto& carried = edges[{k.start_element, k.end_element}];
        const std::string out = base_of(k.start_connector), in = base_of(k.end_connector);
        const std::string what = out == in ? out : out + " -> " + in;
        const std::string shown = what + (out != k.start_connector ? " [..]" : "");
        if (std::find(carried.begin(), carried.end(), shown) == carried.end()) carried.push_back(shown);
    }
    for (const auto& [ends, carried] : edges) {
        dot << "  " << quoted(ends.first) << " -> " << quoted(ends.second) << " [label=" << lines(carried) << "];\n";
    }
    dot << "}\n";
    return dot.str();
}

std::vector<std::filesystem::path> write_system_diagram(const std::filesystem::path& system,
                                                        const std::filesystem::path& out) {
    const SystemDescription d = read_system_description(system);
    const std::filesystem::path folder = out.parent_path().empty() ? std::filesystem::path(".") : out.parent_path();
    const std::string base = out.filename().string();
    if (base.empty()) throw CosimError("--diagram " + out.string() + ": give a file name (without extension)");
    const auto dot_file = folder / (base + ".dot"), svg_file = folder / (base + ".svg");
    refuse_overwriting_inputs("--diagram", dot_file, {system});
    {
        std::ofstream f(dot_file);
        f << system_dot(d);
        f.close();
        if (!f) throw CosimError("cannot write " + dot_file.string());
    }
    // dot in the diagram's folder, file names only: no folder name reaches it; no shell.
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addchdir_np(&actions, folder.c_str());
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    std::string program = "dot", format = "-Tsvg", output = "-o" + base + ".svg", input = base + ".dot";
    std::vector<char*> argv{program.data(), format.data(), output.data(), input.data(), nullptr};
    pid_t pid = -1;
    const int spawned = posix_spawnp(&pid, "dot", &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0)
        throw CosimError("cannot start dot (" + std::string(std::strerror(spawned)) +
                         "; install the Debian package graphviz); the diagram's text is in " + dot_file.string());
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw CosimError("dot failed on " + dot_file.string() + " (exit status " + std::to_string(WEXITSTATUS(status)) +
                         ")");
    return {dot_file, svg_file};
}

}  // namespace cosim

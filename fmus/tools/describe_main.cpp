// Build-time tool linked with one block: writes that block's modelDescription.xml (FMI 2.0, or 3.0
// with the argument "3.0") and documentation/index.html into a staging folder, from its variable table.
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string_view>

#include "description3_xml.hpp"
#include "description_xml.hpp"
#include "documentation_html.hpp"

int main(int argc, char** argv) {
    const bool fmi3 = argc == 3 && std::string_view(argv[2]) == "3.0";
    if (argc != 2 && !fmi3) {
        std::cerr << "usage: " << argv[0] << " STAGING_DIR [3.0]\n";
        return 2;
    }
    try {
        const std::filesystem::path dir = argv[1];
        std::filesystem::create_directories(dir / "documentation");
        const auto model = fmu::make_model();
        auto write = [](const std::filesystem::path& path, const std::string& text) {
            std::ofstream out(path, std::ios::binary);
            out << text;
            if (!out) throw std::runtime_error("cannot write " + path.string());
        };
        write(dir / "modelDescription.xml",
              fmi3 ? fmu::model_description3_xml(*model) : fmu::model_description_xml(*model));
        write(dir / "documentation" / "index.html", fmu::documentation_html(*model));
        return 0;
    } catch (const std::exception& e) {
        std::cerr << argv[0] << ": " << e.what() << "\n";
        return 1;
    }
}

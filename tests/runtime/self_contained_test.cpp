// Every FMU's binary must run where SUNDIALS (or any other project dependency) is not installed.
// Proof in two parts, for every .fmu in the build's FMU folder:
//  1. its shared library names no library beyond the C runtime in DT_NEEDED (read from the ELF
//     file itself), in particular no libsundials;
//  2. loaded into this process (which does not link SUNDIALS dynamically) and run in
//     Co-Simulation, where CVODE integrates inside the FMU, no libsundials object gets mapped.
#include <elf.h>
#include <gtest/gtest.h>
#include <link.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "engine/fmi2_instance.hpp"
#include "fmi_loader/fmu.hpp"

namespace {

std::vector<std::filesystem::path> built_fmus() {
    std::vector<std::filesystem::path> out;
    for (const auto& entry : std::filesystem::directory_iterator(PVATT_FMU_DIR))
        if (entry.path().extension() == ".fmu") out.push_back(entry.path());
    return out;
}

// DT_NEEDED entries of a 64-bit ELF shared object, from its section headers.
std::vector<std::string> needed_libraries(const std::filesystem::path& so) {
    std::ifstream in(so, std::ios::binary);
    std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.size() < sizeof(Elf64_Ehdr)) throw std::runtime_error("not an ELF file: " + so.string());
    Elf64_Ehdr eh;
    std::memcpy(&eh, bytes.data(), sizeof eh);
    if (std::memcmp(eh.e_ident, ELFMAG, SELFMAG) != 0 || eh.e_ident[EI_CLASS] != ELFCLASS64)
        throw std::runtime_error("not a 64-bit ELF file: " + so.string());
    auto section = [&](std::size_t i) {
        Elf64_Shdr sh;
        std::memcpy(&sh, bytes.data() + eh.e_shoff + i * eh.e_shentsize, sizeof sh);
        return sh;
    };
    std::vector<std::string> needed;
    for (std::size_t i = 0; i < eh.e_shnum; ++i) {
        const Elf64_Shdr dyn = section(i);
        if (dyn.sh_type != SHT_DYNAMIC) continue;
        const Elf64_Shdr strtab = section(dyn.sh_link);
        for (std::size_t off = 0; off + sizeof(Elf64_Dyn) <= dyn.sh_size; off += sizeof(Elf64_Dyn)) {
            Elf64_Dyn d;
            std::memcpy(&d, bytes.data() + dyn.sh_offset + off, sizeof d);
            if (d.d_tag == DT_NEEDED) needed.emplace_back(bytes.data() + strtab.sh_offset + d.d_un.d_val);
        }
    }
    return needed;
}

bool sundials_mapped() {
    bool found = false;
    dl_iterate_phdr(
        [](dl_phdr_info* info, size_t, void* data) {
            if (info->dlpi_name && std::strstr(info->dlpi_name, "libsundials")) *static_cast<bool*>(data) = true;
            return 0;
        },
        &found);
    return found;
}

TEST(SelfContained, FmuBinariesNeedOnlyTheCRuntime) {
    const auto fmus = built_fmus();
    ASSERT_FALSE(fmus.empty()) << "no .fmu in " << PVATT_FMU_DIR;
    for (const auto& path : fmus) {
        fmi_loader::Fmu fmu(path);
        const auto so = fmi_loader::Fmi2Library::binary_path(fmu.archive().directory(),
                                                             fmu.description().co_simulation->model_identifier);
        for (const auto& lib : needed_libraries(so)) {
            EXPECT_EQ(lib.find("sundials"), std::string::npos) << path << " needs " << lib;
#ifndef PVATT_SANITIZE_BUILD  // a sanitizer build adds its runtimes and the shared C++ runtime
            const bool c_runtime = lib == "libc.so.6" || lib == "libm.so.6" || lib.starts_with("ld-linux");
            EXPECT_TRUE(c_runtime) << path << " needs " << lib << ", which a host may not have";
#endif
        }
    }
}

TEST(SelfContained, CoSimulationRunsWithoutLoadingSystemSundials) {
    ASSERT_FALSE(sundials_mapped()) << "the test itself must not link SUNDIALS dynamically";
    for (const auto& path : built_fmus()) {
        fmi_loader::Fmu fmu(path);
        cosim::Fmi2Instance instance(fmu, fmi_loader::FmuKind::co_simulation, "self_contained");
        instance.setup_experiment(0.0, std::nullopt, std::nullopt);
        instance.enter_initialization_mode();
        instance.exit_initialization_mode();
        for (int k = 0; k < 10; ++k) instance.do_step(0.01 * k, 0.01);
        instance.terminate();
        EXPECT_FALSE(sundials_mapped()) << path;
    }
}

}  // namespace

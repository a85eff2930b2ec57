#include "engine/import_cache.hpp"

#include <map>
#include <mutex>
#include <tuple>

namespace cosim {

namespace {

bool only_once_per_process(const fmi_loader::ModelDescription& d) {
    return (d.model_exchange && d.model_exchange->can_be_instantiated_only_once_per_process) ||
           (d.co_simulation && d.co_simulation->can_be_instantiated_only_once_per_process);
}

}  // namespace

std::shared_ptr<fmi_loader::Fmu> import_fmu(const std::filesystem::path& file, const fmi_loader::Limits& limits) {
    using Key = std::tuple<std::filesystem::path, std::uintmax_t, std::filesystem::file_time_type>;
    static std::mutex mutex;
    static std::map<Key, std::shared_ptr<fmi_loader::Fmu>> imported;
    std::error_code ec;
    Key key{std::filesystem::canonical(file, ec), 0, {}};
    if (!ec) std::get<1>(key) = std::filesystem::file_size(std::get<0>(key), ec);
    if (!ec) std::get<2>(key) = std::filesystem::last_write_time(std::get<0>(key), ec);
    if (ec) return std::make_shared<fmi_loader::Fmu>(file, limits);  // the loader names what is wrong
    std::lock_guard lock(mutex);
    if (const auto it = imported.find(key); it != imported.end()) return it->second;
    auto fmu = std::make_shared<fmi_loader::Fmu>(file, limits);
    if (!only_once_per_process(fmu->description())) imported.emplace(key, fmu);
    return fmu;
}

}  // namespace cosim

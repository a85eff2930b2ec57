#include "engine/observer.hpp"

#include <cerrno>
#include <cstring>

#include "engine/cosim_error.hpp"
#include "engine/csv_table.hpp"
#include "engine/interrupt.hpp"
#include "engine/name_hint.hpp"
#include "engine/value_text.hpp"

namespace cosim {

std::string io_reason() {
    return errno != 0 ? std::strerror(errno) : "input/output error";
}

std::vector<OutputColumn> output_columns(const System& system, const std::vector<std::string>& names) {
    const auto& comps = system.components();
    std::vector<OutputColumn> columns;
    if (names.empty()) {
        for (std::size_t i = 0; i < comps.size(); ++i)
            for (const auto& v : comps[i].description().model_variables)
                if (v.causality == fmi_loader::Causality::output) columns.push_back({i, &v});
    }
    for (const auto& name : names) {
        const auto split = split_variable_name(name);
        if (!split) throw CosimError("--columns expects component.variable, got '" + name + "'");
        const std::size_t i = system.component_index(split->component);
        const auto* v = comps[i].description().find_variable(split->variable);
        if (!v)
            throw CosimError("--columns: " +
                             unknown_variable_message(comps[i].description(), comps[i].name, split->variable));
        columns.push_back({i, v});
    }
    return columns;
}

void InterruptCheck::sample(double t, System&) {
    throw_if_interrupted();
    last_time = t;
}

CsvWriter::CsvWriter(const std::filesystem::path& file, const System& system, const std::vector<std::string>& columns,
                     bool qualified)
    : path_(file), columns_(output_columns(system, columns)) {
    const auto& comps = system.components();
    pending_ = std::make_unique<PendingFile>(file);
    out_.open(pending_->path());
    if (!out_) throw CosimError("cannot write " + file.string() + ": " + std::strerror(errno));
    last_flush_ = std::chrono::steady_clock::now();
    out_ << "time";
    for (const auto& c : columns_)
        out_ << "," << csv_field(qualified ? comps[c.component].name + "." + c.variable->name : c.variable->name);
    out_ << "\n";
    check();
}

void CsvWriter::sample(double t, System& system) {
    out_ << format_real(t);
    for (const auto& c : columns_) {
        const std::string text = system.components()[c.component].instance->get_as_text(*c.variable);
        out_ << "," << (c.variable->type == fmi_loader::VariableType::string ? csv_field(text) : text);
    }
    out_ << "\n";
    ++rows_;
    if (!pending_->committed()) pending_->commit();
    unflushed_ = true;
    between_steps();
    check();
}

void CsvWriter::between_steps() {
    if (!unflushed_) return;
    if (const auto now = std::chrono::steady_clock::now(); now - last_flush_ >= csv_flush_interval) {
        out_.flush();
        last_flush_ = now;
        unflushed_ = false;
        check();
    }
}

void CsvWriter::check() {
    // errno is what the failed write(2) under the stream left; the stream itself keeps no reason.
    if (!out_) throw CosimError("writing " + path_.string() + " failed: " + io_reason());
}

void CsvWriter::close() {
    if (!out_.is_open()) return;
    errno = 0;
    out_.flush();
    check();
    out_.close();
    if (out_.fail()) throw CosimError("closing " + path_.string() + " failed: " + io_reason());
}

}  // namespace cosim

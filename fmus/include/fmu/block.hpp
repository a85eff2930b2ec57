// The base a block derives from. A block supplies:
//   - a trivially copyable `Data` struct: every variable as a field, defaults in member initializers;
//   - `static void declare(fmu::Table<Data>&)`: its variable table;
//   - `static fmu::ModelInfo describe()`: name, description, documentation, default experiment;
//   - the equations it needs (see fmu::Model); the defaults do nothing.
// and ends with FMU_BLOCK(ClassName) in one source file.
#pragma once

#include <cstring>
#include <memory>

#include "fmu/model.hpp"

namespace fmu {

template <class Derived, class DataT>
class Block : public Model {
public:
    using Data = DataT;

    const ModelInfo& info() const final {
        static const ModelInfo info = Derived::describe();
        return info;
    }
    const TableBase& table() const final { return static_table(); }
    static const Table<Data>& static_table() {
        static const Table<Data> table = [] {
            Table<Data> t;
            Derived::declare(t);
            return t;
        }();
        return table;
    }
    std::unique_ptr<Model> clone() const final { return std::make_unique<Derived>(static_cast<const Derived&>(*this)); }

    std::span<std::byte> bytes() final { return {reinterpret_cast<std::byte*>(&data_), sizeof(Data)}; }
    std::span<const std::byte> bytes() const final {
        return {reinterpret_cast<const std::byte*>(&data_), sizeof(Data)};
    }
    void reset_to_defaults() final { data_ = Data{}; }

    void initialize(double) override {}
    void evaluate(double) override {}
    std::size_t event_indicator_count() const override { return 0; }
    void event_indicators(double, std::span<double>) override {}
    EventUpdate event_update(double, bool) override { return {}; }
    double next_time_event() const override { return no_time_event; }
    void validate() const override {}

    Data& data() { return data_; }
    const Data& data() const { return data_; }

private:
    Data data_{};
};

}  // namespace fmu

#define FMU_BLOCK(ClassName)                          \
    std::unique_ptr<::fmu::Model> fmu::make_model() { \
        return std::make_unique<ClassName>();         \
    }

#include "fmu3_under_test.hpp"

#include <dlfcn.h>
#include <libxml/parser.h>
#include <libxml/tree.h>

#include <algorithm>
#include <cstdlib>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace conformance3 {

namespace {

std::optional<std::string> attr(const xmlNode* n, const char* name) {
    xmlChar* v = xmlGetProp(n, BAD_CAST name);
    if (!v) return std::nullopt;
    std::string s(reinterpret_cast<const char*>(v));
    xmlFree(v);
    return s;
}

bool is(const xmlNode* n, const char* name) {
    return n->type == XML_ELEMENT_NODE && xmlStrcmp(n->name, BAD_CAST name) == 0;
}

std::vector<std::string> words(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

Variable3 read_variable(const xmlNode* n) {
    Variable3 v;
    v.type = reinterpret_cast<const char*>(n->name);
    v.name = attr(n, "name").value_or("");
    v.value_reference = static_cast<std::uint32_t>(std::stoul(attr(n, "valueReference").value_or("0")));
    v.causality = attr(n, "causality").value_or("local");
    v.variability = attr(n, "variability").value_or(v.type == "Float64" ? "continuous" : "discrete");
    v.initial = attr(n, "initial").value_or("");
    if (const auto d = attr(n, "derivative")) v.derivative = static_cast<std::uint32_t>(std::stoul(*d));
    if (const auto s = attr(n, "start")) v.start = words(*s);
    for (const xmlNode* c = n->children; c; c = c->next) {
        if (is(c, "Dimension")) {
            v.array = true;
            v.count *= std::stoul(attr(c, "start").value_or("0"));
        }
        if (is(c, "Start")) v.start.push_back(attr(c, "value").value_or(""));
    }
    return v;
}

}  // namespace

const Variable3& Description3::by_reference(std::uint32_t vr) const {
    for (const auto& v : variables)
        if (v.value_reference == vr) return v;
    throw std::runtime_error("no variable has value reference " + std::to_string(vr));
}

std::size_t Description3::count_of(const std::vector<std::uint32_t>& refs) const {
    std::size_t n = 0;
    for (auto r : refs) n += by_reference(r).count;
    return n;
}

Description3 read_description3(const std::filesystem::path& xml) {
    std::unique_ptr<xmlDoc, void (*)(xmlDoc*)> doc(xmlReadFile(xml.c_str(), nullptr, XML_PARSE_NONET), xmlFreeDoc);
    if (!doc) throw std::runtime_error("cannot parse " + xml.string());
    const xmlNode* root = xmlDocGetRootElement(doc.get());
    Description3 md;
    md.token = attr(root, "instantiationToken").value_or("");
    for (const xmlNode* n = root->children; n; n = n->next) {
        if (is(n, "CoSimulation")) {
            md.model_identifier = attr(n, "modelIdentifier").value_or("");
            md.has_event_mode = attr(n, "hasEventMode") == "true";
            md.might_return_early = attr(n, "mightReturnEarlyFromDoStep") == "true";
        }
        if (is(n, "DefaultExperiment")) {
            md.start_time = std::stod(attr(n, "startTime").value_or("0"));
            md.stop_time = std::stod(attr(n, "stopTime").value_or("1"));
            md.step_size = std::stod(attr(n, "stepSize").value_or("0.01"));
        }
        if (is(n, "ModelVariables"))
            for (const xmlNode* v = n->children; v; v = v->next)
                if (v->type == XML_ELEMENT_NODE) md.variables.push_back(read_variable(v));
        if (is(n, "ModelStructure"))
            for (const xmlNode* u = n->children; u; u = u->next) {
                if (u->type != XML_ELEMENT_NODE) continue;
                const auto vr = static_cast<std::uint32_t>(std::stoul(attr(u, "valueReference").value_or("0")));
                if (is(u, "Output")) md.outputs.push_back(vr);
                if (is(u, "ContinuousStateDerivative")) md.derivatives.push_back(vr);
                if (is(u, "EventIndicator")) md.event_indicators.push_back(vr);
            }
    }
    return md;
}

Fmu3::Fmu3(const std::filesystem::path& fmu) : archive_(fmu) {
    md_ = read_description3(archive_.model_description_path());
    const auto so = archive_.directory() / "binaries" / "x86_64-linux" / (md_.model_identifier + ".so");
    handle_ = dlopen(so.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle_) throw std::runtime_error(std::string("dlopen: ") + dlerror());
    auto sym = [&](auto& pointer, const char* name) {
        pointer = reinterpret_cast<std::remove_reference_t<decltype(pointer)>>(dlsym(handle_, name));
        if (!pointer) throw std::runtime_error(std::string("missing ") + name);
    };
    sym(f_.instantiate_me, "fmi3InstantiateModelExchange");
    sym(f_.instantiate_cs, "fmi3InstantiateCoSimulation");
    sym(f_.instantiate_se, "fmi3InstantiateScheduledExecution");
    sym(f_.free_instance, "fmi3FreeInstance");
    sym(f_.enter_initialization_mode, "fmi3EnterInitializationMode");
    sym(f_.exit_initialization_mode, "fmi3ExitInitializationMode");
    sym(f_.enter_event_mode, "fmi3EnterEventMode");
    sym(f_.terminate, "fmi3Terminate");
    sym(f_.reset, "fmi3Reset");
    sym(f_.get_float64, "fmi3GetFloat64");
    sym(f_.get_float32, "fmi3GetFloat32");
    sym(f_.get_int32, "fmi3GetInt32");
    sym(f_.get_int64, "fmi3GetInt64");
    sym(f_.get_boolean, "fmi3GetBoolean");
    sym(f_.get_string, "fmi3GetString");
    sym(f_.set_float64, "fmi3SetFloat64");
    sym(f_.set_int32, "fmi3SetInt32");
    sym(f_.set_int64, "fmi3SetInt64");
    sym(f_.set_boolean, "fmi3SetBoolean");
    sym(f_.set_string, "fmi3SetString");
    sym(f_.get_fmu_state, "fmi3GetFMUState");
    sym(f_.set_fmu_state, "fmi3SetFMUState");
    sym(f_.free_fmu_state, "fmi3FreeFMUState");
    sym(f_.serialized_size, "fmi3SerializedFMUStateSize");
    sym(f_.serialize, "fmi3SerializeFMUState");
    sym(f_.deserialize, "fmi3DeserializeFMUState");
    sym(f_.enter_configuration_mode, "fmi3EnterConfigurationMode");
    sym(f_.update_discrete_states, "fmi3UpdateDiscreteStates");
    sym(f_.enter_continuous_time_mode, "fmi3EnterContinuousTimeMode");
    sym(f_.completed_integrator_step, "fmi3CompletedIntegratorStep");
    sym(f_.set_time, "fmi3SetTime");
    sym(f_.set_continuous_states, "fmi3SetContinuousStates");
    sym(f_.get_derivatives, "fmi3GetContinuousStateDerivatives");
    sym(f_.get_event_indicators, "fmi3GetEventIndicators");
    sym(f_.get_continuous_states, "fmi3GetContinuousStates");
    sym(f_.get_number_of_states, "fmi3GetNumberOfContinuousStates");
    sym(f_.get_number_of_event_indicators, "fmi3GetNumberOfEventIndicators");
    sym(f_.enter_step_mode, "fmi3EnterStepMode");
    sym(f_.do_step, "fmi3DoStep");
}

Fmu3::~Fmu3() {
    if (handle_) dlclose(handle_);
}

bool Log3::has_error() const {
    for (const auto& [status, text] : records)
        if (status >= fmi3Error) return true;
    return false;
}

std::string Log3::dump() const {
    std::string out;
    for (const auto& [status, text] : records) out += std::to_string(status) + ": " + text + "\n";
    return out;
}

namespace {
void record(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category, fmi3String message) {
    static_cast<Log3*>(env)->records.emplace_back(
        status, std::string(category ? category : "") + ": " + (message ? message : ""));
}
}  // namespace

Instance3::Instance3(Fmu3& fmu, Kind kind, bool event_mode_used, bool early_return_allowed, const std::string& token,
                     fmi3IntermediateUpdateCallback intermediate_update)
    : fmu_(fmu), log_(std::make_unique<Log3>()) {
    const std::string& t = token.empty() ? fmu.md().token : token;
    if (kind == Kind::model_exchange)
        c_ = fmu.f().instantiate_me("conformance3", t.c_str(), nullptr, false, false, log_.get(), record);
    else
        c_ = fmu.f().instantiate_cs("conformance3", t.c_str(), nullptr, false, false, event_mode_used,
                                    early_return_allowed, nullptr, 0, log_.get(), record, intermediate_update);
}

Instance3::~Instance3() {
    if (c_) fmu_.f().free_instance(c_);
}

fmi3Status Instance3::initialize() {
    const auto& md = fmu_.md();
    fmi3Status s = f().enter_initialization_mode(c_, false, 0.0, md.start_time, true, md.stop_time);
    if (s != fmi3OK) return s;
    return f().exit_initialization_mode(c_);
}

std::vector<double> Instance3::get_float64(const Variable3& v) {
    std::vector<double> values(v.count);
    if (f().get_float64(c_, &v.value_reference, 1, values.data(), values.size()) != fmi3OK)
        throw std::runtime_error("fmi3GetFloat64 of " + v.name + " failed:\n" + log_->dump());
    return values;
}

std::vector<double> Instance3::outputs() {
    std::vector<double> all;
    for (auto r : md().outputs) {
        const auto& v = md().by_reference(r);
        if (v.type != "Float64") continue;
        const auto values = get_float64(v);
        all.insert(all.end(), values.begin(), values.end());
    }
    return all;
}

std::vector<std::filesystem::path> fmu3_files() {
    std::filesystem::path dir = PVATT_FMU3_DIR_DEFAULT;
    if (const char* env = std::getenv("PVATT_FMU3_DIR"); env && *env) dir = env;
    std::vector<std::filesystem::path> out;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
        if (entry.is_regular_file() && entry.path().extension() == ".fmu") out.push_back(entry.path());
    std::sort(out.begin(), out.end());
    return out;
}

std::filesystem::path fmi2_archive_of(const std::filesystem::path& fmu3) {
    std::filesystem::path dir = PVATT_FMU_DIR_DEFAULT;
    if (const char* env = std::getenv("PVATT_FMU_DIR"); env && *env) dir = env;
    return dir / fmu3.filename();
}

}  // namespace conformance3

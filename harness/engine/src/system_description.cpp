#include "engine/system_description.hpp"

#include <libxml/parser.h>
#include <libxml/tree.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <sstream>

#include "engine/cosim_error.hpp"
#include "engine/name_hint.hpp"
#include "engine/value_text.hpp"

namespace cosim {

std::filesystem::path inside_archive(const fmi_loader::FmuArchive& archive, const std::string& reference,
                                     const std::string& what) {
    namespace fs = std::filesystem;
    const auto refuse = [&](const std::string& why) {
        return CosimError(archive.fmu_path().string() + ": " + what + " '" + reference + "' refused: " + why +
                          " (an .ssp reads only relative references inside itself)");
    };
    const auto colon = reference.find(':'), slash = reference.find('/');
    if (colon != std::string::npos && (slash == std::string::npos || colon < slash))
        throw refuse("a URI with a scheme");
    const fs::path p(reference);
    if (reference.empty() || p.is_absolute()) throw refuse("an absolute or empty path");
    const fs::path normal = p.lexically_normal();
    if (normal.empty() || *normal.begin() == ".." || normal == ".") throw refuse("it climbs out of the archive");
    const fs::path candidate = archive.directory() / normal;
    std::error_code ec, ec_root;
    const fs::path real = fs::weakly_canonical(candidate, ec), root = fs::canonical(archive.directory(), ec_root);
    const auto [end, _] = std::mismatch(root.begin(), root.end(), real.begin(), real.end());
    if (ec || ec_root || end != root.end()) throw refuse("it resolves outside the archive");
    if (!fs::is_regular_file(real)) throw refuse("no such file in the archive");
    return candidate;
}

namespace {

struct DocDeleter {
    void operator()(xmlDoc* d) const { xmlFreeDoc(d); }
};
using Doc = std::unique_ptr<xmlDoc, DocDeleter>;

// No network, no DTD loading, no entity substitution: a system file cannot reach outside itself.
// A DOCTYPE is the only way to declare entities, and SSP never uses one: it is refused outright.
// The size is bounded before parsing (max_ssd_bytes) so that a huge file is not read into memory.
Doc parse_file(const std::filesystem::path& path) {
    std::error_code ec;
    // Not a device, a pipe or a folder: /dev/stdin would block, /dev/zero never end.
    if (!std::filesystem::is_regular_file(path, ec))
        throw CosimError(path.string() + ": not a regular file (" + (ec ? ec.message() : "a device, pipe or folder") +
                         ")");
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec && size > max_ssd_bytes)
        throw CosimError(path.string() + " is " + std::to_string(size) + " bytes, more than the limit of " +
                         std::to_string(max_ssd_bytes) + " bytes for a system description");
    Doc doc(xmlReadFile(path.c_str(), nullptr, XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING));
    if (!doc) {
        const xmlError* e = xmlGetLastError();
        throw CosimError(
            path.string() + ": not well-formed XML" +
            (e && e->message ? std::string(" (line ") + std::to_string(e->line) + ": " + e->message + ")" : ""));
    }
    if (doc->intSubset || doc->extSubset)
        throw CosimError(path.string() + ": DOCTYPE declarations are not allowed in an .ssd");
    return doc;
}

bool is(const xmlNode* n, const char* local) {
    return n && n->type == XML_ELEMENT_NODE && std::strcmp(reinterpret_cast<const char*>(n->name), local) == 0;
}

std::optional<std::string> attribute(const xmlNode* n, const char* name) {
    xmlChar* v = xmlGetProp(n, BAD_CAST name);
    if (!v) return std::nullopt;
    std::string s(reinterpret_cast<const char*>(v));
    xmlFree(v);
    return s;
}

std::string required(const xmlNode* n, const char* name, const std::filesystem::path& file) {
    auto v = attribute(n, name);
    if (!v)
        throw CosimError(file.string() + ":" + std::to_string(n->line) + ": <" +
                         reinterpret_cast<const char*>(n->name) + "> lacks the attribute '" + name + "'");
    return *v;
}

template <class F>
void for_children(const xmlNode* n, const char* local, F&& f) {
    for (const xmlNode* c = n ? n->children : nullptr; c; c = c->next)
        if (is(c, local)) f(c);
}

const xmlNode* first_child(const xmlNode* n, const char* local) {
    for (const xmlNode* c = n ? n->children : nullptr; c; c = c->next)
        if (is(c, local)) return c;
    return nullptr;
}

ConnectorKind parse_kind(const std::string& kind, const std::filesystem::path& file, int line) {
    if (kind == "input") return ConnectorKind::input;
    if (kind == "output") return ConnectorKind::output;
    if (kind == "parameter") return ConnectorKind::parameter;
    if (kind == "calculatedParameter") return ConnectorKind::calculated_parameter;
    if (kind == "inout") return ConnectorKind::inout;
    throw CosimError(file.string() + ":" + std::to_string(line) + ": unknown connector kind '" + kind + "'");
}

// The type child of a connector or parameter: <ssc:Real unit="V"/>, <ssv:Integer value="3"/>, ...
const xmlNode* type_child(const xmlNode* n) {
    for (const char* t : {"Real", "Integer", "Boolean", "String", "Enumeration", "Binary"})
        if (const xmlNode* c = first_child(n, t)) return c;
    return nullptr;
}

void read_parameter_set(const xmlNode* set, const std::filesystem::path& file, std::vector<Setting>& out,
                        std::vector<std::string>& places) {
    for_children(first_child(set, "Parameters"), "Parameter", [&](const xmlNode* p) {
        const std::string where = file.string() + ":" + std::to_string(p->line);
        const std::string name = required(p, "name", file);
        if (name.empty()) throw CosimError(where + ": a parameter with an empty name");
        const xmlNode* t = type_child(p);
        if (!t)
            throw CosimError(where + ": parameter '" + name +
                             "' has no typed value (<ssv:Real value=\"..\"/>, Integer, Boolean, String or "
                             "Enumeration)");
        const auto value = attribute(t, "value");
        if (!value)
            throw CosimError(where + ": parameter '" + name + "': <ssv:" + reinterpret_cast<const char*>(t->name) +
                             "> lacks the attribute 'value'");
        out.push_back({"", name, *value, reinterpret_cast<const char*>(t->name)});
        places.push_back(where);
    });
}

ParameterValues read_parameter_file(const std::filesystem::path& ssv);

void read_bindings(const xmlNode* component, const std::filesystem::path& file, const fmi_loader::FmuArchive* archive,
                   std::vector<Setting>& out, std::vector<std::string>& places,
                   std::vector<std::filesystem::path>& parameter_files) {
    for_children(first_child(component, "ParameterBindings"), "ParameterBinding", [&](const xmlNode* binding) {
        if (auto prefix = attribute(binding, "prefix"); prefix && !prefix->empty())
            throw CosimError(file.string() + ":" + std::to_string(binding->line) +
                             ": parameter prefixes are not supported");
        if (const xmlNode* inline_values = first_child(binding, "ParameterValues")) {
            for_children(inline_values, "ParameterSet",
                         [&](const xmlNode* set) { read_parameter_set(set, file, out, places); });
        } else if (auto source = attribute(binding, "source")) {
            const auto ssv =
                archive ? inside_archive(*archive, *source, "parameter file") : file.parent_path() / *source;
            parameter_files.push_back(ssv);
            auto read = read_parameter_file(ssv);
            out.insert(out.end(), read.values.begin(), read.values.end());
            places.insert(places.end(), read.places.begin(), read.places.end());
        }
    });
}

ParameterValues read_parameter_file(const std::filesystem::path& ssv) {
    const Doc doc = parse_file(ssv);
    const xmlNode* root = xmlDocGetRootElement(doc.get());
    if (!is(root, "ParameterSet"))
        throw CosimError(ssv.string() + ":" + std::to_string(root ? root->line : 1) +
                         ": the root element is not ssv:ParameterSet (an SSP parameter set, .ssv)");
    ParameterValues out;
    read_parameter_set(root, ssv, out.values, out.places);
    return out;
}

// The system's own connectors: parameters only, each typed, each name once and without a '.'.
void read_system_parameters(const xmlNode* system, SystemDescription& out, const std::filesystem::path& file) {
    for_children(first_child(system, "Connectors"), "Connector", [&](const xmlNode* k) {
        const std::string where = file.string() + ":" + std::to_string(k->line);
        SystemParameter p;
        p.name = required(k, "name", file);
        p.place = where;
        const std::string kind = required(k, "kind", file);
        if (kind != "parameter")
            throw CosimError(where + ": system connector '" + p.name + "' is of kind " + kind +
                             ": a system's own connectors may only be parameters here (kind=\"parameter\")");
        if (p.name.empty() || p.name.find_first_of(".= ") != std::string::npos)
            throw CosimError(where + ": system parameter name '" + p.name +
                             "' must be non-empty without '.', '=' or spaces ('.' separates component and variable)");
        const xmlNode* t = type_child(k);
        if (!t || is(t, "Binary"))
            throw CosimError(where + ": system parameter '" + p.name +
                             "' needs its type: <ssc:Real unit=\"..\"/>, Integer, Boolean, String or Enumeration");
        p.type = reinterpret_cast<const char*>(t->name);
        p.unit = attribute(t, "unit").value_or("");
        if (find_system_parameter(out, p.name))
            throw CosimError(where + ": a second system parameter named '" + p.name + "' (first at " +
                             find_system_parameter(out, p.name)->place + ")");
        out.parameters.push_back(std::move(p));
    });
}

// A connection one of whose ends is the system's own connector (its element left out): a system parameter
// feeding a component's parameter, in either order of start and end.
void read_feed(const ConnectionDescription& c, SystemDescription& out) {
    if (c.start_element.empty() && c.end_element.empty())
        throw CosimError(c.place + ": a connection between two connectors of the system itself (" + c.start_connector +
                         ", " + c.end_connector + ") is not supported");
    const bool from_start = c.start_element.empty();
    ParameterFeed f{from_start ? c.start_connector : c.end_connector, from_start ? c.end_element : c.start_element,
                    from_start ? c.end_connector : c.start_connector, c.place};
    if (!find_system_parameter(out, f.parameter)) {
        std::vector<std::string> names;
        for (const auto& p : out.parameters) names.push_back(p.name);
        throw CosimError(c.place + ": the system has no parameter connector '" + f.parameter + "'" +
                         name_hint(f.parameter, names) + " (declare it in the system's <ssd:Connectors>)");
    }
    for (const auto& other : out.feeds)
        if (other.component == f.component && other.variable == f.variable)
            throw CosimError(c.place + ": " + f.component + "." + f.variable + " is fed twice (by '" + other.parameter +
                             "' at " + other.place + " and by '" + f.parameter + "')");
    out.feeds.push_back(std::move(f));
}

int int_attribute(const xmlNode* n, const char* name, int fallback, int lo, int hi, const std::filesystem::path& file) {
    const auto text = attribute(n, name);
    if (!text) return fallback;
    const int x = parse_integer(*text, file.string() + ":" + std::to_string(n->line) + ": " + name);
    if (x < lo || x > hi)
        throw CosimError(file.string() + ":" + std::to_string(n->line) + ": " + name + " = " + *text + " is outside [" +
                         std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return x;
}

BridgeDescription parse_bridge(const xmlNode* b, const std::filesystem::path& file) {
    const std::string where = file.string() + ":" + std::to_string(b->line);
    BridgeDescription d;
    d.transport = attribute(b, "transport").value_or(d.transport);
    d.host = attribute(b, "host").value_or(d.host);
    d.device = attribute(b, "device").value_or("");
    d.policy = attribute(b, "policy").value_or(d.policy);
    d.port = int_attribute(b, "port", d.port, 0, 65535, file);
    d.baud = int_attribute(b, "baud", d.baud, 1, 4000000, file);
    d.timeout_ms = int_attribute(b, "timeout_ms", d.timeout_ms, 1, 60000, file);
    d.max_misses = int_attribute(b, "max_misses", d.max_misses, 1, 1000000, file);
    if (d.transport != "udp" && d.transport != "serial")
        throw CosimError(where + ": bridge transport '" + d.transport + "' is neither udp nor serial");
    if (d.transport == "serial" && d.device.empty()) throw CosimError(where + ": a serial bridge needs device=\"...\"");
    if (d.policy != "hold" && d.policy != "stop")
        throw CosimError(where + ": bridge policy '" + d.policy + "' is neither hold nor stop");
    return d;
}

std::optional<BridgeDescription> read_bridge(const xmlNode* component, const std::filesystem::path& file) {
    std::optional<BridgeDescription> out;
    for_children(first_child(component, "Annotations"), "Annotation", [&](const xmlNode* a) {
        if (attribute(a, "type").value_or("") != hardware_bridge_annotation) return;
        const xmlNode* b = first_child(a, "Bridge");
        if (!b)
            throw CosimError(file.string() + ":" + std::to_string(a->line) +
                             ": a hardware-bridge annotation needs a <Bridge> element");
        out = parse_bridge(b, file);
    });
    return out;
}

// The element `element` of the annotation of `type` under n's <Annotations>, or null.
const xmlNode* annotation(const xmlNode* n, const char* type, const char* element) {
    const xmlNode* found = nullptr;
    for_children(first_child(n, "Annotations"), "Annotation", [&](const xmlNode* a) {
        if (!found && attribute(a, "type").value_or("") == type) found = first_child(a, element);
    });
    return found;
}

double positive_attribute(const xmlNode* n, const char* name, const std::filesystem::path& file) {
    const std::string where = file.string() + ":" + std::to_string(n->line) + ": " + name;
    const double x = parse_real(required(n, name, file), where);
    if (!(x > 0.0) || !std::isfinite(x)) throw CosimError(where + " must be positive and finite");
    return x;
}

ExecutionHint parse_execution(const xmlNode* e, const std::filesystem::path& file) {
    ExecutionHint hint;
    const std::string kind = required(e, "interface", file);
    if (kind != "CoSimulation" && kind != "ModelExchange")
        throw CosimError(file.string() + ":" + std::to_string(e->line) + ": interface '" + kind +
                         "' is neither ModelExchange nor CoSimulation");
    hint.co_simulation = kind == "CoSimulation";
    if (attribute(e, "communicationStep")) hint.communication_step = positive_attribute(e, "communicationStep", file);
    return hint;
}

std::optional<ExecutionHint> read_execution(const xmlNode* component, const std::filesystem::path& file) {
    const xmlNode* e = annotation(component, execution_annotation, "Execution");
    if (!e) return std::nullopt;
    return parse_execution(e, file);
}

// A component's execution hint or bridge written among the system's annotations, with a component
// attribute naming it (where `cosim pack` puts them: OMSimulator 2.1.3 refuses annotations in a component).
void read_system_level_hints(const xmlNode* system, SystemDescription& out, const std::filesystem::path& file) {
    for_children(first_child(system, "Annotations"), "Annotation", [&](const xmlNode* a) {
        const std::string type = attribute(a, "type").value_or("");
        const bool execution = type == execution_annotation, bridge = type == hardware_bridge_annotation;
        if (!execution && !bridge) return;
        for_children(a, execution ? "Execution" : "Bridge", [&](const xmlNode* e) {
            const std::string where = file.string() + ":" + std::to_string(e->line);
            const std::string name = required(e, "component", file);
            const auto c = std::find_if(out.components.begin(), out.components.end(),
                                        [&](const ComponentDescription& d) { return d.name == name; });
            if (c == out.components.end()) throw CosimError(where + ": no component named '" + name + "'");
            if (execution ? c->execution.has_value() : c->bridge.has_value())
                throw CosimError(where + ": component '" + name + "' has a second " + type + " annotation");
            if (execution)
                c->execution = parse_execution(e, file);
            else
                c->bridge = parse_bridge(e, file);
        });
    });
}

}  // namespace

ParameterValues read_parameter_values(const std::filesystem::path& ssv) {
    if (!std::filesystem::exists(ssv)) throw CosimError(ssv.string() + ": no such parameter file");
    return read_parameter_file(ssv);
}

const SystemParameter* find_system_parameter(const SystemDescription& d, const std::string& name) {
    for (const auto& p : d.parameters)
        if (p.name == name) return &p;
    return nullptr;
}

SystemDescription read_system_description(const std::filesystem::path& path) {
    if (!std::filesystem::exists(path)) throw CosimError(path.string() + ": no such file");
    std::shared_ptr<const fmi_loader::FmuArchive> archive;
    std::filesystem::path ssd = path;
    if (path.extension() == ".ssp") {
        try {
            archive = std::make_shared<const fmi_loader::FmuArchive>(path);
        } catch (const std::exception& e) {
            throw CosimError(path.string() + ": not a usable SSP archive: " + e.what());
        }
        ssd = archive->directory() / "SystemStructure.ssd";
        if (!std::filesystem::is_regular_file(ssd))
            throw CosimError(path.string() + ": no SystemStructure.ssd at the archive's root (SSP 1.0 section 5)");
    }
    const Doc doc = parse_file(ssd);
    const xmlNode* root = xmlDocGetRootElement(doc.get());
    if (!is(root, "SystemStructureDescription"))
        throw CosimError(ssd.string() + ": the root element is not ssd:SystemStructureDescription");
    const xmlNode* system = first_child(root, "System");
    if (!system) throw CosimError(ssd.string() + ": no <ssd:System>");

    SystemDescription out;
    out.file = ssd;
    out.archive = std::move(archive);
    out.name = required(system, "name", ssd);
    read_system_parameters(system, out, ssd);
    read_bindings(system, ssd, out.archive.get(), out.system_bindings.values, out.system_bindings.places,
                  out.parameter_files);
    for (const xmlNode* e = first_child(system, "Elements") ? first_child(system, "Elements")->children : nullptr; e;
         e = e->next) {
        if (e->type != XML_ELEMENT_NODE) continue;
        if (!is(e, "Component"))
            throw CosimError(ssd.string() + ":" + std::to_string(e->line) + ": <" +
                             reinterpret_cast<const char*>(e->name) +
                             "> elements are not supported (only flat systems of components)");
        ComponentDescription c;
        c.name = required(e, "name", ssd);
        c.source = required(e, "source", ssd);
        for_children(first_child(e, "Connectors"), "Connector", [&](const xmlNode* k) {
            ConnectorDescription conn;
            conn.name = required(k, "name", ssd);
            conn.kind = parse_kind(required(k, "kind", ssd), ssd, k->line);
            if (const xmlNode* t = type_child(k)) {
                conn.type = reinterpret_cast<const char*>(t->name);
                conn.unit = attribute(t, "unit").value_or("");
            }
            c.connectors.push_back(std::move(conn));
        });
        read_bindings(e, ssd, out.archive.get(), c.parameters, c.parameter_places, out.parameter_files);
        c.bridge = read_bridge(e, ssd);
        c.execution = read_execution(e, ssd);
        out.components.push_back(std::move(c));
    }
    for_children(first_child(system, "Connections"), "Connection", [&](const xmlNode* k) {
        ConnectionDescription conn;
        conn.start_element = attribute(k, "startElement").value_or("");
        conn.start_connector = required(k, "startConnector", ssd);
        conn.end_element = attribute(k, "endElement").value_or("");
        conn.end_connector = required(k, "endConnector", ssd);
        conn.place = ssd.string() + ":" + std::to_string(k->line);
        if (conn.start_element.empty() || conn.end_element.empty())
            read_feed(conn, out);
        else
            out.connections.push_back(std::move(conn));
    });
    // A system parameter that feeds nothing would take a --set and change nothing.
    for (const auto& p : out.parameters)
        if (std::none_of(out.feeds.begin(), out.feeds.end(),
                         [&](const ParameterFeed& f) { return f.parameter == p.name; }))
            throw CosimError(p.place + ": system parameter '" + p.name +
                             "' is connected to no component parameter (add an <ssd:Connection> without startElement "
                             "from it)");
    read_system_level_hints(system, out, ssd);
    if (const xmlNode* ex = first_child(root, "DefaultExperiment")) {
        if (auto s = attribute(ex, "startTime")) out.start_time = parse_real(*s, ssd.string() + ": startTime");
        if (auto s = attribute(ex, "stopTime")) out.stop_time = parse_real(*s, ssd.string() + ": stopTime");
        if (const xmlNode* o = annotation(ex, execution_annotation, "Output"))
            out.output_interval = positive_attribute(o, "interval", ssd);
        if (const xmlNode* i = annotation(ex, execution_annotation, "Integrator"))
            out.max_step = positive_attribute(i, "maxStep", ssd);
        if (const xmlNode* st = annotation(ex, execution_annotation, "Stop"))
            out.stop_orbits = positive_attribute(st, "orbits", ssd);
        if (const xmlNode* me = annotation(ex, execution_annotation, "Measures")) {
            SystemDescription::Measures m;
            std::istringstream words(required(me, "report", ssd));
            for (std::string w; words >> w;) m.report.push_back(w);
            if (attribute(me, "convergedAfter")) m.converged_after = positive_attribute(me, "convergedAfter", ssd);
            out.measures = std::move(m);
        }
    }
    return out;
}

}  // namespace cosim

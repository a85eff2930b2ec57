#include "engine/ssp_archive.hpp"

#include <libxml/parser.h>
#include <libxml/tree.h>
#include <zip.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <string>

#include "engine/cosim_error.hpp"
#include "engine/output_file.hpp"
#include "engine/setting.hpp"
#include "engine/value_text.hpp"
#include "fmi_loader/fmu_archive.hpp"
#include "fmi_loader/model_description.hpp"

namespace cosim {

std::filesystem::path resolve_fmu(const SystemDescription& description, const std::string& source,
                                  const std::vector<std::filesystem::path>& fmu_dirs) {
    // An .ssp is a closed world: its FMUs are inside it or the system is refused, never taken elsewhere.
    if (description.archive) return inside_archive(*description.archive, source, "component source");
    if (auto found = find_fmu(description, source, fmu_dirs)) return *found;
    std::string where;
    for (const auto& t : fmu_candidates(description, source, fmu_dirs)) where += "\n  " + t.string();
    throw CosimError(description.file.string() + ": FMU '" + source + "' not found; looked at:" + where);
}

std::vector<std::filesystem::path> fmu_candidates(const SystemDescription& description, const std::string& source,
                                                  const std::vector<std::filesystem::path>& fmu_dirs) {
    std::filesystem::path p = source;
    if (source.starts_with("file:")) p = source.substr(source.starts_with("file://") ? 7 : 5);
    std::vector<std::filesystem::path> out;
    auto add = [&](const std::filesystem::path& candidate) {
        // Absolute and normalized, each once: the default FMU folder given again as --fmu-dir is one place.
        const auto full = std::filesystem::absolute(candidate).lexically_normal();
        if (std::find(out.begin(), out.end(), full) == out.end()) out.push_back(full);
    };
    if (p.is_absolute()) {
        add(p);
    } else {
        add(description.file.parent_path() / p);
        for (const auto& dir : fmu_dirs) {
            add(dir / p);
            add(dir / p.filename());
        }
    }
    return out;
}

std::optional<std::filesystem::path> find_fmu(const SystemDescription& description, const std::string& source,
                                              const std::vector<std::filesystem::path>& fmu_dirs) {
    for (const auto& c : fmu_candidates(description, source, fmu_dirs))
        if (std::filesystem::is_regular_file(c)) return c;
    return std::nullopt;
}

void check_fmus_found(const SystemDescription& description, const std::vector<std::filesystem::path>& fmu_dirs) {
    if (description.archive) return;  // resolve_fmu refuses what the archive lacks, one by one
    std::vector<std::string> missing;
    std::vector<std::filesystem::path> folders;
    for (const auto& c : description.components) {
        if (std::find(missing.begin(), missing.end(), c.source) != missing.end()) continue;
        if (find_fmu(description, c.source, fmu_dirs)) continue;
        missing.push_back(c.source);
        for (const auto& candidate : fmu_candidates(description, c.source, fmu_dirs))
            if (std::find(folders.begin(), folders.end(), candidate.parent_path()) == folders.end())
                folders.push_back(candidate.parent_path());
    }
    if (missing.empty()) return;
    std::string text = description.file.string() + ": " + std::to_string(missing.size()) +
                       (missing.size() == 1 ? " FMU" : " FMUs") + " not found:";
    for (const auto& m : missing) text += " " + m;
    text += "; looked in:";
    for (const auto& f : folders) text += "\n  " + f.string();
    text += "\n(build them, or give the folder that holds them with --fmu-dir)";
    throw CosimError(text);
}

std::vector<std::filesystem::path> system_inputs(const SystemDescription& description,
                                                 const std::vector<std::filesystem::path>& fmu_dirs) {
    if (description.archive) return {description.archive->fmu_path()};  // the rest is unpacked from it
    std::vector<std::filesystem::path> inputs{description.file};
    for (const auto& c : description.components) inputs.push_back(resolve_fmu(description, c.source, fmu_dirs));
    inputs.insert(inputs.end(), description.parameter_files.begin(), description.parameter_files.end());
    return inputs;
}

namespace {

struct DocDeleter {
    void operator()(xmlDoc* d) const { xmlFreeDoc(d); }
};
struct XmlFree {
    void operator()(xmlChar* p) const { xmlFree(p); }
};

bool named(const xmlNode* n, const char* local) {
    return n->type == XML_ELEMENT_NODE && xmlStrcmp(n->name, reinterpret_cast<const xmlChar*>(local)) == 0;
}

const xmlChar* x(const char* s) {
    return reinterpret_cast<const xmlChar*>(s);
}

std::optional<std::string> property(const xmlNode* n, const char* name) {
    std::unique_ptr<xmlChar, XmlFree> v(xmlGetProp(n, x(name)));
    if (!v) return std::nullopt;
    return std::string(reinterpret_cast<const char*>(v.get()));
}

std::vector<xmlNode*> element_children(xmlNode* n, const char* local = nullptr) {
    std::vector<xmlNode*> out;
    for (xmlNode* c = n ? n->children : nullptr; c; c = c->next)
        if (c->type == XML_ELEMENT_NODE && (!local || named(c, local))) out.push_back(c);
    return out;
}

xmlNode* element_child(xmlNode* n, const char* local) {
    const auto all = element_children(n, local);
    return all.empty() ? nullptr : all.front();
}

constexpr const char* ssc_namespace = "http://ssp-standard.org/SSP1/SystemStructureCommon";
constexpr const char* ssv_namespace = "http://ssp-standard.org/SSP1/SystemStructureParameterValues";
// OMSimulator matches its annotation by these literal names (it reads the XML without namespaces).
constexpr const char* oms_namespace =
    "https://raw.githubusercontent.com/OpenModelica/OMSimulator/master/schema/oms.xsd";

// A binding of an Enumeration parameter by item name, as ssv:Integer with the item's value: SSP 1.0 binds
// an Enumeration by name, but OMSimulator 2.1.3 reads only Real, Integer and Boolean bindings, and an
// FMI 2.0 Enumeration is set through fmi2SetInteger by every importer.
void bind_enumerations_by_value(xmlNode* component, const fmi_loader::ModelDescription& md, const std::string& where) {
    for (xmlNode* binding : element_children(element_child(component, "ParameterBindings"), "ParameterBinding"))
        for (xmlNode* set : element_children(element_child(binding, "ParameterValues"), "ParameterSet"))
            for (xmlNode* p : element_children(element_child(set, "Parameters"), "Parameter")) {
                const auto name = property(p, "name");
                const fmi_loader::ScalarVariable* v = name ? md.find_variable(*name) : nullptr;
                if (!v || v->type != fmi_loader::VariableType::enumeration) continue;
                for (xmlNode* value : element_children(p)) {
                    if (!named(value, "String") && !named(value, "Enumeration")) continue;
                    const int item =
                        parse_enumeration(md, *v, property(value, "value").value_or(""), where + ": " + *name);
                    xmlNodeSetName(value, x("Integer"));
                    xmlUnsetProp(value, x("name"));
                    xmlSetProp(value, x("value"), x(std::to_string(item).c_str()));
                }
            }
}

// The system's parameters resolved into the components' bindings, for importers that do not connect a
// system's parameter connectors (OMSimulator 2.1.3 takes a system connector only under a plain identifier,
// [a-zA-Z][a-zA-Z0-9_]*: "inertia[1] -> env.inertia[1]" is refused as a causality mismatch). Each component
// parameter a system parameter feeds gets the system's value as its own binding, and each system binding
// of a component.variable (SSP's hierarchical name) becomes that component's, after its own (later wins,
// as cosim applies them); the system's connectors, bindings and feeding connections are removed. Run by
// cosim, the archive gives the same values to the same variables.
// The <ssv:Parameters> of the component's inline parameter set, made when it has none. One inline set per
// component: OMSimulator 2.1.3 keeps only the last of several inline bindings of a component.
xmlNode* own_parameters(xmlNode* component, xmlNs* ssd, xmlNs* ssv) {
    xmlNode* bindings = element_child(component, "ParameterBindings");
    for (xmlNode* binding : element_children(bindings, "ParameterBinding"))
        if (xmlNode* set = element_child(element_child(binding, "ParameterValues"), "ParameterSet")) {
            if (xmlNode* parameters = element_child(set, "Parameters")) return parameters;
            return xmlNewChild(set, ssv, x("Parameters"), nullptr);
        }
    if (!bindings) {
        bindings = xmlNewNode(ssd, x("ParameterBindings"));
        // After Connectors (and ElementGeometry), before Annotations (TComponent's order).
        xmlNode* after = element_child(component, "ElementGeometry");
        if (!after) after = element_child(component, "Connectors");
        if (after)
            xmlAddNextSibling(after, bindings);
        else if (component->children)
            xmlAddPrevSibling(component->children, bindings);
        else
            xmlAddChild(component, bindings);
    }
    xmlNode* binding = xmlNewChild(bindings, ssd, x("ParameterBinding"), nullptr);
    xmlNode* values = xmlNewChild(binding, ssd, x("ParameterValues"), nullptr);
    xmlNode* set = xmlNewChild(values, ssv, x("ParameterSet"), nullptr);
    xmlSetProp(set, x("version"), x("1.0"));
    xmlSetProp(set, x("name"), x("system_parameters"));
    return xmlNewChild(set, ssv, x("Parameters"), nullptr);
}

void flatten_system_parameters(xmlDoc* doc, xmlNode* system, const SystemDescription& description) {
    if (description.parameters.empty() && description.system_bindings.values.empty()) return;
    xmlNode* root = xmlDocGetRootElement(doc);
    xmlNs* ssd = system->ns;
    xmlNs* ssv = xmlSearchNsByHref(doc, root, x(ssv_namespace));
    if (!ssv) ssv = xmlNewNs(root, x(ssv_namespace), x("ssv"));
    std::map<std::string, xmlNode*> parameters_of;  // component -> the <ssv:Parameters> added to it
    auto add = [&](const std::string& component, const std::string& variable, const Setting& value,
                   const std::string& unit) {
        xmlNode* target = nullptr;
        for (xmlNode* c : element_children(element_child(system, "Elements"), "Component"))
            if (property(c, "name").value_or("") == component) target = c;
        if (!target) throw CosimError(description.file.string() + ": no component named '" + component + "'");
        xmlNode*& parameters = parameters_of[component];
        if (!parameters) parameters = own_parameters(target, ssd, ssv);
        xmlNode* p = xmlNewChild(parameters, ssv, x("Parameter"), nullptr);
        xmlSetProp(p, x("name"), x(variable.c_str()));
        const std::string type = value.ssv_type.empty() ? "String" : value.ssv_type;
        xmlNode* v = xmlNewChild(p, ssv, x(type.c_str()), nullptr);
        if (!unit.empty() && type == "Real") xmlSetProp(v, x("unit"), x(unit.c_str()));
        xmlSetProp(v, x("value"), x(value.value.c_str()));
    };
    // Each system parameter's value: its last system binding.
    const auto& bound = description.system_bindings.values;
    for (const auto& f : description.feeds) {
        const Setting* value = nullptr;
        for (const auto& b : bound)
            if (b.variable == f.parameter) value = &b;
        const SystemParameter* p = find_system_parameter(description, f.parameter);
        if (!value)
            throw CosimError(p->place + ": system parameter '" + f.parameter +
                             "' has no value in the system's bindings; an archive carries it as one");
        add(f.component, f.variable, *value, p->unit);
    }
    for (const auto& b : bound) {
        if (find_system_parameter(description, b.variable)) continue;
        const auto split = split_variable_name(b.variable);
        if (!split) throw CosimError(description.file.string() + ": system binding '" + b.variable + "' names nothing");
        add(split->component, split->variable, b, "");
    }
    for (const char* gone : {"Connectors", "ParameterBindings"})
        if (xmlNode* n = element_child(system, gone)) {
            xmlUnlinkNode(n);
            xmlFreeNode(n);
        }
    for (xmlNode* c : element_children(element_child(system, "Connections"), "Connection"))
        if (!property(c, "startElement") || !property(c, "endElement")) {
            xmlUnlinkNode(c);
            xmlFreeNode(c);
        }
}

// A String binding that repeats its variable's start value changes nothing, for any importer: it is left
// out, because OMSimulator 2.1.3 reads no ssv:String binding and counts each one as an error. A String
// binding that changes a value stays (cosim needs it; pack_system names it on its report).
std::vector<std::string> drop_start_value_strings(xmlNode* component, const fmi_loader::ModelDescription& md) {
    std::vector<std::string> kept;
    for (xmlNode* binding : element_children(element_child(component, "ParameterBindings"), "ParameterBinding"))
        for (xmlNode* set : element_children(element_child(binding, "ParameterValues"), "ParameterSet"))
            for (xmlNode* p : element_children(element_child(set, "Parameters"), "Parameter")) {
                const auto name = property(p, "name");
                const fmi_loader::ScalarVariable* v = name ? md.find_variable(*name) : nullptr;
                xmlNode* value = element_child(p, "String");
                if (!v || v->type != fmi_loader::VariableType::string || !value) continue;
                if (v->start && property(value, "value").value_or("") == *v->start) {
                    xmlUnlinkNode(p);
                    xmlFreeNode(p);
                } else {
                    kept.push_back(*name);
                }
            }
    return kept;
}

// The components' annotations moved into the system's <Annotations>, each element tagged with its
// component's name (system_description.cpp reads both places).
void lift_component_annotations(xmlNode* system, xmlNode* system_annotations, xmlNs* ssc) {
    for (xmlNode* component : element_children(element_child(system, "Elements"), "Component")) {
        xmlNode* annotations = element_child(component, "Annotations");
        if (!annotations) continue;
        const std::string name = property(component, "name").value_or("");
        for (xmlNode* a : element_children(annotations, "Annotation")) {
            const std::string type = property(a, "type").value_or("");
            xmlNode* lifted = xmlNewChild(system_annotations, ssc, x("Annotation"), nullptr);
            xmlSetProp(lifted, x("type"), x(type.c_str()));
            for (xmlNode* e : element_children(a)) {
                xmlUnlinkNode(e);
                xmlSetProp(e, x("component"), x(name.c_str()));
                xmlAddChild(lifted, e);
            }
        }
        xmlUnlinkNode(annotations);
        xmlFreeNode(annotations);
    }
}

// OMSimulator's SimulationInformation, first among the system's annotations (OMSimulator 2.1.3 looks
// at the first only): a weakly coupled co-simulation of the FMUs' Co-Simulation interfaces.
void add_omsimulator_annotation(xmlNode* system_annotations, xmlNs* ssc, double step) {
    xmlNode* a = xmlNewNode(ssc, x("Annotation"));
    xmlSetProp(a, x("type"), x("org.openmodelica"));
    xmlNode* root = xmlNewChild(a, nullptr, x("Annotations"), nullptr);
    xmlNs* oms = xmlNewNs(root, x(oms_namespace), x("oms"));
    xmlSetNs(root, oms);
    xmlNode* info = xmlNewChild(root, oms, x("SimulationInformation"), nullptr);
    xmlNode* master = xmlNewChild(info, oms, x("FixedStepMaster"), nullptr);
    xmlSetProp(master, x("description"), x("oms-ma"));
    xmlSetProp(master, x("stepSize"), x(format_real(step).c_str()));
    xmlSetProp(master, x("absoluteTolerance"), x("1e-06"));
    xmlSetProp(master, x("relativeTolerance"), x("1e-06"));
    if (system_annotations->children)
        xmlAddPrevSibling(system_annotations->children, a);
    else
        xmlAddChild(system_annotations, a);
}

// The archive entry of a parameter file the .ssd binds: resources/<its file name>.
std::string parameter_entry(const SystemDescription& description, const std::string& source) {
    return "resources/" + (description.file.parent_path() / source).filename().string();
}

// Rewrites the parsed .ssd of `description` for the archive (see pack_system).
void make_portable(xmlDoc* doc, const SystemDescription& description,
                   const std::map<std::string, std::string>& source_of,
                   const std::map<std::string, fmi_loader::ModelDescription>& model_of, double oms_step,
                   std::vector<std::string>& strings_kept) {
    xmlNode* root = xmlDocGetRootElement(doc);
    xmlNode* system = element_child(root, "System");
    if (!system) throw CosimError(description.file.string() + ": no <ssd:System>");
    flatten_system_parameters(doc, system, description);
    for (xmlNode* component : element_children(element_child(system, "Elements"), "Component")) {
        const std::string name = property(component, "name").value_or("");
        if (const auto it = source_of.find(name); it != source_of.end())
            xmlSetProp(component, x("source"), x(it->second.c_str()));
        if (const auto it = model_of.find(name); it != model_of.end()) {
            bind_enumerations_by_value(component, it->second, description.file.string() + ": component " + name);
            for (const auto& kept : drop_start_value_strings(component, it->second))
                strings_kept.push_back(name + "." + kept);
        }
        for (xmlNode* binding : element_children(element_child(component, "ParameterBindings"), "ParameterBinding"))
            if (const auto source = property(binding, "source"))
                xmlSetProp(binding, x("source"), x(parameter_entry(description, *source).c_str()));
    }
    xmlNs* ssc = xmlSearchNsByHref(doc, root, x(ssc_namespace));
    if (!ssc) ssc = xmlNewNs(root, x(ssc_namespace), x("ssc"));
    xmlNode* annotations = element_child(system, "Annotations");  // the last child of a System (SSP 1.0)
    if (!annotations) annotations = xmlNewChild(system, system->ns, x("Annotations"), nullptr);
    lift_component_annotations(system, annotations, ssc);
    bool has_oms = false;
    for (xmlNode* a : element_children(annotations, "Annotation"))
        has_oms = has_oms || property(a, "type").value_or("") == "org.openmodelica";
    if (!has_oms) add_omsimulator_annotation(annotations, ssc, oms_step);
    xmlReconciliateNs(doc, root);
}

std::string zip_reason(zip_t* z) {
    const char* s = z ? zip_strerror(z) : nullptr;
    return s ? s : "unknown libzip error";
}

}  // namespace

void pack_system(const std::filesystem::path& ssd, const std::filesystem::path& ssp, const PackOptions& options,
                 std::ostream& out) {
    const auto& fmu_dirs = options.fmu_dirs;
    const SystemDescription description = read_system_description(ssd);
    if (description.archive) throw CosimError(ssd.string() + " is an SSP archive already");
    refuse_overwriting_inputs("-o", ssp, system_inputs(description, fmu_dirs));
    if (std::error_code ec; std::filesystem::exists(ssp, ec) && !std::filesystem::is_regular_file(ssp, ec))
        throw CosimError("-o " + ssp.string() + ": not a regular file (an archive is written beside it and renamed)");
    // The FMUs by the name they get in the archive; two different files of one name would collide.
    std::map<std::string, std::string> source_of;                  // component -> resources/<file>
    std::map<std::string, std::filesystem::path> file_of_entry;    // resources/<file> -> FMU on disk
    std::map<std::string, fmi_loader::ModelDescription> model_of;  // component -> its FMU's description
    std::optional<double> step = options.oms_step, smallest_fmu_step;
    for (const auto& c : description.components) {
        const auto fmu = resolve_fmu(description, c.source, fmu_dirs);
        const fmi_loader::FmuArchive unpacked(fmu);
        auto md = fmi_loader::read_model_description(unpacked.model_description_path());
        if (md.default_experiment && md.default_experiment->step_size && *md.default_experiment->step_size > 0.0)
            smallest_fmu_step = std::min(smallest_fmu_step.value_or(*md.default_experiment->step_size),
                                         *md.default_experiment->step_size);
        model_of.emplace(c.name, std::move(md));
        if (!options.oms_step && c.execution && c.execution->co_simulation && c.execution->communication_step)
            step = std::min(step.value_or(*c.execution->communication_step), *c.execution->communication_step);
        const std::string entry = "resources/" + fmu.filename().string();
        const auto [it, inserted] = file_of_entry.emplace(entry, fmu);
        if (!inserted && !same_file(it->second, fmu))
            throw CosimError(ssd.string() + ": two different FMUs are named " + fmu.filename().string() + " (" +
                             it->second.string() + ", " + fmu.string() + ")");
        source_of[c.name] = entry;
    }

    // The parameter files travel too, under the name make_portable() gives their bindings.
    for (const auto& ssv : description.parameter_files) {
        const std::string entry = "resources/" + ssv.filename().string();
        const auto [it, inserted] = file_of_entry.emplace(entry, ssv);
        if (!inserted && !same_file(it->second, ssv))
            throw CosimError(ssd.string() + ": two different files are named " + ssv.filename().string() + " (" +
                             it->second.string() + ", " + ssv.string() + ")");
    }

    if (!step) step = smallest_fmu_step;
    if (!step || !(*step > 0.0) || !std::isfinite(*step))
        throw CosimError(ssd.string() + ": no communication step for OMSimulator (give --oms-step)");

    // The .ssd as written but made portable (make_portable): libxml2 keeps comments and namespaces.
    std::unique_ptr<xmlDoc, DocDeleter> doc(
        xmlReadFile(ssd.c_str(), nullptr, XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING));
    if (!doc) throw CosimError(ssd.string() + ": cannot be parsed");
    std::vector<std::string> strings_kept;
    make_portable(doc.get(), description, source_of, model_of, *step, strings_kept);
    xmlChar* text = nullptr;
    int size = 0;
    xmlDocDumpFormatMemoryEnc(doc.get(), &text, &size, "UTF-8", 0);
    if (!text || size <= 0) throw CosimError(ssd.string() + ": cannot be serialized");
    const std::unique_ptr<xmlChar, XmlFree> xml(text);

    PendingFile pending(ssp);
    const auto& partial = pending.path();
    int error = 0;
    zip_t* z = zip_open(partial.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
    if (!z) {
        zip_error_t e;
        zip_error_init_with_code(&e, error);
        const std::string reason = zip_error_strerror(&e);
        zip_error_fini(&e);
        throw CosimError("cannot create " + partial.string() + ": " + reason);
    }
    auto fail = [&](const std::string& what) {
        const std::string reason = zip_reason(z);
        zip_discard(z);
        throw CosimError(ssp.string() + ": " + what + ": " + reason);
    };
    zip_source_t* src = zip_source_buffer(z, xml.get(), static_cast<zip_uint64_t>(size), 0);
    if (!src || zip_file_add(z, "SystemStructure.ssd", src, ZIP_FL_ENC_UTF_8) < 0) {
        if (src) zip_source_free(src);
        fail("cannot add SystemStructure.ssd");
    }
    for (const auto& [entry, file] : file_of_entry) {
        zip_source_t* f = zip_source_file(z, file.c_str(), 0, 0);
        const zip_int64_t index = f ? zip_file_add(z, entry.c_str(), f, ZIP_FL_ENC_UTF_8) : -1;
        if (index < 0) {
            if (f) zip_source_free(f);
            fail("cannot add " + file.string());
        }
        if (entry.ends_with(".fmu") &&
            zip_set_file_compression(z, static_cast<zip_uint64_t>(index), ZIP_CM_STORE, 0) < 0)
            fail("cannot store " + entry);
        out << "  " << entry << "  <- " << file.string() << "\n";
    }
    // zip_close writes everything (and reports a full disk); the buffer above lives until it returns.
    if (zip_close(z) < 0) fail("writing the archive failed");
    pending.commit();
    out << ssp.string() << ": SystemStructure.ssd and " << file_of_entry.size() << " files (OMSimulator step "
        << format_real(*step) << " s)\n";
    for (const auto& name : strings_kept)
        out << "  note: " << name << " is bound as ssv:String, which OMSimulator 2.1.3 does not read\n";
}

}  // namespace cosim

#include "ssp_archive.hpp"

#include <libxml/parser.h>
#include <libxml/tree.h>
#include <zip.h>

#include <map>
#include <memory>
#include <string>

#include "cosim_error.hpp"

namespace cosim {

std::filesystem::path resolve_fmu(const SystemDescription& description, const std::string& source,
                                  const std::vector<std::filesystem::path>& fmu_dirs) {
    std::filesystem::path p = source;
    if (source.starts_with("file:")) p = source.substr(source.starts_with("file://") ? 7 : 5);
    std::vector<std::filesystem::path> tried;
    auto found = [&](const std::filesystem::path& candidate) {
        tried.push_back(candidate);
        return std::filesystem::is_regular_file(candidate);
    };
    if (p.is_absolute()) {
        if (found(p)) return p;
    } else {
        if (auto beside = description.file.parent_path() / p; found(beside)) return beside;
        for (const auto& dir : fmu_dirs) {
            if (found(dir / p)) return dir / p;
            if (found(dir / p.filename())) return dir / p.filename();
        }
    }
    std::string where;
    for (const auto& t : tried) where += "\n  " + t.string();
    throw CosimError(description.file.string() + ": FMU '" + source + "' not found; looked at:" + where);
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

// Every ssd:Component below `n` (systems may nest), its source rewritten from the map name -> new source.
void rewrite_sources(xmlNode* n, const std::map<std::string, std::string>& by_name) {
    for (xmlNode* c = n; c; c = c->next) {
        if (named(c, "Component")) {
            std::unique_ptr<xmlChar, XmlFree> name(xmlGetProp(c, reinterpret_cast<const xmlChar*>("name")));
            if (name) {
                const auto it = by_name.find(reinterpret_cast<const char*>(name.get()));
                if (it != by_name.end())
                    xmlSetProp(c, reinterpret_cast<const xmlChar*>("source"),
                               reinterpret_cast<const xmlChar*>(it->second.c_str()));
            }
        }
        if (c->children) rewrite_sources(c->children, by_name);
    }
}

std::string zip_reason(zip_t* z) {
    const char* s = z ? zip_strerror(z) : nullptr;
    return s ? s : "unknown libzip error";
}

}  // namespace

void pack_system(const std::filesystem::path& ssd, const std::filesystem::path& ssp,
                 const std::vector<std::filesystem::path>& fmu_dirs, std::ostream& out) {
    const SystemDescription description = read_system_description(ssd);
    if (description.archive) throw CosimError(ssd.string() + " is an SSP archive already");
    // The FMUs by the name they get in the archive; two different files of one name would collide.
    std::map<std::string, std::string> source_of;                // component -> resources/<file>
    std::map<std::string, std::filesystem::path> file_of_entry;  // resources/<file> -> FMU on disk
    for (const auto& c : description.components) {
        const auto fmu = resolve_fmu(description, c.source, fmu_dirs);
        const std::string entry = "resources/" + fmu.filename().string();
        const auto [it, inserted] = file_of_entry.emplace(entry, fmu);
        if (!inserted && std::filesystem::canonical(it->second) != std::filesystem::canonical(fmu))
            throw CosimError(ssd.string() + ": two different FMUs are named " + fmu.filename().string() + " (" +
                             it->second.string() + ", " + fmu.string() + ")");
        source_of[c.name] = entry;
    }

    // The .ssd as written, but for the sources: libxml2 keeps comments, annotations and namespaces.
    std::unique_ptr<xmlDoc, DocDeleter> doc(
        xmlReadFile(ssd.c_str(), nullptr, XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING));
    if (!doc) throw CosimError(ssd.string() + ": cannot be parsed");
    rewrite_sources(xmlDocGetRootElement(doc.get()), source_of);
    xmlChar* text = nullptr;
    int size = 0;
    xmlDocDumpFormatMemoryEnc(doc.get(), &text, &size, "UTF-8", 0);
    if (!text || size <= 0) throw CosimError(ssd.string() + ": cannot be serialized");
    const std::unique_ptr<xmlChar, XmlFree> xml(text);

    const auto partial = std::filesystem::path(ssp.string() + ".partial");
    std::filesystem::remove(partial);
    int error = 0;
    zip_t* z = zip_open(partial.c_str(), ZIP_CREATE | ZIP_EXCL, &error);
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
        std::filesystem::remove(partial);
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
        if (zip_set_file_compression(z, static_cast<zip_uint64_t>(index), ZIP_CM_STORE, 0) < 0)
            fail("cannot store " + entry);
        out << "  " << entry << "  <- " << file.string() << "\n";
    }
    // zip_close writes everything (and reports a full disk); the buffer above lives until it returns.
    if (zip_close(z) < 0) fail("writing the archive failed");
    std::error_code ec;
    std::filesystem::rename(partial, ssp, ec);
    if (ec) {
        std::filesystem::remove(partial);
        throw CosimError("cannot move " + partial.string() + " to " + ssp.string() + ": " + ec.message());
    }
    out << ssp.string() << ": SystemStructure.ssd and " << file_of_entry.size() << " FMUs\n";
}

}  // namespace cosim

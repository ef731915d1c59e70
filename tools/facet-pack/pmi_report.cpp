// facet-pack --annotations PACK: a pack's annotations as JSON lines, for scripts and tests.
#include "pmi_report.h"

#include "core/format.h"
#include "geom/pack.h"
#include "geom/pmi.h"
#include "pack_io.h"

#include <cstdio>
#include <string>

namespace facet::packer {
namespace {

// UTF-8 text as a JSON string's contents (quotes, backslashes and control characters escaped).
std::string json_text(const char* s) {
    std::string out;
    for (; *s; ++s) {
        const unsigned char c = static_cast<unsigned char>(*s);
        if (c == '"' || c == '\\') out += '\\', out += char(c);
        else if (c < 0x20) {
            char e[8];
            std::snprintf(e, sizeof e, "\\u%04x", c);
            out += e;
        } else out += char(c);
    }
    return out;
}

} // namespace

int print_annotations(const char* path, std::string& error) {
    geom::LoadedPack file;
    if (!geom::load_pack_file(path, file, error)) return 1;
    geom::Pack pack;
    geom::Annotations pmi;
    Result r = pack.open(file.data(), file.bytes);
    if (r.ok()) r = pmi.open(pack);
    if (!r.ok()) {
        char text[160];
        describe(r, text, sizeof text);
        error = std::string(path) + ": " + text;
        return 1;
    }
    for (uint32_t i = 0; i < pmi.count(); ++i) {
        const pack::Annotation& a = pmi[i];
        std::string faces;
        for (uint32_t f : pmi.faces(i)) faces += (faces.empty() ? "" : ", ") + std::to_string(f);
        std::printf("{\"index\": %u, \"kind\": \"%s\", \"type\": %u, \"semantic\": %s, \"presented\": %s, \"repeat\": %s, \"text\": \"%s\", "
                    "\"value\": %.9g, \"lower\": %.9g, \"upper\": %.9g, \"material\": %u, \"faces\": [%s], \"drawn_by\": %d, "
                    "\"polylines\": %u, \"coarse_polylines\": %u, \"anchor\": [%.9g, %.9g, %.9g]}\n",
                    i, geom::annotation_kind_name(pack::AnnotationKind(a.kind)), a.type, a.flags & pack::kSemantic ? "true" : "false",
                    a.flags & pack::kPresented ? "true" : "false", a.flags & pack::kRepeat ? "true" : "false", json_text(pmi.text(i)).c_str(), a.value, a.lower, a.upper, a.material,
                    faces.c_str(), a.drawn_by == pack::kNoIndex ? -1 : int(a.drawn_by), a.polyline_count, a.coarse_count, a.anchor[0],
                    a.anchor[1], a.anchor[2]);
    }
    return 0;
}

} // namespace facet::packer

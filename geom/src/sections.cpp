#include "geom/sections.h"

#include "geom/pack.h"
#include "geom/pack_index.h"

namespace facet::geom {

SectionTable SectionTable::of(const Pack& pack) {
    if (pack.faces().empty()) return {};
    const pack::Header& h = pack.header();
    const auto* base = reinterpret_cast<const uint8_t*>(&h);
    return {base, h.total_bytes, {reinterpret_cast<const pack::SectionEntry*>(base + sizeof h), h.section_count}};
}

SectionTable SectionTable::of(const PackIndex& index) {
    if (index.parts().empty()) return {};
    const pack::IndexHeader& h = index.header();
    const auto* base = reinterpret_cast<const uint8_t*>(&h);
    return {base, h.index_bytes, {reinterpret_cast<const pack::SectionEntry*>(base + sizeof h), h.section_count}};
}

const char* SectionTable::problem(const pack::SectionEntry& s, uint32_t record_bytes) const {
    if (s.record_bytes != record_bytes) return "record size does not match this reader";
    const uint64_t table_end = uint64_t(reinterpret_cast<const uint8_t*>(entries.data() + entries.size()) - base);
    if ((s.offset & 3) || s.offset < table_end || uint64_t(s.offset) + uint64_t(s.count) * record_bytes > bytes) {
        return "section lies outside the pack or is not 4-byte aligned";
    }
    return nullptr;
}

} // namespace facet::geom

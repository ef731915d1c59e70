#pragma once
// Sections appended to a pack made in code (its table, offsets and CRC made again): the optional
// sections a test gives a shape (annotations, an assembly tree), whole or made to lie.
#include "geom/pack_format.h"

#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <vector>

namespace facet::test {

struct Section {
    uint32_t id;
    std::vector<uint8_t> bytes;
    uint32_t count, record_bytes;
};

template <typename Id, typename T>
Section section(Id id, const std::vector<T>& records) {
    const auto* p = reinterpret_cast<const uint8_t*>(records.data());
    return {uint32_t(id), std::vector<uint8_t>(p, p + records.size() * sizeof(T)), uint32_t(records.size()), uint32_t(sizeof(T))};
}

inline std::vector<uint8_t> with_sections(const std::vector<uint8_t>& pack_bytes, std::initializer_list<Section> sections) {
    pack::Header h;
    std::memcpy(&h, pack_bytes.data(), sizeof h);
    std::vector<pack::SectionEntry> table(h.section_count);
    std::memcpy(table.data(), pack_bytes.data() + sizeof h, table.size() * sizeof(pack::SectionEntry));
    const uint32_t old_head = uint32_t(sizeof h + table.size() * sizeof(pack::SectionEntry));
    const uint32_t shift = uint32_t(sections.size() * sizeof(pack::SectionEntry));
    for (pack::SectionEntry& e : table) e.offset += shift;
    std::vector<uint8_t> body(pack_bytes.begin() + old_head, pack_bytes.end());
    for (const Section& s : sections) {
        table.push_back({s.id, uint32_t(old_head + shift + body.size()), s.count, s.record_bytes});
        body.insert(body.end(), s.bytes.begin(), s.bytes.end());
        body.resize((body.size() + 3) & ~size_t(3), 0);
    }
    std::vector<uint8_t> out(sizeof h);
    const auto* tb = reinterpret_cast<const uint8_t*>(table.data());
    out.insert(out.end(), tb, tb + table.size() * sizeof(pack::SectionEntry));
    out.insert(out.end(), body.begin(), body.end());
    h.section_count = uint32_t(table.size()), h.total_bytes = uint32_t(out.size());
    h.crc32 = pack::crc32(out.data() + sizeof h, uint32_t(out.size() - sizeof h));
    std::memcpy(out.data(), &h, sizeof h);
    return out;
}

} // namespace facet::test

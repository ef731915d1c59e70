#pragma once
// Reading a pack in place (zero-copy) after validating all of it.
//
//   geom::Pack pack;
//   if (Result r = pack.open(data, size); !r.ok()) print(con, "pack: {}\n", r);
//       -> "pack: section Faces record 12: surface index out of range"
//
// open() checks the header, the CRC, every section's bounds and record size, every index
// against its target's count, every surface's and curve's parameter layout, and that every
// float is finite. Nothing is read before it is checked, so a corrupt pack can only produce a
// status and a message naming the bad record, never a crash.
#include "geom/pack_format.h"
#include "core/status.h"

#include <cstdint>
#include <span>

namespace facet::geom {

class Pack {
public:
    // Corrupt, with the bad record as the place (section_place), unless every check passes.
    Result open(const void* data, uint32_t size);
    // The same bytes moved (a memmove) to `to`: every record read there from now on, without
    // checking them again (they were where they lay). A few instructions, not an open().
    void moved(const void* to);

    const pack::Header& header() const { return *header_; }
    std::span<const float> floats() const { return floats_; }
    std::span<const pack::Surface> surfaces() const { return surfaces_; }
    std::span<const pack::Curve> curves3() const { return curves3_; }
    std::span<const pack::Curve> curves2() const { return curves2_; }
    std::span<const pack::Vertex> vertices() const { return vertices_; }
    std::span<const pack::Edge> edges() const { return edges_; }
    std::span<const pack::Coedge> coedges() const { return coedges_; }
    std::span<const pack::Loop> loops() const { return loops_; }
    std::span<const pack::Face> faces() const { return faces_; }
    std::span<const pack::Shell> shells() const { return shells_; }
    std::span<const pack::Instance> instances() const { return instances_; }
    std::span<const pack::Colour> colours() const { return colours_; }
    // Names from the STEP file (pack_format.h): "" when the pack has none.
    const char* model_name() const { return names_.empty() ? "" : names_.data(); }
    std::span<const char> names() const { return names_; } // the pool (checked: its last name ends in a 0 byte)
    const char* shell_name(uint32_t s) const { return name_at(shell_names_, s); }
    const char* instance_name(uint32_t i) const { return name_at(instance_names_, i); }
    // Whether edge e's two faces meet tangentially (SmoothEdges; false when the pack says nothing).
    bool smooth_edge(uint32_t e) const { return e / 32 < smooth_.size() && (smooth_[e / 32] >> (e % 32)) & 1u; }
    // What the model takes on a device (Needs), measured by the packer; null when the pack says nothing.
    const pack::Needs* needs() const { return needs_.empty() ? nullptr : needs_.data(); }

    // The pcurve of coedge c (one of face F's) on F's surface; kNoIndex if F has none.
    uint32_t pcurve_of(const pack::Face& F, uint32_t c) const {
        return F.first_pcurve == pack::kNoIndex ? pack::kNoIndex : F.first_pcurve + (c - loops_[F.first_loop].first_coedge);
    }

    // The parameters of a surface or curve (validated by open()).
    std::span<const float> params(uint32_t first, uint32_t count) const {
        return floats_.subspan(first, count);
    }

private:
    Result fail(const char* what, uint32_t section, uint32_t index);
    Result check_records();
    Result check_names();
    const char* name_at(std::span<const uint32_t> table, uint32_t i) const {
        return i < table.size() && table[i] != pack::kNoIndex ? names_.data() + table[i] : "";
    }

    const pack::Header* header_ = nullptr;
    std::span<const float> floats_;
    std::span<const pack::Surface> surfaces_;
    std::span<const pack::Curve> curves3_, curves2_;
    std::span<const pack::Vertex> vertices_;
    std::span<const pack::Edge> edges_;
    std::span<const pack::Coedge> coedges_;
    std::span<const pack::Loop> loops_;
    std::span<const pack::Face> faces_;
    std::span<const pack::Shell> shells_;
    std::span<const pack::Instance> instances_;
    std::span<const pack::Colour> colours_;
    std::span<const char> names_;
    std::span<const uint32_t> shell_names_, instance_names_;
    std::span<const uint32_t> smooth_;
    std::span<const pack::Needs> needs_;
};

// Expected parameter count of a surface or curve from its head (B-splines) or type; 0 if the
// head itself is invalid. `avail` floats start at `p`.
uint32_t surface_param_count(uint8_t type, const float* p, uint32_t avail);
uint32_t curve_param_count(uint8_t type, uint8_t dim, const float* p, uint32_t avail);

const char* section_name(uint32_t id);
// The place of record `index` of section `id` ("section Faces record" 12; id 0: "header").
Place section_place(uint32_t id, uint32_t index);

} // namespace facet::geom

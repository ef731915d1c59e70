// The UART protocol's records (facet/records.h): the one place their words are written.
#include "facet/records.h"

#include "core/format.h"

namespace facet {
namespace {

uint32_t um(float mm) { return uint32_t(mm * 1000 + 0.5f); }
int32_t rounded(float v) { return int32_t(v + (v >= 0 ? 0.5f : -0.5f)); }

template <typename... Args>
uint32_t line(char* out, uint32_t size, const char* fmt, const Args&... args) {
    return uint32_t(format(out, size, fmt, args...));
}

} // namespace

uint32_t event_record(const Event& e, char* out, uint32_t size) {
    using Kind = Event::Kind;
    switch (e.kind) {
    case Kind::Loaded: {
        const auto& l = e.loaded;
        return line(out, size, "@model faces {} edges {} shells {} instances {} bytes {} file_bytes {} boxed_parts {} boxed_faces {}\n",
                    l.faces, l.edges, l.shells, l.instances, l.pack_bytes, l.file_bytes, l.boxed_parts, l.boxed_faces);
    }
    case Kind::Pass: return line(out, size, "@pass {} tolerance_um {}\n", e.pass.pass, um(e.pass.tolerance_mm));
    case Kind::Sampled: return line(out, size, "@lod tolerance_um {} samples {}\n", um(e.pass.tolerance_mm), e.pass.samples);
    case Kind::Progress: {
        const auto& p = e.progress;
        return line(out, size, "@progress {}/{} triangles {}\n", p.done + p.failed, p.total, p.triangles);
    }
    case Kind::FaceFailed:
        return line(out, size, "@face {} failed: {} ({}); it stays wireframe\n", e.failed.face, e.why, e.why.status);
    case Kind::Tessellated: {
        const auto& t = e.tessellated;
        return line(out, size, "@{} faces {} failed {} triangles {} vertices {} mesh_bytes {} arena_peak {} tolerance_um {}\n",
                    t.pass == 0 ? "tessellation" : "retessellation", t.faces, t.failed, t.triangles, t.vertices, t.mesh_bytes,
                    t.arena_peak_bytes, um(t.tolerance_mm));
    }
    case Kind::FrameDone: {
        const auto& f = e.frame;
        if (!f.full) return 0; // (a band or an update: no frame of its own)
        return line(out, size, "@frame triangles {} culled {} pixels {} pieces {} cost_us {}\n", f.triangles, f.culled, f.pixels,
                    f.pieces, f.cost_us);
    }
    case Kind::ViewChanged:
        return line(out, size, "@view yaw {} pitch {} zoom_pct {}\n", rounded(e.view.yaw_deg), rounded(e.view.pitch_deg),
                    uint32_t(100.0f / e.view.zoom + 0.5f));
    case Kind::Picked: {
        const auto& p = e.pick;
        if (!p.hit) return line(out, size, "@pick hit 0 x {} y {}\n", p.x, p.y);
        return line(out, size, "@pick hit 1 face {} instance {} shell {} surface_type {} x {} y {}\n", p.face, p.instance, p.shell,
                    p.surface_type, p.x, p.y);
    }
    case Kind::BudgetExceeded:
        return line(out, size, "@budget {} used_us {} budget_us {}\n", e.budget.step ? "step" : "frame", e.budget.used_us,
                    e.budget.budget_us);
    case Kind::PassFailed:
        return line(out, size, "@pass_failed tolerance_um {} {} {}\n", um(e.pass.tolerance_mm), e.why.status, e.why);
    case Kind::ModelFailed: return line(out, size, "@model_failed {} {} {}\n", e.model.index + 1, e.why.status, e.why);
    case Kind::WorkBegin:
    case Kind::WorkEnd: break;
    }
    if (size) out[0] = '\0';
    return 0;
}

uint32_t load_failed_record(const Result& why, char* out, uint32_t size) {
    return line(out, size, "@load_failed {} {}\n", why.status, why);
}

uint32_t memory_record(const Stats& s, char* out, uint32_t size) {
    return line(out, size, "@memory pack_bytes {} pack_file_bytes {} storage_peak_bytes {}\n", s.pack_bytes, s.pack_file_bytes,
                s.workspace_peak_bytes);
}

uint32_t stats_record(const Stats& s, char* out, uint32_t size) {
    return line(out, size, "@stats faces {} done {} failed {} deferred {} triangles {} refused {}\n", s.faces, s.done, s.failed,
                s.deferred, s.triangles, s.refused);
}

} // namespace facet

// facet-records-check: every record the module's writer (facet/records.h) makes, with the
// largest values each field can hold and a reason of the longest kind, one per line on stdout,
// for tests/tools/protocol_test.py to read back through tools/protocol.py's table.
#include "facet/records.h"

#include <cstdio>
#include <cstring>

namespace {

constexpr uint32_t kMax = 0xFFFFFFFFu;

int fails = 0;

void put(uint32_t length, const char* line) {
    if (length >= facet::kRecordBytes || length != std::strlen(line)) {
        std::fprintf(stderr, "records_check: a record of %u bytes does not fit %u: %s\n", length, facet::kRecordBytes, line);
        ++fails;
    }
    std::fputs(line, stdout);
}

} // namespace

int main() {
    using facet::Event;
    using Kind = Event::Kind;
    char line[facet::kRecordBytes];
    // The longest reason: a long text at two places of long names.
    const facet::Result why = facet::Result::fail(facet::Status::OutOfRange, "the loop's points are not all in the surface's domain",
                                                  {"section Faces record", kMax - 1}, {"loop", kMax - 1});
    for (uint8_t k = 0; k <= uint8_t(Kind::ModelFailed); ++k) {
        Event e{};
        e.kind = Kind(k);
        e.why = why;
        switch (e.kind) {
        case Kind::Loaded: e.loaded = {kMax, kMax, kMax, kMax, kMax, kMax, kMax, kMax}; break;
        case Kind::Pass:
        case Kind::Sampled:
        case Kind::PassFailed: e.pass = {kMax, 4000.0f, kMax}; break;
        case Kind::Progress: e.progress = {kMax / 2, kMax / 2, kMax, kMax}; break;
        case Kind::FaceFailed: e.failed = {kMax}; break;
        case Kind::Tessellated: e.tessellated = {0, kMax, kMax, kMax, kMax, kMax, kMax, 4000.0f}; break;
        case Kind::FrameDone: e.frame = {kMax, kMax, kMax, kMax, kMax, kMax, kMax, kMax, true, false}; break;
        case Kind::BudgetExceeded: e.budget = {true, kMax, kMax}; break;
        case Kind::Picked: e.pick = {true, kMax, kMax, kMax, 255, -32768, -32768}; break;
        case Kind::ViewChanged: e.view = {-179.6f, 89.6f, 0.05f}; break;
        case Kind::ModelFailed: e.model = {kMax - 1}; break;
        default: break;
        }
        if (uint32_t n = facet::event_record(e, line, sizeof line)) put(n, line);
        if (e.kind == Kind::Tessellated) { // a later pass: @retessellation
            e.tessellated.pass = 1;
            put(facet::event_record(e, line, sizeof line), line);
        }
        if (e.kind == Kind::Picked) { // nothing under the point
            e.pick.hit = false;
            put(facet::event_record(e, line, sizeof line), line);
        }
    }
    facet::Stats s{};
    s.faces = s.done = s.failed = s.deferred = s.triangles = s.refused = kMax;
    s.pack_bytes = s.pack_file_bytes = s.workspace_peak_bytes = kMax;
    put(facet::memory_record(s, line, sizeof line), line);
    put(facet::stats_record(s, line, sizeof line), line);
    put(facet::load_failed_record(why, line, sizeof line), line);
    // A buffer too small: cut, NUL-terminated, the full length returned.
    char small[8];
    const uint32_t full = facet::memory_record(s, small, sizeof small);
    if (full < sizeof small || std::strlen(small) != sizeof small - 1) {
        std::fprintf(stderr, "records_check: a record cut to %zu bytes: length %u, '%s'\n", sizeof small, full, small);
        ++fails;
    }
    return fails ? 1 : 0;
}

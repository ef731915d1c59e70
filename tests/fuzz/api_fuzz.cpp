// libFuzzer target for the public C API (facet/facet.h) used as an application might misuse it:
// the input is a display size and a sequence of calls, each with values taken from a dictionary
// of extremes (0, -0, the smallest and largest floats, infinities, NaN, the range's ends, indices
// past the counts), over several packs (plain and blocked, a library of them) built in code.
// Every call must return (a status where it has one), nothing may overflow (UBSan), read or
// write outside its buffers (ASan) or loop for ever (the step budget: libFuzzer's timeout).
#include "../geom/shapes.h"
#include "../viewer/packs.h"
#include "facet/facet.h"
#include "pack_blocks.h"
#include "pack_io.h"

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

using namespace facet;
using namespace facet::test;

namespace {

// Shapes of every surface kind, one part each, blocked a part a block.
Bytes blocked_shapes() {
    const Bytes shapes[] = {plate_with_holes(), sphere(), torus(), trimmed_bspline()};
    std::vector<geom::Pack> packs(4);
    for (int k = 0; k < 4; ++k) (void)packs[k].open(shapes[k].data(), uint32_t(shapes[k].size()));
    const Bytes whole = combine_packs(packs, 150.0f);
    geom::Pack p;
    if (!p.open(whole.data(), uint32_t(whole.size())).ok()) return whole;
    std::vector<geom::PartBox> boxes(p.shells().size());
    for (geom::PartBox& b : boxes)
        for (int k = 0; k < 3; ++k) b.min[k] = p.header().bbox_min[k], b.max[k] = p.header().bbox_max[k];
    Bytes out;
    std::string error;
    return geom::make_blocked(p, boxes, {1, geom::BlockStore::Lzma}, out, error) ? out : whole;
}

// The models, made once: a plain pack, an LZMA one, a blocked assembly, and a library of them.
struct Models {
    std::vector<std::vector<uint64_t>> files; // 8-byte aligned copies
    std::vector<uint32_t> sizes;
    std::vector<uint64_t> library;
    uint32_t library_bytes = 0;
    uint32_t memory_bytes = 0; // pack memory enough for any of them
    Models() {
        const std::vector<Bytes> made = {polygon_and_triangle(40), geom::lzma_pack(disc()), blocked_shapes(), tube(), two_blocks()};
        for (const Bytes& b : made) {
            files.emplace_back(b.size() / 8 + 1, 0);
            std::memcpy(files.back().data(), b.data(), b.size());
            sizes.push_back(uint32_t(b.size()));
            memory_bytes = std::max(memory_bytes, facet_pack_memory_bytes(b.data(), uint32_t(b.size())));
        }
        Bytes lib;
        std::string error;
        if (geom::make_library(made, lib, error)) {
            library.assign(lib.size() / 8 + 1, 0);
            std::memcpy(library.data(), lib.data(), lib.size());
            library_bytes = uint32_t(lib.size());
        }
    }
};

const float kFloats[] = {0.0f, -0.0f, 1.0f, -1.0f, 0.5f, 2.0f, 45.0f, -90.0f, 180.0f, 360.0f, 0.05f, 20.0f, 1e-38f, -1e-38f,
                         1e7f, -1e7f, 1e30f, -1e30f, FLT_MAX, -FLT_MAX, FLT_MIN, std::numeric_limits<float>::denorm_min(),
                         std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                         std::numeric_limits<float>::quiet_NaN(), 100.0f, -100.0f, 6400.0f, -6400.0f, 0.0625f, 16.0f, 8191.9f};
const uint32_t kInts[] = {0, 1, 2, 3, 5, 7, 9, 100, 255, 256, 65535, 65536, 0x7FFFFFFFu, 0x80000000u, 0xFFFFFFFEu, 0xFFFFFFFFu};
const int16_t kShorts[] = {0, 1, -1, 5, 60, -60, 120, 239, 240, 479, 32767, -32768, 200, -200, 12, 3};
constexpr std::pair<uint16_t, uint16_t> kSizes[] = {{160, 120}, {1, 1}, {2, 300}, {300, 2}, {480, 272}, {64, 48}};

// The input, read a byte at a time (zeros past its end).
struct Reader {
    const uint8_t* p;
    size_t n;
    uint8_t byte() { return n ? (--n, *p++) : 0; }
    float f() { return kFloats[byte() % (sizeof kFloats / sizeof kFloats[0])]; }
    uint32_t u() { return kInts[byte() % (sizeof kInts / sizeof kInts[0])]; }
    int16_t s() { return kShorts[byte() % (sizeof kShorts / sizeof kShorts[0])]; }
};

void flush(facet_viewer*, void*, const facet_area*, const facet_rgb565*) {}
void on_event(void*, const facet_event*) {}
uint32_t clock_us(void* user) { return (*static_cast<uint32_t*>(user) += 700); }

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static Models models;
    Reader in{data, size};
    const auto [w, h] = kSizes[in.byte() % (sizeof kSizes / sizeof kSizes[0])];
    const uint8_t shape = in.byte();
    const uint16_t lines = (shape & 1) ? uint16_t(std::max(1, h / 4)) : h; // bands or whole frames
    std::vector<facet_rgb565> buf[2] = {std::vector<facet_rgb565>(size_t(w) * h), std::vector<facet_rgb565>(size_t(w) * h)};
    std::vector<uint16_t> depth[2] = {std::vector<uint16_t>(size_t(w) * h), std::vector<uint16_t>(size_t(w) * h)};
    std::vector<facet_rgb565> layer((shape & 2) && lines == h ? size_t(w) * h : 0);
    std::vector<uint16_t> layer_depth(layer.size());
    facet_config cfg;
    facet_config_init(&cfg);
    uint32_t now = 0;
    cfg.display.width = w, cfg.display.height = h, cfg.display.band_lines = lines;
    cfg.display.buffers[0] = buf[0].data(), cfg.display.buffers[1] = (shape & 4) ? buf[1].data() : nullptr;
    cfg.display.depth[0] = depth[0].data(), cfg.display.depth[1] = (shape & 4) ? depth[1].data() : nullptr;
    cfg.display.faces = layer.empty() ? nullptr : layer.data(), cfg.display.faces_depth = layer.empty() ? nullptr : layer_depth.data();
    cfg.display.flush = flush;
    cfg.on_event = on_event;
    if (shape & 8) cfg.now_us = clock_us, cfg.clock_user = &now;
    cfg.interface = facet_interface((shape >> 4) % 3);
    static std::vector<uint64_t> workspace(facet_workspace_bytes(nullptr) / 8 + 1);
    facet_result why;
    facet_viewer* v = facet_create(&cfg, workspace.data(), workspace.size() * 8, &why);
    if (!v) return 0;
    std::vector<uint64_t> memory(models.memory_bytes / 8 + 1);
    const uint32_t m = in.byte() % models.files.size();
    (void)facet_load(v, models.files[m].data(), models.sizes[m], memory.data(), uint32_t(memory.size() * 8));
    facet_face_facts facts[2] = {};
    for (int calls = 0; in.n && calls < 200; ++calls) {
        switch (in.byte() % 40) {
        case 0: (void)facet_step(v, in.u() % 20000); break;
        case 1: facet_flush_done(v); break;
        case 2: facet_key(v, in.u()); break;
        case 3: facet_pointer(v, in.s(), in.s(), in.byte()); break;
        case 4: facet_wheel(v, int8_t(in.byte())); break;
        case 5: facet_touch(v, in.byte() % 4, in.s(), in.s(), in.byte() & 1); break;
        case 6: facet_act(v, facet_action(in.byte())); break;
        case 7: {
            facet_orbit o = {in.f(), in.f(), in.f(), {in.f(), in.f()}, (in.byte() & 1) != 0};
            (void)facet_set_orbit(v, &o);
            break;
        }
        case 8: (void)facet_show_view(v, facet_standard_view(in.byte() % 10)); break;
        case 9: facet_fit(v); break;
        case 10: (void)facet_fit_part(v, in.u()); break;
        case 11: (void)facet_fit_face(v, in.u(), in.u()); break;
        case 12: facet_set_parallel(v, in.byte() & 1); break;
        case 13: (void)facet_set_display_mode(v, facet_display_mode(in.byte() % 8)); break;
        case 14: (void)facet_set_detail(v, in.f()); break;
        case 15: facts[in.byte() & 1] = facet_pick(v, in.s(), in.s()); break;
        case 16: (void)facet_get_face(v, in.u(), in.u(), &facts[in.byte() & 1]); break;
        case 17: (void)facet_select(v, in.u(), in.u()); break;
        case 18: (void)facet_measure(v, &facts[0], &facts[1]); break;
        case 19: (void)facet_show_part(v, in.u(), in.byte() & 1); break;
        case 20: (void)facet_isolate_part(v, in.u()); break;
        case 21: (void)facet_choose_part(v, in.u()); break;
        case 22: {
            facet_section s = {(in.byte() & 1) != 0, {in.f(), in.f(), in.f()}, in.f()};
            (void)facet_set_section(v, &s);
            break;
        }
        case 23: (void)facet_section_through(v, in.u(), in.u()); break;
        case 24: (void)facet_section_across(v, in.byte()); break;
        case 25: (void)facet_move_section(v, in.f()); break;
        case 26: facet_set_measuring(v, in.byte() & 1); break;
        case 27: facet_set_tangent_edges(v, in.byte() & 1); break;
        case 28: facet_clear_selection(v); break;
        case 29: facet_show_all_parts(v); break;
        case 30: facet_unload(v); break;
        case 31: {
            const uint32_t k = in.byte() % models.files.size();
            (void)facet_load(v, models.files[k].data(), models.sizes[k], memory.data(), uint32_t(memory.size() * 8));
            break;
        }
        case 32:
            if (models.library_bytes) {
                (void)facet_set_library(v, models.library.data(), models.library_bytes, memory.data(), uint32_t(memory.size() * 8));
            }
            break;
        case 33: (void)facet_open_model(v, in.u()); break;
        case 34: {
            char text[64];
            const facet_result r = facet_set_detail(v, in.f());
            (void)facet_describe(&r, (in.byte() & 1) ? text : nullptr, (in.byte() & 1) ? sizeof text : in.u());
            break;
        }
        case 35: {
            const char* got[3];
            (void)facet_get_measurement_lines(v, got);
            (void)facet_get_stats(v), (void)facet_get_model(v), (void)facet_get_camera(v), (void)facet_get_orbit(v);
            break;
        }
        case 36: (void)facet_get_part(v, in.u()); break;
        default: // a run of steps, each flush taken (most of what an application does)
            for (int k = 0; k < 8; ++k) {
                facet_flush_done(v);
                if (facet_step(v, 5000) == FACET_ACTIVITY_IDLE) break;
            }
            break;
        }
    }
    return 0;
}

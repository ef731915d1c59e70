// Picking: the face under a screen pixel, as drawn (the same transforms, culling and
// projection as the frame; the nearest triangle that covers the pixel's centre), its exact
// facts, the selection (a tap's, or select()'s) and measuring between two faces.
#include "core.h"
#include "geom/measure.h"

#include <cstdlib>

namespace facet {

void Core::tap(int16_t x, int16_t y) {
    // A tap on a toolbar button is the button's.
    if (const Action a = presenter_.overlay().button_at(x, y); a != Action::None) {
        act(a);
        return;
    }
    if (presenter_.overlay().help_button().contains(x, y)) return act(Action::TangentEdges); // the help panel's button
    if (presenter_.overlay().name_at(x, y)) return toggle_models(); // the model's name, with a library: the chooser
    if (tap_parts(x, y) || tap_pmi(x, y) || tap_models(x, y)) return; // the parts list's, the annotations', the models chooser's
    if (const uint32_t a = presenter_.annotating().label_at(x, y); a != kNone) { // an annotation's label: it is chosen
        (void)choose_annotation(a);
        return;
    }
    const Event e = pick_at(x, y);
    if (e.pick.hit) (void)select(e.pick.instance, e.pick.face); // (a face drawn is one select() takes)
    else clear_selection();
    // A second tap where the first one was, soon after (or, without a clock, right after):
    // frame the tapped face.
    const uint32_t t = now();
    const bool again = std::abs(x - tap_x_) <= kDoubleTapSlop && std::abs(y - tap_y_) <= kDoubleTapSlop &&
                       (!config_.now_us || t - tap_t_ <= kDoubleTapUs);
    tap_x_ = x, tap_y_ = y, tap_t_ = t;
    emit(e);
    if (again && e.pick.hit) {
        tap_x_ = tap_y_ = -1000; // a third tap starts again
        glide_to(camera_.view(), e.pick.instance, e.pick.face);
    }
}

Result Core::check_part(uint32_t part) const {
    if (!scene_.loaded()) return Result::fail(Status::NotFound, "no model is loaded");
    if (part >= scene_.instances().size()) return Result::fail(Status::OutOfRange, "no such part", {"part", part});
    return {};
}

Result Core::check_face(uint32_t part, uint32_t face) const {
    if (const Result r = check_part(part); !r.ok()) return r;
    const module::Part sh = scene_.part(scene_.instances()[part].shell);
    if (face < sh.first_face || face >= sh.first_face + sh.face_count) {
        return Result::fail(Status::OutOfRange, "the face is not one of the part's", {"face", face}, {"part", part});
    }
    if (scene_.face(face).state == module::FaceState::Absent) { // its block is not decoded: no exact geometry at hand
        return Result::fail(Status::NotFound, "the face's part is left out (drawn as its proxy) until the view brings it in", {"face", face});
    }
    return {};
}

Result Core::facts(uint32_t part, uint32_t face, FaceFacts& out) const {
    out = {};
    if (const Result r = check_face(part, face); !r.ok()) return r;
    geom::FaceGeometry g;
    if (const Result r = scene_.face_geometry(face, part, g); !r.ok()) return r;
    static_assert(uint8_t(Surface::Extrusion) == uint8_t(pack::SurfaceType::Extrusion) && uint8_t(Surface::Plane) == uint8_t(pack::SurfaceType::Plane),
                  "Surface is pack::SurfaceType");
    out.hit = true, out.part = part, out.face = face;
    out.surface = Surface(uint8_t(g.type));
    out.hole = g.hole;
    const geom::D3 o = g.origin, a = g.axis;
    out.origin_mm[0] = o.x, out.origin_mm[1] = o.y, out.origin_mm[2] = o.z;
    out.axis[0] = a.x, out.axis[1] = a.y, out.axis[2] = a.z;
    out.offset_mm = g.offset, out.radius_mm = g.radius, out.minor_mm = g.minor;
    out.half_angle_deg = g.half_angle * 57.29577951308232;
    return {};
}

FaceFacts Core::pick(int16_t x, int16_t y) {
    const Event e = pick_at(x, y);
    FaceFacts f;
    if (e.pick.hit) (void)facts(e.pick.instance, e.pick.face, f); // (a face drawn is one whose block is in)
    f.x = x, f.y = y;
    return f;
}

Result Core::select(uint32_t part, uint32_t face) {
    if (const Result r = check_face(part, face); !r.ok()) return r;
    picks_.picked(true, {face, part});
    return {};
}

void Core::clear_selection() {
    if (picks_.selection().count() > 0) picks_.picked(false, {});
}

uint32_t Core::selection(FaceFacts out[2]) const {
    const module::Selection& s = picks_.selection();
    for (uint32_t i = 0; i < s.count(); ++i) (void)facts(s[i].instance, s[i].face, out[i]); // (forgotten when left out)
    return s.count();
}

void Core::set_measuring(bool on) {
    if (!scene_.loaded() || on == measuring()) return;
    picks_.set_measuring(on);
}

Measurement Core::measure(const FaceFacts& a, const FaceFacts& b) const {
    Measurement m;
    geom::FaceGeometry g[2];
    if (!a.hit || !b.hit || !check_face(a.part, a.face).ok() || !check_face(b.part, b.face).ok() ||
        !scene_.face_geometry(a.face, a.part, g[0]).ok() || !scene_.face_geometry(b.face, b.part, g[1]).ok()) {
        return m;
    }
    const geom::Relation r = geom::relate(g[0], g[1]);
    static_assert(uint8_t(Measurement::Kind::Points) == uint8_t(geom::Relation::Kind::Points), "Measurement::Kind is geom's");
    m.kind = Measurement::Kind(uint8_t(r.kind));
    m.parallel = r.parallel, m.has_distance = r.has_distance;
    m.distance_mm = r.distance, m.angle_deg = r.angle * 57.29577951308232;
    return m;
}

Event Core::pick_at(int16_t x, int16_t y) {
    Event e{};
    e.kind = Event::Kind::Picked;
    e.pick = {false, 0, 0, 0, 0, x, y};
    const Display& d = config_.display;
    if (!scene_.loaded() || x < 0 || y < 0 || x >= d.width || y >= d.height) return e;
    presenter_.projected_reused(); // a frame under way projects its face again
    const auto instances = scene_.instances();
    const int64_t sx = render::subpixel::centre(x), sy = render::subpixel::centre(y);
    float best = 1e30f;
    const module::ViewBasis basis = camera_.basis(scene_, d.width, d.height); // (once: every instance's)
    for (uint32_t i = 0; i < instances.size(); ++i) {
        if (!scene_.shown(i)) continue;
        module::Transform t = module::Camera::transform(basis, scene_, i);
        t.place_eye(); // (planes turned away are skipped)
        const module::Rows row{t.cy16 - render::subpixel::start(y), render::subpixel::start(y + 1) - t.cy16};
        const module::Part sh = scene_.part(instances[i].shell);
        for (uint32_t f = sh.first_face; f < sh.first_face + sh.face_count; ++f) {
            const module::FaceInfo& F = scene_.face(f);
            if (F.state != module::FaceState::Done || !t.visible(F.centre, F.radius, row)) continue;
            const module::DrawVertex* v = scene_.vertices() + F.first_vertex;
            if (F.planar && F.vertex_count && t.hides_plane(v[0].p, v[0].n)) continue;
            module::Projected* P = projected_.data();
            for (uint32_t k = 0; k < F.vertex_count; ++k) t.project(v[k].p, P[k]);
            const uint16_t* id = scene_.indices() + F.first_index;
            for (uint32_t k = 0; k < F.triangle_count; ++k, id += 3) {
                const module::Projected& a = P[id[0]];
                const module::Projected& b = P[t.mirrored ? id[2] : id[1]];
                const module::Projected& c = P[t.mirrored ? id[1] : id[2]];
                if (a.out | b.out | c.out) continue; // crossing the near plane: not pickable
                const int64_t area2 = render::doubled_area(a.s, b.s, c.s);
                if (area2 == 0 || (t.closed && area2 > 0)) continue; // as the rasterizer culls
                // Barycentric weights of the pixel centre (areas of the sub-triangles).
                const int64_t wa = int64_t(b.s.x - sx) * (c.s.y - sy) - int64_t(b.s.y - sy) * (c.s.x - sx);
                const int64_t wb = int64_t(c.s.x - sx) * (a.s.y - sy) - int64_t(c.s.y - sy) * (a.s.x - sx);
                const int64_t wc = area2 - wa - wb;
                const bool inside = area2 > 0 ? (wa >= 0 && wb >= 0 && wc >= 0) : (wa <= 0 && wb <= 0 && wc <= 0);
                if (!inside) continue;
                const float z = (float(wa) * a.s.z + float(wb) * b.s.z + float(wc) * c.s.z) / float(area2);
                if (t.cut.on) { // a point the section cuts away is not there to pick
                    const float side = (float(wa) * float(t.cut.side(a.x, a.y, a.d)) + float(wb) * float(t.cut.side(b.x, b.y, b.d)) +
                                        float(wc) * float(t.cut.side(c.x, c.y, c.d))) / float(area2);
                    if (side > 0) continue;
                }
                if (z < best) {
                    best = z;
                    e.pick = {true, f, i, instances[i].shell, scene_.surface_type(f), x, y};
                }
            }
        }
    }
    return e;
}

} // namespace facet

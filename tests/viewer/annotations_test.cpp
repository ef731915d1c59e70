// Annotations (PMI, issue 53) in a pack and on the screen: the reader takes them and refuses a
// record that lies; the viewer draws them over the model (and the model alone, pixel for
// pixel, when they are hidden), lists a face's, lights a chosen one's faces, and a tap on a
// label chooses it.
#include "../geom/shapes.h"
#include "app.h"
#include "sections.h"
#include "geom/pack.h"
#include "geom/pmi.h"
#include "pack_blocks.h"

#include <cmath>
#include <random>
#include <string>

using namespace facet;
using namespace facet::test;

namespace {

// The plate's faces (tests/geom/shapes.h): its top, and the larger hole's wall (radius 10).
constexpr uint32_t kTop = 0, kBottom = 1, kHole = 6;

// A pack with the tables as its annotation sections.
Bytes with_annotations(const Bytes& pack_bytes, const geom::AnnotationTables& t) {
    std::vector<char> text = t.text;
    text.resize((text.size() + 3) & ~size_t(3), 0);
    return with_sections(pack_bytes, {section(pack::PmiSectionId::Annotations, t.records), section(pack::PmiSectionId::PmiText, text),
                                      section(pack::PmiSectionId::PmiFaces, t.faces), section(pack::PmiSectionId::PmiPolylines, t.polylines),
                                      section(pack::PmiSectionId::PmiPoints, t.points)});
}

uint32_t add_text(geom::AnnotationTables& t, const char* s) {
    const uint32_t at = uint32_t(t.text.size());
    t.text.insert(t.text.end(), s, s + std::strlen(s) + 1);
    return at;
}

// The plate's PMI: the larger hole's diameter, drawn (a leader up from the hole to a line its
// text would sit on, above the plate), the top's flatness and datum A on the bottom, both
// placed at their faces (no presentation).
geom::AnnotationTables plate_pmi() {
    geom::AnnotationTables t;
    pack::Annotation d{};
    d.kind = uint8_t(pack::AnnotationKind::Dimension), d.type = uint8_t(pack::DimensionType::Diameter);
    d.flags = pack::kSemantic | pack::kPresented | pack::kHasPlane;
    d.text = add_text(t, "\u230020 \u00B10.1");
    d.first_face = uint32_t(t.faces.size()), d.face_count = 1;
    t.faces.push_back(kHole);
    const float leader[3][3] = {{37, 37, 10}, {60, 80, 40}, {110, 80, 40}};
    d.first_polyline = 0, d.polyline_count = 1, d.first_coarse = 1, d.coarse_count = 1;
    const float centre[3] = {73.5f, 58.5f, 25}, radius = 52;
    for (int copy = 0; copy < 2; ++copy) { // (fine and coarse alike: three points are all there is)
        t.polylines.push_back({uint32_t(t.points.size()), 3});
        int32_t before[3] = {0, 0, 0}; // each point's step from the one before, in radius / kStepUnits
        for (const auto& p : leader) {
            pack::PmiStep step;
            for (int k = 0; k < 3; ++k) {
                const int32_t q = int32_t(std::lround((p[k] - centre[k]) / radius * float(pack::kStepUnits)));
                step.d[k] = int16_t(q - before[k]), before[k] = q;
            }
            t.points.push_back(step);
        }
    }
    d.drawn_by = pack::kNoIndex;
    d.value = 20, d.lower = -0.1f, d.upper = 0.1f;
    const float anchor[3] = {85, 80, 40}, normal[3] = {0, 0, 1};
    std::memcpy(d.anchor, anchor, 12), std::memcpy(d.normal, normal, 12), std::memcpy(d.centre, centre, 12);
    d.radius = radius, d.stroke = 80, d.outline_count = 1;
    t.records.push_back(d);
    pack::Annotation f{};
    f.kind = uint8_t(pack::AnnotationKind::Tolerance), f.type = uint8_t(pack::ToleranceType::Flatness);
    f.flags = pack::kSemantic;
    f.text = add_text(t, "\u23E5 0.05");
    f.first_face = uint32_t(t.faces.size()), f.face_count = 1;
    t.faces.push_back(kTop);
    f.first_polyline = f.first_coarse = uint32_t(t.polylines.size());
    f.drawn_by = pack::kNoIndex, f.value = 0.05f;
    const float top[3] = {50, 8, 10};
    std::memcpy(f.anchor, top, 12);
    t.records.push_back(f);
    pack::Annotation a = f;
    a.kind = uint8_t(pack::AnnotationKind::Datum), a.type = uint8_t(pack::DatumType::Feature), a.value = 0;
    a.text = add_text(t, "A");
    a.first_face = uint32_t(t.faces.size());
    t.faces.push_back(kBottom);
    const float bottom[3] = {90, 52, 0};
    std::memcpy(a.anchor, bottom, 12);
    t.records.push_back(a);
    return t;
}

Bytes annotated_plate() { return with_annotations(plate_with_holes(), plate_pmi()); }

Result open_annotations(const Bytes& bytes, geom::Annotations& pmi) {
    std::vector<uint64_t> aligned(bytes.size() / 8 + 1);
    std::memcpy(aligned.data(), bytes.data(), bytes.size());
    static geom::Pack pack; // (the annotations read the pack's bytes: kept while they are)
    static std::vector<uint64_t> kept;
    kept = aligned;
    if (Result r = pack.open(kept.data(), uint32_t(bytes.size())); !r.ok()) return r;
    return pmi.open(pack);
}

constexpr Rgb565 kDimensionInk = rgb565(20, 70, 190), kToleranceInk = rgb565(190, 30, 40); // (annotations.cpp)

uint32_t pixels_of(const std::vector<Rgb565>& screen, Rgb565 c) {
    return uint32_t(std::count(screen.begin(), screen.end(), c));
}

// Pixels in the highlight's hue (magenta: red and blue well over green), whatever their shade.
uint32_t lit_pixels(const std::vector<Rgb565>& screen) {
    uint32_t n = 0;
    for (Rgb565 p : screen) {
        const int r = p >> 11, g = (p >> 5) & 63, b = p & 31;
        n += r >= 12 && b >= 8 && g < r && g < b;
    }
    return n;
}

// The annotated plate on the handheld's 480 x 272 screen, with facet's own interface, at rest.
bool open_on_the_handheld(App& app) {
    app.w = 480, app.h = 272, app.lines = 272;
    app.interface = Interface::Full;
    if (!app.create().ok() || !app.load(annotated_plate()).ok()) return false;
    app.run();
    return true;
}

} // namespace

TEST(Annotations, TheReaderTakesThemAndRefusesEachWayARecordLies) {
    geom::Annotations pmi;
    ASSERT_TRUE(open_annotations(annotated_plate(), pmi).ok());
    ASSERT_EQ(pmi.count(), 3u);
    EXPECT_STREQ(pmi.text(0), "\u230020 \u00B10.1");
    EXPECT_STREQ(pmi.text(1), "\u23E5 0.05");
    EXPECT_TRUE(pmi.applies_to(0, kHole) && !pmi.applies_to(0, kTop) && pmi.applies_to(1, kTop));
    EXPECT_EQ(pmi.polylines(0).size(), 1u);
    EXPECT_EQ(pmi.points(pmi.polylines(0)[0]).size(), 3u);
    geom::Annotations none;
    EXPECT_TRUE(open_annotations(plate_with_holes(), none).ok());
    EXPECT_EQ(none.count(), 0u) << "a pack without the sections has none";

    struct Lie {
        const char* what;
        void (*make)(geom::AnnotationTables&);
    };
    const Lie lies[] = {
        {"a face past the pack's", [](geom::AnnotationTables& t) { t.faces[0] = 8; }},
        {"text starting inside another", [](geom::AnnotationTables& t) { t.records[1].text = 1; }},
        {"text past the pool", [](geom::AnnotationTables& t) { t.records[1].text = 4000; }},
        {"faces past PmiFaces", [](geom::AnnotationTables& t) { t.records[2].face_count = 9; }},
        {"drawn by one after it", [](geom::AnnotationTables& t) { t.records[0].drawn_by = 2; }},
        {"a polyline of one point", [](geom::AnnotationTables& t) { t.polylines[0].point_count = 1; }},
        {"points past PmiPoints", [](geom::AnnotationTables& t) { t.polylines[1].first_point = 5; }},
        {"a point outside its sphere", [](geom::AnnotationTables& t) { t.points[1].d[2] = 32000; }}, // (its first point 4,726 below the centre)
        {"a polyline's points before the one before's", [](geom::AnnotationTables& t) { t.polylines[1].first_point = 0; }},
        {"polylines not after the annotation before's", [](geom::AnnotationTables& t) { t.records[1].first_polyline = t.records[1].first_coarse = 0; }},
        {"an unknown kind", [](geom::AnnotationTables& t) { t.records[0].kind = 4; }},
        {"an unknown tolerance type", [](geom::AnnotationTables& t) { t.records[1].type = 16; }},
        {"unknown flags", [](geom::AnnotationTables& t) { t.records[1].flags |= 16; }},
        {"presented without polylines", [](geom::AnnotationTables& t) { t.records[1].flags |= pack::kPresented; }},
        {"polylines, not presented", [](geom::AnnotationTables& t) { t.records[0].flags &= uint8_t(~pack::kPresented); }},
        {"fine polylines without coarse", [](geom::AnnotationTables& t) { t.records[0].coarse_count = 0; }},
        {"an outline past its polylines", [](geom::AnnotationTables& t) { t.records[0].outline_count = 2; }},
        {"a plane's normal not of unit length", [](geom::AnnotationTables& t) { t.records[0].normal[2] = 3; }},
        {"a value not finite", [](geom::AnnotationTables& t) { t.records[0].value = INFINITY; }},
        {"a text without its 0", [](geom::AnnotationTables& t) {
             t.text.back() = 'x';
             while (t.text.size() % 4) t.text.push_back('y'); // (no padding of 0s to end it)
         }},
        {"a text of 300 bytes", [](geom::AnnotationTables& t) {
             t.text.pop_back();
             t.text.insert(t.text.end(), 300, 'x');
             t.text.push_back(0);
         }},
    };
    for (const Lie& lie : lies) {
        geom::AnnotationTables t = plate_pmi();
        lie.make(t);
        geom::Annotations bad;
        const Result r = open_annotations(with_annotations(plate_with_holes(), t), bad);
        EXPECT_EQ(r.status, Status::Corrupt) << lie.what;
        EXPECT_EQ(bad.count(), 0u) << lie.what << ": nothing read from a pack that lies";
        // The viewer refuses the pack with the reason.
        App app;
        ASSERT_TRUE(app.create().ok());
        const Result loaded = app.load(with_annotations(plate_with_holes(), t));
        EXPECT_EQ(loaded.status, Status::Corrupt) << lie.what;
        const std::string why = text(loaded);
        EXPECT_TRUE(why.find("section Annotations") != std::string::npos || why.find("section Pmi") != std::string::npos)
            << lie.what << ": " << why;
    }
}

TEST(Annotations, MillimetresBecomeMeshUnitsAsRoundingTheExactQuotientWould) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> mm(-3000, 3000), units(1e-4f, 0.02f);
    for (int k = 0; k < 20000; ++k) {
        const float unit = units(rng), x = k % 7 == 0 ? float(k) * 0.125f : mm(rng);
        const module::Annotating::UnitScale s = module::Annotating::unit_scale(unit);
        int32_t q;
        const long double exact = (long double)x * (long double)s.m * std::ldexp(1.0L, s.e); // x times the scale's 1/unit
        const bool fits = std::fabs(exact) < (long double)(1 << 30) - 1;
        ASSERT_EQ(module::Annotating::to_units(x, s, q), fits) << x << " mm at " << unit;
        if (!fits) continue;
        ASSERT_LE(std::fabs((long double)q - exact), 0.5L) << x << " mm at " << unit << ": the nearest mesh unit";
        ASSERT_LE(std::fabs((long double)q - (long double)x / unit), 0.5L + 1e-6L * std::fabs(exact)) << "the scale is 1/unit to 32 bits";
    }
    int32_t q = 7;
    EXPECT_TRUE(module::Annotating::to_units(0.0f, module::Annotating::unit_scale(0.01f), q));
    EXPECT_EQ(q, 0);
    EXPECT_FALSE(module::Annotating::to_units(INFINITY, module::Annotating::unit_scale(0.01f), q));
    EXPECT_FALSE(module::Annotating::to_units(1e8f, module::Annotating::unit_scale(1e-4f), q)) << "2^30 units or more: left out";
}

TEST(Annotations, DrawnOverTheModelAndTheModelAloneWhenHidden) {
    App plain, annotated;
    plain.w = annotated.w = 320, plain.h = annotated.h = 240, plain.lines = annotated.lines = 240;
    ASSERT_TRUE(plain.create().ok() && annotated.create().ok());
    ASSERT_TRUE(plain.load(plate_with_holes()).ok());
    ASSERT_TRUE(annotated.load(annotated_plate()).ok());
    plain.run(), annotated.run();
    EXPECT_EQ(annotated.v->annotation_count(), 3u);
    EXPECT_EQ(annotated.v->annotations_shown(), kAllAnnotationKinds);
    const std::vector<Rgb565> model = plain.screen(), with = annotated.screen();
    EXPECT_GT(pixels_of(with, kDimensionInk), 40u) << "the diameter's leader, in the dimensions' blue";
    EXPECT_GT(pixels_of(with, kToleranceInk), 8u) << "the flatness's label (it has no presentation), in the tolerances' red";
    EXPECT_EQ(pixels_of(model, kDimensionInk) + pixels_of(model, kToleranceInk), 0u);
    // Hidden by kind: the tolerances alone, then none: the model's own picture.
    annotated.v->show_annotations(annotation_kind_bit(AnnotationKind::Tolerance));
    annotated.run();
    EXPECT_EQ(pixels_of(annotated.screen(), kDimensionInk), 0u);
    EXPECT_GT(pixels_of(annotated.screen(), kToleranceInk), 8u);
    annotated.v->show_annotations(0);
    annotated.run();
    EXPECT_TRUE(annotated.screen() == model) << "with its annotations hidden, the model's picture pixel for pixel";
    // In bands, the same picture as whole (labels placed on the screen, not the band).
    App banded;
    banded.w = 320, banded.h = 240, banded.lines = 40;
    ASSERT_TRUE(banded.create().ok());
    ASSERT_TRUE(banded.load(annotated_plate()).ok());
    banded.run();
    EXPECT_TRUE(banded.screen() == with) << "drawn band by band, the same pixels";
    // The key (r) and its action hide and show them all.
    annotated.v->act(Action::Annotations);
    EXPECT_EQ(annotated.v->annotations_shown(), kAllAnnotationKinds);
    annotated.v->key('r');
    EXPECT_EQ(annotated.v->annotations_shown(), 0u);
}

TEST(Annotations, AFaceListsItsAnnotationsAndAChosenOneLightsItsFaces) {
    App app;
    ASSERT_TRUE(open_on_the_handheld(app));
    uint32_t ids[4] = {};
    EXPECT_EQ(app.v->face_annotations(0, kHole, ids, 4), 1u);
    EXPECT_EQ(ids[0], 0u);
    EXPECT_EQ(app.v->face_annotations(0, kTop, ids, 4), 1u);
    EXPECT_EQ(ids[0], 1u);
    EXPECT_EQ(app.v->face_annotations(0, 3, ids, 4), 0u) << "a side has none";
    EXPECT_EQ(app.v->face_annotations(5, kTop, ids, 4), 0u) << "no such part";
    Viewer::Annotation a{};
    ASSERT_TRUE(app.v->annotation(0, a).ok());
    EXPECT_EQ(a.kind, AnnotationKind::Dimension);
    EXPECT_TRUE(a.semantic && a.presented);
    EXPECT_FLOAT_EQ(a.value, 20);
    ASSERT_EQ(a.face_count, 1u);
    EXPECT_EQ(a.faces[0], kHole);
    EXPECT_EQ(app.v->annotation(3, a).status, Status::OutOfRange);

    // A face picked: its facts, then its PMI.
    ASSERT_TRUE(app.v->select(0, kTop).ok());
    app.run();
    const char* lines[3] = {};
    ASSERT_EQ(app.v->measurement(lines), 2u);
    EXPECT_STREQ(lines[1], "PMI: \u23E5 0.05");

    // An annotation chosen: its faces lit, its text on the panel; none: as before.
    const std::vector<Rgb565> before = (app.v->clear_selection(), app.run(), app.screen());
    ASSERT_TRUE(app.v->choose_annotation(0).ok());
    app.run();
    EXPECT_EQ(app.v->chosen_annotation(), 0u);
    ASSERT_EQ(app.v->measurement(lines), 2u);
    EXPECT_STREQ(lines[0], "\u230020 \u00B10.1");
    EXPECT_STREQ(lines[1], "dimension, on 1 face");
    EXPECT_GT(lit_pixels(app.screen()), lit_pixels(before) + 50) << "the hole's wall in the highlight colour";
    EXPECT_EQ(app.v->choose_annotation(3).status, Status::OutOfRange);
    EXPECT_EQ(app.v->chosen_annotation(), 0u) << "a refused call changes nothing";
    ASSERT_TRUE(app.v->choose_annotation(kNone).ok());
    app.run();
    EXPECT_TRUE(app.screen() == before);

    // A tap on a label chooses its annotation.
    const module::Annotating& labels = static_cast<Core*>(app.v)->annotating();
    int lx = -1, ly = -1;
    for (int y = 0; y < app.h && lx < 0; ++y)
        for (int x = 0; x < app.w && lx < 0; ++x)
            if (labels.label_at(int16_t(x), int16_t(y)) == 1) lx = x, ly = y;
    ASSERT_GE(lx, 0) << "the flatness's label is placed";
    app.tap(lx + 2, ly + 2);
    EXPECT_EQ(app.v->chosen_annotation(), 1u);
    ASSERT_GE(app.v->measurement(lines), 1u);
    EXPECT_STREQ(lines[0], "\u23E5 0.05");
    // A face picked ends the choice.
    ASSERT_TRUE(app.v->select(0, kHole).ok());
    EXPECT_EQ(app.v->chosen_annotation(), kNone);
}

TEST(Annotations, TheListShowsEachKindAndTapsChooseAndHide) {
    App app;
    ASSERT_TRUE(open_on_the_handheld(app));
    const module::Overlay& o = static_cast<Core*>(app.v)->overlay();
    EXPECT_TRUE(o.has_pmi());
    app.v->act(Action::Parts);
    app.run();
    ASSERT_TRUE(o.parts_open());
    const Area p = o.parts_panel();
    constexpr int kRow = module::Overlay::kRow;
    const int tab_x = p.width - 2 * 28 - 40 + 20; // (overlay_style.h: the scroll buttons and the tab)
    app.tap(tab_x, p.y + kRow / 2);
    ASSERT_TRUE(o.pmi_open()) << "the parts list's PMI tab opens the annotations list";
    EXPECT_FALSE(o.parts_open());
    EXPECT_EQ(o.pmi_rows() > 2, true);
    // The rows: the three annotations, in the file's order.
    app.tap(40, p.y + 2 * kRow + kRow + kRow / 2); // the second row
    EXPECT_EQ(app.v->chosen_annotation(), 1u);
    app.tap(40, p.y + 2 * kRow + kRow + kRow / 2);
    EXPECT_EQ(app.v->chosen_annotation(), kNone) << "a second tap lets go";
    // The kinds: DIM, TOL, DAT, NOTE across the row under the header.
    app.tap(p.width / 8, p.y + kRow + kRow / 2);
    EXPECT_EQ(app.v->annotations_shown(), kAllAnnotationKinds & ~annotation_kind_bit(AnnotationKind::Dimension));
    app.tap(p.width / 8 + p.width / 4, p.y + kRow + kRow / 2);
    EXPECT_EQ(app.v->annotations_shown(), annotation_kind_bit(AnnotationKind::Datum) | annotation_kind_bit(AnnotationKind::Note));
    app.tap(p.width - 10, p.y + p.height - 5); // HIDE ALL
    EXPECT_EQ(app.v->annotations_shown(), 0u);
    app.tap(10, p.y + p.height - 5); // SHOW ALL
    EXPECT_EQ(app.v->annotations_shown(), kAllAnnotationKinds);
    // The PARTS tab goes back; the PART button closes the list.
    app.tap(tab_x, p.y + kRow / 2);
    EXPECT_TRUE(o.parts_open() && !o.pmi_open());
    app.tap(tab_x, p.y + kRow / 2);
    ASSERT_TRUE(o.pmi_open());
    app.v->act(Action::Parts);
    EXPECT_FALSE(o.pmi_open() || o.parts_open());
    // A model without annotations has no PMI tab: the tap is the header's.
    ASSERT_TRUE(app.load(plate_with_holes()).ok());
    app.run();
    EXPECT_FALSE(o.has_pmi());
    app.v->act(Action::Parts);
    app.tap(tab_x, p.y + kRow / 2);
    EXPECT_TRUE(o.parts_open() && !o.pmi_open());
}

TEST(Annotations, ABlockedPackCarriesThemInItsIndex) {
    // Three plates, a block each, the annotations on the first one's faces.
    const Bytes plate = plate_with_holes();
    std::vector<geom::Pack> plates(3);
    for (auto& p : plates) ASSERT_TRUE(p.open(plate.data(), uint32_t(plate.size())).ok());
    const Bytes whole_bytes = with_annotations(geom::combine_packs(plates, 150.0f), plate_pmi());
    std::vector<uint32_t> words(whole_bytes.size() / 4 + 1);
    std::memcpy(words.data(), whole_bytes.data(), whole_bytes.size());
    geom::Pack whole;
    ASSERT_TRUE(whole.open(words.data(), uint32_t(whole_bytes.size())).ok());
    Bytes file;
    std::string error;
    ASSERT_TRUE(geom::make_blocked(whole, {}, {1, geom::BlockStore::Lzma}, file, error)) << error;
    App app;
    ASSERT_TRUE(app.create().ok());
    ASSERT_TRUE(app.load(file).ok());
    app.run();
    EXPECT_EQ(static_cast<Core*>(app.v)->scene().index().blocks().size(), 3u) << "a block a plate";
    ASSERT_EQ(app.v->annotation_count(), 3u);
    Viewer::Annotation a{};
    ASSERT_TRUE(app.v->annotation(0, a).ok());
    EXPECT_STREQ(a.text, "\u230020 \u00B10.1");
    ASSERT_EQ(a.face_count, 1u);
    EXPECT_EQ(a.faces[0], kHole) << "faces numbered as the whole pack's";
    uint32_t ids[2];
    EXPECT_EQ(app.v->face_annotations(0, kTop, ids, 2), 1u);
    // Joined again (facet-pack --check, the host's tools), the same annotations.
    Bytes joined;
    ASSERT_TRUE(geom::join_blocked(file, joined, error)) << error;
    geom::Annotations back, before;
    ASSERT_TRUE(open_annotations(joined, back).ok());
    ASSERT_TRUE(before.open(whole).ok());
    ASSERT_EQ(back.count(), before.count());
    for (uint32_t i = 0; i < back.count(); ++i) {
        EXPECT_STREQ(back.text(i), before.text(i));
        EXPECT_TRUE(std::equal(back.faces(i).begin(), back.faces(i).end(), before.faces(i).begin(), before.faces(i).end()));
        EXPECT_EQ(back.polylines(i).size(), before.polylines(i).size());
    }
}

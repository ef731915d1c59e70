// The overlay's parts list (overlay.h): the assembly tree, or a flat list of the parts.
#include "core/format.h"
#include "overlay.h"
#include "overlay_style.h"
#include "render/text.h"

namespace facet::module {
namespace {

using namespace overlay_style;
constexpr int32_t kIndent = 8;   // pixels a level
constexpr uint32_t kFooterButtons = 5;
constexpr const char* kFooter[kFooterButtons] = {"HIDE", "ISOL", "ALL", "FIT", "EXPL"};

} // namespace

// The rows: without a tree, every part; with one, the root's rows: for a node shown, its
// sub-assemblies (each followed by its own rows when it is open), then its own parts.
template <typename Each>
void Overlay::walk_rows(Each each) const {
    if (!scene_ || !scene_->loaded()) return;
    const geom::ProductTree& tree = scene_->tree();
    const uint32_t parts = uint32_t(scene_->instances().size());
    if (!tree.count()) {
        for (uint32_t i = 0; i < parts; ++i)
            if (!each(TreeRow{false, i, 0, false})) return;
        return;
    }
    // Depth-first along the open path, without recursion: at each depth, the node whose rows
    // are being given and where among its children (then its parts) the walk is.
    struct Level {
        uint32_t node, child, part;
        bool children_done;
    } stack[pack::kMaxTreeDepth + 1];
    uint32_t top = 0;
    stack[0] = {0, tree[0].first_child, tree[0].first_instance, false};
    for (;;) {
        Level& l = stack[top];
        const pack::Node& n = tree[l.node];
        if (!l.children_done) {
            if (l.child == pack::kNoIndex) {
                l.children_done = true;
                continue;
            }
            const uint32_t c = l.child;
            l.child = tree[c].next_sibling;
            const bool open = top + 1 <= open_depth_ && open_[top + 1] == c;
            if (!each(TreeRow{true, c, top, open})) return;
            if (open && top + 1 <= pack::kMaxTreeDepth) {
                ++top;
                stack[top] = {c, tree[c].first_child, tree[c].first_instance, false};
            }
            continue;
        }
        // Its own parts: its run less its children's.
        while (l.part < n.first_instance + n.instance_count && !tree.own(l.node, l.part)) ++l.part;
        if (l.part < n.first_instance + n.instance_count) {
            if (!each(TreeRow{false, l.part++, top, false})) return;
            continue;
        }
        if (top == 0) return;
        --top;
    }
}

uint32_t Overlay::tree_row_count() const {
    uint32_t n = 0;
    walk_rows([&](const TreeRow&) { return ++n, true; });
    return n;
}

bool Overlay::tree_row(uint32_t row, TreeRow& out) const {
    uint32_t k = 0;
    bool found = false;
    walk_rows([&](const TreeRow& r) {
        if (k++ < row) return true;
        out = r, found = true;
        return false;
    });
    return found;
}

void Overlay::scroll(int32_t rows) { first_row_ = scrolled(first_row_, rows, tree_row_count(), part_rows()); }

void Overlay::scroll_to(uint32_t row) {
    const uint32_t rows = part_rows();
    if (rows == 0) return;
    if (row < first_row_) first_row_ = row;
    if (row >= first_row_ + rows) first_row_ = row - rows + 1;
}

void Overlay::toggle_open(uint32_t node) {
    if (!scene_ || node == 0 || node >= scene_->tree().count()) return;
    const geom::ProductTree& tree = scene_->tree();
    const uint32_t d = tree.depth(node);
    if (d <= open_depth_ && open_[d] == node) { // open: closed (with what is open under it)
        open_depth_ = d - 1;
        return;
    }
    // Opened: the path to it, its ancestors open, what was open beside it closed.
    for (uint32_t n = node, k = d; k > 0 && n != pack::kNoIndex; --k, n = tree[n].parent) open_[k] = n;
    open_[0] = 0, open_depth_ = d;
}

void Overlay::set_chosen(uint32_t part) {
    chosen_ = part, chosen_node_ = kNone;
    if (part == kNone || !scene_ || !scene_->loaded()) return;
    const uint32_t node = scene_->tree().node_of(part);
    if (node != pack::kNoIndex && node != 0 && !(scene_->tree().depth(node) <= open_depth_ && open_[scene_->tree().depth(node)] == node)) {
        toggle_open(node); // (its sub-assembly open, so its row shows)
    }
    uint32_t k = 0;
    walk_rows([&](const TreeRow& r) {
        if (!r.node && r.index == part) return scroll_to(k), false;
        return ++k, true;
    });
}

void Overlay::set_chosen_node(uint32_t node) {
    chosen_node_ = node, chosen_ = kNone;
    if (node == kNone || !scene_ || !scene_->loaded()) return;
    if (node > 0 && scene_->tree()[node].parent != 0) toggle_open(scene_->tree()[node].parent);
    uint32_t k = 0;
    walk_rows([&](const TreeRow& r) {
        if (r.node && r.index == node) return scroll_to(k), false;
        return ++k, true;
    });
}

void Overlay::parts_list(const render::Target& t) const {
    const Area p = parts_panel();
    if (!scene_ || !scene_->loaded() || p.height < kRow + kPartsFooter) return;
    const geom::ProductTree& tree = scene_->tree();
    char text[128];
    format(text, sizeof text, "PARTS {}", scene_->instances().size());
    list_head(t, p, text);
    if (has_pmi()) list_tab(t, p, "PMI");
    const uint32_t rows = part_rows();
    uint32_t k = 0;
    walk_rows([&](const TreeRow& r) {
        if (k < first_row_) return ++k, true;
        const uint32_t at = k++ - first_row_;
        if (at >= rows) return false;
        const int32_t y = p.y + kRow + int32_t(at) * kRow, x = p.x + int32_t(r.depth) * kIndent;
        const bool lit = r.node ? r.index == chosen_node_ : r.index == chosen_;
        if (lit) render::fill_rect(t, p.x, y, p.width - 1, kRow, kButtonOn);
        if (r.node) { // its box: + closed, - open; its name and how many parts
            const pack::Node& n = tree[r.index];
            render::fill_rect(t, x + 5, y + 4, 12, 12, kText);
            render::fill_rect(t, x + 6, y + 5, 10, 10, lit ? kButtonOn : kBar);
            render::draw_text(t, x + 8, y + (kRow - render::kGlyphHeight) / 2, r.open ? "-" : "+", kText);
            const char* name = *tree.occurrence(r.index) ? tree.occurrence(r.index) : tree.name(r.index);
            format(text, sizeof text, "{} ({})", *name ? name : "(unnamed)", n.instance_count);
        } else { // its box: filled when the part is shown
            const bool shown = scene_->shown(r.index);
            render::fill_rect(t, x + 5, y + 4, 12, 12, shown ? kText : kDim);
            if (!shown) render::fill_rect(t, x + 7, y + 6, 8, 8, lit ? kButtonOn : kBar);
            const char* name = scene_->part_name(scene_->instances()[r.index].shell);
            format(text, sizeof text, "{} {}", r.index + 1, *name ? name : "(unnamed)");
        }
        const int32_t room = p.width - (x - p.x) - 26;
        render::cut_text(text, room > 0 ? room / render::kCellWidth : 0);
        render::draw_text(t, x + 22, y + (kRow - render::kGlyphHeight) / 2, text, r.node || scene_->shown(r.index) ? kText : kDim);
        return true;
    });
    const bool chosen = chosen_ != kNone || chosen_node_ != kNone;
    const int32_t w5 = p.width / int32_t(kFooterButtons), y = p.y + p.height - kPartsFooter;
    for (uint32_t i = 0; i < kFooterButtons; ++i) {
        const int32_t x = p.x + int32_t(i) * w5, w = i + 1 == kFooterButtons ? p.width - int32_t(kFooterButtons - 1) * w5 : w5;
        const bool on = i == 2 || (i < 4 && chosen) || (i == 4 && tree.count());
        const bool lit = i == 4 && scene_->explode() != 0;
        render::fill_rect(t, x + 1, y + 1, w - 2, kPartsFooter - 2, lit ? kButtonOn : on ? kButton : kBar);
        render::draw_text(t, x + (w - render::text_width(kFooter[i])) / 2, y + (kPartsFooter - render::kGlyphHeight) / 2, kFooter[i],
                          on ? kText : kDim);
    }
}

Overlay::PartsHit Overlay::parts_at(int16_t x, int16_t y) const {
    PartsHit h;
    if (!parts_open() || list_hit(x, y, h)) {
        if (h.kind == PartsHit::Kind::Panel && has_pmi() && tab_hit(x, y)) h.kind = PartsHit::Kind::Tab;
        return h;
    }
    const Area p = parts_panel();
    if (y >= p.y + p.height - kPartsFooter) { // HIDE, ISOL, ALL, FIT, EXPL
        const int32_t w5 = p.width / int32_t(kFooterButtons), i = x / w5 < int32_t(kFooterButtons) ? x / w5 : int32_t(kFooterButtons) - 1;
        static constexpr PartsHit::Kind kKinds[kFooterButtons] = {PartsHit::Kind::Hide, PartsHit::Kind::Isolate, PartsHit::Kind::All,
                                                                  PartsHit::Kind::Fit, PartsHit::Kind::Explode};
        h.kind = kKinds[i];
        return h;
    }
    const uint32_t row = uint32_t(y - p.y - kRow) / uint32_t(kRow);
    TreeRow r;
    if (row >= part_rows() || !tree_row(first_row_ + row, r)) return h;
    h.part = r.index;
    const int32_t box_end = int32_t(r.depth) * kIndent + 22;
    if (r.node) h.kind = x < box_end ? PartsHit::Kind::NodeBox : PartsHit::Kind::NodeRow;
    else h.kind = x < box_end ? PartsHit::Kind::Box : PartsHit::Kind::Row;
    return h;
}

} // namespace facet::module

// The Viewer's calls for the assembly tree and the exploded view (facet/viewer.h), and the
// Core's behind them.
#include "core.h"

#include <cmath>

namespace facet {
namespace {
Core& core(Viewer* v) { return *static_cast<Core*>(v); }
const Core& core(const Viewer* v) { return *static_cast<const Core*>(v); }
} // namespace

Result Core::check_node(uint32_t node) const {
    if (!scene_.loaded()) return Result::fail(Status::NotFound, "no model is loaded");
    if (node >= scene_.tree().count()) return Result::fail(Status::OutOfRange, "no such node of the assembly tree", {"node", node});
    return {};
}

Result Core::show_node(uint32_t node, bool shown) {
    if (const Result r = check_node(node); !r.ok()) return r;
    const pack::Node& n = scene_.tree()[node];
    for (uint32_t i = n.first_instance; i < n.first_instance + n.instance_count && i < module::Scene::kMaxHideable; ++i) {
        scene_.set_shown(i, shown);
        if (!shown) picks_.hidden(i);
    }
    presenter_.invalidate();
    return {};
}

Result Core::isolate_node(uint32_t node) {
    if (const Result r = check_node(node); !r.ok()) return r;
    const pack::Node& n = scene_.tree()[node];
    const uint32_t parts = uint32_t(scene_.instances().size());
    if (parts > module::Scene::kMaxHideable && (n.first_instance > 0 || n.instance_count < parts)) {
        return Result::fail(Status::OutOfRange, "only the first parts can be hidden (Viewer::kMaxHideableParts)", {"node", node});
    }
    for (uint32_t i = 0; i < parts && i < module::Scene::kMaxHideable; ++i) {
        const bool in = i >= n.first_instance && i < n.first_instance + n.instance_count;
        scene_.set_shown(i, in);
        if (!in) picks_.hidden(i);
    }
    presenter_.invalidate();
    return {};
}

Result Core::fit_node(uint32_t node) {
    if (const Result r = check_node(node); !r.ok()) return r;
    const pack::Node& n = scene_.tree()[node];
    if (n.instance_count == 0) return Result::fail(Status::NotFound, "the node holds no part", {"node", node});
    glide_to(camera_.view(), n.first_instance, kNone, n.instance_count);
    return {};
}

Result Core::choose_node(uint32_t node) {
    if (node != kNone) {
        if (const Result r = check_node(node); !r.ok()) return r;
    }
    picks_.choose_node(node);
    return {};
}

Result Core::set_explode(float factor) {
    if (!scene_.loaded()) return Result::fail(Status::NotFound, "no model is loaded");
    if (!scene_.tree().count()) return Result::fail(Status::NotFound, "the model has no assembly tree to explode");
    if (!(factor >= 0 && factor <= module::Scene::kMostExplode)) {
        return Result::fail(Status::OutOfRange, "an explode factor is 0 (assembled) to 2");
    }
    if (factor == scene_.explode()) return {};
    scene_.set_explode(factor);
    module::Overlay& o = presenter_.overlay();
    if (o.slider_explodes()) o.set_explode_slider(true, factor / module::Scene::kMostExplode);
    presenter_.invalidate(); // (every part where it is now)
    return {};
}

void Core::toggle_explode() {
    module::Overlay& o = presenter_.overlay();
    const bool out = scene_.explode() == 0 && scene_.tree().count() > 0;
    o.set_explode_slider(out && config_.interface == Interface::Full, 0);
    (void)set_explode(out ? 1.0f : 0.0f); // (the slider, when on, follows it)
    fit(); // (the model apart, or together again, framed from where the eye is)
}

uint32_t Viewer::node_count() const {
    const module::Scene& s = core(this).scene();
    return s.loaded() ? s.tree().count() : 0;
}

Result Viewer::node(uint32_t index, Node& out) const {
    const Core& c = core(this);
    if (const Result r = c.check_node(index); !r.ok()) return r;
    const geom::ProductTree& t = c.scene().tree();
    const pack::Node& n = t[index];
    out = {t.name(index), t.occurrence(index), n.parent, n.first_child, n.next_sibling, n.first_instance, n.instance_count, t.depth(index)};
    return {};
}

uint32_t Viewer::part_node(uint32_t part) const {
    const module::Scene& s = core(this).scene();
    return s.loaded() ? s.tree().node_of(part) : kNone;
}

Result Viewer::show_node(uint32_t index, bool shown) { return core(this).show_node(index, shown); }
Result Viewer::isolate_node(uint32_t index) { return core(this).isolate_node(index); }
Result Viewer::fit_node(uint32_t index) { return core(this).fit_node(index); }
Result Viewer::choose_node(uint32_t index) { return core(this).choose_node(index); }
uint32_t Viewer::chosen_node() const { return core(this).chosen_node(); }
float Viewer::explode() const { return core(this).scene().explode(); }
Result Viewer::set_explode(float factor) { return core(this).set_explode(factor); }

} // namespace facet

// facet-sim: the module on the desktop, with the buffers of a board (full frames, or bands
// with --bands), in an SDL window with the mouse, the wheel, the keys and touch -- or headless.
// The same module code the boards run, so the same input gives the same pixels.
//
//   facet-sim --pack MODEL.fpk [--size WxH] [--bands N] [--out DIR] [--headless] [--quiet]
//             [--scale K] [--ram MIB] [--send ENTRY]...
//
// --ram MIB: the module gets that much RAM, the pack decoded at its end, as on a board (a model
// larger than it opens in part, its other parts as boxes until the view brings them in);
// without it, what the model asks for.
// --send ENTRY: a scripted session (sim/session.h lists the entries), played one entry per
// idle moment like tools/qemu/run.py does; the program ends when the entries run out. In the
// window, entries arrive as SDL events (the path a user's input takes); headless, they go to
// the module directly. Screenshots (wireframe, half, done, !shot NAME) go to DIR as NAME.f565.
// In the window: left drag orbits, right drag pans, wheel zooms, a click picks, two fingers
// pinch and pan; keys as on the boards (h lists them), Esc or q quits.
#include "session.h"

#include <SDL.h>

#include <cstdio>
#include <cstdlib>
#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

namespace {

constexpr uint32_t kStepUs = 8000;

int usage() {
    std::fprintf(stderr, "usage: facet-sim --pack MODEL.fpk [--size WxH] [--bands N] [--out DIR] [--headless] [--no-clock] [--verbose] [--quiet] "
                         "[--scale K] [--ram MIB] [--send ENTRY]...\n");
    return 2;
}

int run_headless(sim::Session& s, const std::vector<std::string>& script) {
    size_t next = 0;
    while (!s.quit()) {
        if (s.step(kStepUs) != facet::Activity::Idle) continue;
        if (next == script.size()) break;
        std::vector<sim::Input> inputs;
        if (!sim::parse_entry(script[next], inputs)) {
            std::fprintf(stderr, "facet-sim: unknown script entry: %s\n", script[next].c_str());
            return 2;
        }
        ++next;
        for (const sim::Input& in : inputs) s.apply(in);
    }
    return s.failures() ? 1 : 0;
}

// The SDL window: the screen as a texture, updated where a flush changed it.
struct Window {
    SDL_Window* window = nullptr;
    SDL_Renderer* renderer = nullptr;
    SDL_Texture* texture = nullptr;
    sim::Session* session = nullptr;
    int scale = 1;
    bool dirty = false;
    int mouse_x = 0, mouse_y = 0;  // the scripted pointer's position (screen pixels)
    uint32_t held = 0;             // the scripted pointer's buttons (SDL masks)
    uint8_t module_buttons = 0;    // the relative pointer's buttons held (right 2, middle 4)
    SDL_FingerID fingers[2] = {-1, -1};

    static void flushed(void* self, const facet::Area& a) {
        Window& w = *static_cast<Window*>(self);
        if (!w.texture) return;
        const SDL_Rect r{a.x, a.y, a.width, a.height};
        const auto& screen = w.session->screen();
        SDL_UpdateTexture(w.texture, &r, &screen[size_t(a.y) * w.session->options().width + a.x], w.session->options().width * 2);
        w.dirty = true;
    }
    void present() {
        if (!renderer || !dirty) return;
        SDL_RenderClear(renderer);
        SDL_RenderCopy(renderer, texture, nullptr, nullptr);
        SDL_RenderPresent(renderer);
        dirty = false;
    }
    int finger(SDL_FingerID id) {
        for (int i = 0; i < 2; ++i)
            if (fingers[i] == id) return i;
        for (int i = 0; i < 2; ++i)
            if (fingers[i] == -1) return fingers[i] = id, i;
        return -1;
    }

    // A user's input (or a scripted one, pushed as SDL events) to the module.
    void handle(const SDL_Event& ev) {
        sim::Session& s = *session;
        facet::Viewer& v = s.viewer();
        const int w = s.options().width, h = s.options().height;
        switch (ev.type) {
        case SDL_QUIT: s.key('q'); break;
        case SDL_TEXTINPUT:
            for (const char* p = ev.text.text; *p; ++p)
                if (uint8_t(*p) < 0x80) s.key(uint8_t(*p));
            break;
        case SDL_KEYDOWN:
            switch (ev.key.keysym.sym) {
            case SDLK_RETURN: s.key('\n'); break;
            case SDLK_ESCAPE: s.key('q'); break;
            case SDLK_LEFT: v.key(facet::KeyLeft); break;
            case SDLK_RIGHT: v.key(facet::KeyRight); break;
            case SDLK_UP: v.key(facet::KeyUp); break;
            case SDLK_DOWN: v.key(facet::KeyDown); break;
            case SDLK_PAGEUP: v.key(facet::KeyPageUp); break;
            case SDLK_PAGEDOWN: v.key(facet::KeyPageDown); break;
            case SDLK_HOME: v.key(facet::KeyHome); break;
            default: break;
            }
            break;
        case SDL_MOUSEBUTTONDOWN:
        case SDL_MOUSEBUTTONUP: {
            if (ev.button.which == SDL_TOUCH_MOUSEID) break; // the fingers' own events come too
            const bool down = ev.type == SDL_MOUSEBUTTONDOWN;
            const int x = ev.button.x / scale, y = ev.button.y / scale;
            // The left button is a finger (absolute: drags orbit, clicks pick); the others
            // drag relatively (right pans, middle zooms).
            if (ev.button.button == SDL_BUTTON_LEFT) {
                v.touch(0, int16_t(x), int16_t(y), down);
                break;
            }
            const uint8_t bit = ev.button.button == SDL_BUTTON_RIGHT ? 2 : ev.button.button == SDL_BUTTON_MIDDLE ? 4 : 0;
            module_buttons = uint8_t(down ? (module_buttons | bit) : (module_buttons & ~bit));
            v.pointer(0, 0, module_buttons);
            break;
        }
        case SDL_MOUSEMOTION: {
            if (ev.motion.which == SDL_TOUCH_MOUSEID) break;
            const uint32_t state = ev.motion.state;
            if (state & SDL_BUTTON_LMASK) v.touch(0, int16_t(ev.motion.x / scale), int16_t(ev.motion.y / scale), true);
            const uint8_t b = uint8_t(((state & SDL_BUTTON_RMASK) ? 2 : 0) | ((state & SDL_BUTTON_MMASK) ? 4 : 0));
            if (b) v.pointer(int16_t(ev.motion.xrel / scale), int16_t(ev.motion.yrel / scale), b);
            break;
        }
        case SDL_MOUSEWHEEL: v.wheel(int16_t(ev.wheel.y)); break;
        case SDL_FINGERDOWN:
        case SDL_FINGERMOTION:
        case SDL_FINGERUP: {
            const int id = finger(ev.tfinger.fingerId);
            if (id < 0) break;
            const int x = int(ev.tfinger.x * float(w) + 0.5f), y = int(ev.tfinger.y * float(h) + 0.5f);
            v.touch(uint8_t(id), int16_t(x), int16_t(y), ev.type != SDL_FINGERUP);
            if (ev.type == SDL_FINGERUP) fingers[id] = -1;
            break;
        }
        default: break;
        }
    }

    // A script entry as the SDL events a user's hands would make.
    bool push(const std::string& entry) {
        std::vector<sim::Input> inputs;
        if (!sim::parse_entry(entry, inputs)) return false;
        const int w = session->options().width, h = session->options().height;
        for (const sim::Input& in : inputs) {
            SDL_Event e;
            std::memset(&e, 0, sizeof e);
            switch (in.kind) {
            case sim::Input::Kind::Key:
                if (in.key == '\n' || in.key == '\r') {
                    e.type = SDL_KEYDOWN;
                    e.key.keysym.sym = SDLK_RETURN;
                } else {
                    e.type = SDL_TEXTINPUT;
                    e.text.text[0] = char(in.key);
                }
                break;
            case sim::Input::Kind::Pointer: {
                const uint32_t want = ((in.buttons & 1) ? SDL_BUTTON_LMASK : 0) | ((in.buttons & 2) ? SDL_BUTTON_RMASK : 0) |
                                      ((in.buttons & 4) ? SDL_BUTTON_MMASK : 0);
                if (in.dx || in.dy) {
                    mouse_x = std::max(0, std::min(w - 1, mouse_x + in.dx));
                    mouse_y = std::max(0, std::min(h - 1, mouse_y + in.dy));
                    e.type = SDL_MOUSEMOTION;
                    e.motion.x = mouse_x * scale, e.motion.y = mouse_y * scale;
                    e.motion.xrel = in.dx * scale, e.motion.yrel = in.dy * scale;
                    e.motion.state = held;
                    break;
                }
                const uint32_t changed = want ^ held;
                if (!changed) continue;
                const uint32_t mask = changed & -changed; // one button per event
                e.type = (want & mask) ? SDL_MOUSEBUTTONDOWN : SDL_MOUSEBUTTONUP;
                e.button.button = uint8_t(mask == SDL_BUTTON_LMASK ? SDL_BUTTON_LEFT : mask == SDL_BUTTON_RMASK ? SDL_BUTTON_RIGHT : SDL_BUTTON_MIDDLE);
                e.button.x = mouse_x * scale, e.button.y = mouse_y * scale;
                held ^= mask;
                break;
            }
            case sim::Input::Kind::Wheel:
                e.type = SDL_MOUSEWHEEL;
                e.wheel.y = in.dy;
                break;
            case sim::Input::Kind::Touch:
                e.type = in.down ? (touching[in.id] ? SDL_FINGERMOTION : SDL_FINGERDOWN) : SDL_FINGERUP;
                touching[in.id] = in.down;
                e.tfinger.fingerId = 100 + in.id;
                e.tfinger.x = float(in.x) / float(w);
                e.tfinger.y = float(in.y) / float(h);
                break;
            }
            SDL_PushEvent(&e);
        }
        return true;
    }
    bool touching[2] = {false, false};
};

int run_window(sim::Session& s, const std::vector<std::string>& script, int scale, bool scripted) {
    if (SDL_Init(SDL_INIT_VIDEO | SDL_INIT_EVENTS) != 0) {
        std::fprintf(stderr, "facet-sim: no display for a window (%s); --headless runs without one\n", SDL_GetError());
        return 1;
    }
    Window win;
    win.session = &s;
    win.scale = scale;
    const int w = s.options().width, h = s.options().height;
    win.mouse_x = w / 2, win.mouse_y = h / 2;
    win.window = SDL_CreateWindow("facet-sim", SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED, w * scale, h * scale, 0);
    if (!win.window) {
        std::fprintf(stderr, "facet-sim: cannot open a window: %s\n", SDL_GetError());
        SDL_Quit();
        return 1;
    }
    win.renderer = SDL_CreateRenderer(win.window, -1, 0);
    if (win.renderer) win.texture = SDL_CreateTexture(win.renderer, SDL_PIXELFORMAT_RGB565, SDL_TEXTUREACCESS_STREAMING, w, h);
    s.on_flush = Window::flushed;
    s.flush_user = &win;
    SDL_StartTextInput();
    size_t next = 0;
    int status = 0;
    while (!s.quit()) {
        SDL_Event ev;
        while (!s.quit() && SDL_PollEvent(&ev)) win.handle(ev);
        if (s.quit()) break;
        const facet::Activity a = s.step(kStepUs);
        win.present();
        if (a != facet::Activity::Idle) continue;
        if (!scripted) {
            if (SDL_WaitEventTimeout(&ev, 100)) win.handle(ev);
            continue;
        }
        if (next == script.size()) break;
        if (!win.push(script[next])) {
            std::fprintf(stderr, "facet-sim: unknown script entry: %s\n", script[next].c_str());
            status = 2;
            break;
        }
        ++next;
    }
    SDL_StopTextInput();
    if (win.texture) SDL_DestroyTexture(win.texture);
    if (win.renderer) SDL_DestroyRenderer(win.renderer);
    SDL_DestroyWindow(win.window);
    SDL_Quit();
    return status ? status : (s.failures() ? 1 : 0);
}

} // namespace

int main(int argc, char** argv) {
    sim::Options opt;
    opt.out = ".";
    std::vector<std::string> script;
    bool headless = false;
    int scale = 1;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        int w = 0, h = 0;
        if (a == "--size" && i + 1 < argc && std::sscanf(argv[i + 1], "%dx%d", &w, &h) == 2) {
            if (w < 16 || h < 16 || w > 4096 || h > 4096) {
                std::fprintf(stderr, "facet-sim: --size must be 16x16 to 4096x4096\n");
                return 2;
            }
            opt.width = uint16_t(w), opt.height = uint16_t(h), ++i;
        } else if (a == "--bands" && i + 1 < argc) {
            opt.band_lines = uint16_t(std::atoi(argv[++i]));
        } else if (a == "--pack" && i + 1 < argc) {
            opt.pack = argv[++i];
        } else if (a == "--out" && i + 1 < argc) {
            opt.out = argv[++i];
        } else if (a == "--send" && i + 1 < argc) {
            script.push_back(argv[++i]);
        } else if (a == "--scale" && i + 1 < argc) {
            scale = std::atoi(argv[++i]);
        } else if (a == "--ram" && i + 1 < argc) {
            const int mib = std::atoi(argv[++i]);
            if (mib < 1 || mib > 1024) {
                std::fprintf(stderr, "facet-sim: --ram must be 1 to 1024 (MiB)\n");
                return 2;
            }
            opt.ram_bytes = size_t(mib) << 20;
        } else if (a == "--headless") {
            headless = true;
        } else if (a == "--verbose") {
            opt.verbose = true;
        } else if (a == "--no-clock") {
            opt.clock = false; // the same pixels whatever the machine's speed (tests)
        } else if (a == "--quiet") {
            opt.quiet = true;
        } else {
            return usage();
        }
    }
    if (opt.pack.empty()) return usage();
    if (opt.band_lines > opt.height || scale < 1 || scale > 4) {
        std::fprintf(stderr, "facet-sim: --bands must be 1 to the height, --scale 1 to 4\n");
        return 2;
    }
    sim::Session s;
    std::string error;
    if (!s.open(opt, error)) {
        std::fprintf(stderr, "facet-sim: %s\n", error.c_str());
        return 1;
    }
    return headless ? run_headless(s, script) : run_window(s, script, scale, !script.empty());
}

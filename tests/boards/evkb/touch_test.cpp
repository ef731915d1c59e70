// The EVKB's LPI2C driver and the touch controllers behind it, on a simulated I2C bus with a GT911
// or an FT5406: the I2C specification's timings, the documented register sequences.
#include "register_model.h"

#include "imxrt1062.h"
#include "lpi2c.h"
#include "touch.h"

#include <gtest/gtest.h>

#include <cstring>
#include <deque>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace {

using namespace facet;
using namespace facet::evkb;
using namespace facet::evkb::test;

// --- LPI2C and the touch controllers ---------------------------------------------------------------

// An I2C device behind the simulated bus: register reads and writes with an address pointer.
struct Device {
    uint8_t address = 0;
    uint32_t address_bytes = 1;                 // 2: the GT911's 16-bit registers
    std::map<uint32_t, uint8_t> mem;
    std::vector<std::vector<uint8_t>> writes;   // every write (the register pointer included)
    uint32_t pointer = 0;
};

// The LPI2C master's commands (MTDR) carried out at once against `devices`: START+address ACKs
// or sets NDF; transmitted bytes go to the selected device; RECEIVE queues bytes; STOP sets SDF.
struct Bus {
    std::vector<Device*> devices;
    Device* selected = nullptr;
    bool reading = false;
    std::vector<uint8_t> pending;
    std::deque<uint8_t> rx;
    std::vector<uint32_t> commands;
    uint32_t msr = 0;

    void attach() {
        const uint32_t base = lpi2c::kLpi2c1;
        model.write_hook = [this, base](uint32_t a, uint32_t v) {
            if (a == base + lpi2c::kMtdr) return command(v), true;
            if (a == base + lpi2c::kMcr && (v & lpi2c::kRrf)) rx.clear();
            if (a == base + lpi2c::kMsr) return msr &= ~(v & 0x3F00), true;
            return false;
        };
        model.read_hook = [this, base](uint32_t a, uint32_t& v) {
            if (a == base + lpi2c::kMsr) return v = msr | lpi2c::kTdf, true;
            if (a == base + lpi2c::kMfsr) return v = uint32_t(rx.size()) << 16, true;
            if (a == base + lpi2c::kMrdr) {
                if (rx.empty()) return v = lpi2c::kRxEmpty, true;
                v = rx.front();
                rx.pop_front();
                return true;
            }
            return false;
        };
    }
    void end_write() {
        if (selected && !reading && !pending.empty()) {
            selected->writes.push_back(pending);
            uint32_t p = 0;
            for (uint32_t i = 0; i < selected->address_bytes && i < pending.size(); ++i) p = p << 8 | pending[i];
            selected->pointer = p;
            for (size_t i = selected->address_bytes; i < pending.size(); ++i) selected->mem[p + uint32_t(i - selected->address_bytes)] = pending[i];
        }
        pending.clear();
    }
    void command(uint32_t v) {
        commands.push_back(v);
        const uint32_t cmd = v & 0x700, data = v & 0xFF;
        if (cmd == lpi2c::kCmdStart) {
            end_write();
            selected = nullptr;
            for (Device* d : devices)
                if (d->address == (data >> 1)) selected = d;
            reading = data & 1;
            if (!selected) msr |= lpi2c::kNdf;
        } else if (cmd == lpi2c::kCmdTransmit) {
            if (selected) pending.push_back(uint8_t(data));
        } else if (cmd == lpi2c::kCmdReceive) {
            if (!selected) return; // nobody acknowledged: nothing comes
            for (uint32_t i = 0; i <= data; ++i) rx.push_back(selected ? selected->mem[selected->pointer++] : 0xFF);
        } else if (cmd == lpi2c::kCmdStop) {
            end_write();
            selected = nullptr;
            msr |= lpi2c::kSdf;
        }
    }
};

TEST(Lpi2c, StandardModeTimingWithinTheI2cSpecification) {
    reset_model();
    Lpi2c i2c(lpi2c::kLpi2c1);
    i2c.init(kI2c100kHzAt10MHz);
    const uint32_t m = model.last(lpi2c::kLpi2c1 + lpi2c::kMccr0);
    const uint32_t clklo = field(m, 5, 0), clkhi = field(m, 13, 8), sethold = field(m, 21, 16), datavd = field(m, 29, 24);
    const double tick = 1.0 / 10e6; // LPI2C root: 10 MHz (clocks.h); PRESCALE 0
    EXPECT_EQ(field(model.last(lpi2c::kLpi2c1 + lpi2c::kMcfgr1), 2, 0), 0u);
    const double period = (clkhi + clklo + 2 + 1) * tick; // SCL_LATENCY 1 with no filter
    EXPECT_LE(1.0 / period, 100e3 * 1.0001) << "at most 100 kHz";
    EXPECT_GE(1.0 / period, 90e3);
    EXPECT_GE((clklo + 1) * tick, 4.7e-6) << "tLOW";
    EXPECT_GE((clkhi + 1 + 1) * tick, 4.0e-6) << "tHIGH";
    EXPECT_GE((sethold + 1) * tick, 4.7e-6) << "tSU;STA and tHD;STA";
    EXPECT_LE((datavd + 1) * tick, 3.45e-6) << "tVD;DAT";
    EXPECT_TRUE(model.last(lpi2c::kLpi2c1 + lpi2c::kMcr) & lpi2c::kMen);
}

Device gt911(uint8_t address, uint16_t res_x, uint16_t res_y) {
    Device d;
    d.address = address;
    d.address_bytes = 2;
    const char id[] = "911";
    for (int i = 0; i < 4; ++i) d.mem[0x8140 + i] = uint8_t(id[i]);
    d.mem[0x8048] = uint8_t(res_x), d.mem[0x8049] = uint8_t(res_x >> 8);
    d.mem[0x804A] = uint8_t(res_y), d.mem[0x804B] = uint8_t(res_y >> 8);
    return d;
}

void gt911_point(Device& d, int slot, uint8_t id, uint16_t x, uint16_t y) {
    const uint32_t p = 0x814F + 8 * slot;
    d.mem[p] = id, d.mem[p + 1] = uint8_t(x), d.mem[p + 2] = uint8_t(x >> 8), d.mem[p + 3] = uint8_t(y),
    d.mem[p + 4] = uint8_t(y >> 8);
}

TEST(Touch, Gt911FoundAt0x5DReadWithTheDocumentedRegisterSequence) {
    reset_model();
    Bus bus;
    Device d = gt911(0x5D, 800, 480); // a GT911 configured for another resolution: scaled
    bus.devices = {&d};
    bus.attach();
    Lpi2c i2c(lpi2c::kLpi2c1);
    Touch touch;
    ASSERT_TRUE(touch.probe(i2c, 480, 272).ok());
    EXPECT_EQ(touch.chip(), Touch::Chip::Gt911);
    // The product ID read: START+W (0xBA), register 0x8140 high byte first, repeated START+R
    // (0xBB), receive 4 bytes, STOP.
    const std::vector<uint32_t> id_read = {lpi2c::kCmdStart | 0xBA, 0x81, 0x40, lpi2c::kCmdStart | 0xBB,
                                           lpi2c::kCmdReceive | 3, lpi2c::kCmdStop};
    ASSERT_GE(bus.commands.size(), id_read.size());
    EXPECT_EQ(std::vector<uint32_t>(bus.commands.begin(), bus.commands.begin() + 6), id_read);

    TouchFrame f;
    bool changed = true;
    d.mem[0x814E] = 0x00; // nothing new
    ASSERT_TRUE(touch.read(f, changed).ok());
    EXPECT_FALSE(changed);
    d.mem[0x814E] = 0x82; // buffer ready, two points
    gt911_point(d, 0, 7, 400, 240);
    gt911_point(d, 1, 9, 799, 0);
    ASSERT_TRUE(touch.read(f, changed).ok());
    ASSERT_TRUE(changed);
    ASSERT_EQ(f.count, 2u);
    EXPECT_EQ(f.points[0].id, 7);
    EXPECT_EQ(f.points[0].x, 240);
    EXPECT_EQ(f.points[0].y, 136);
    EXPECT_EQ(f.points[1].x, 479);
    EXPECT_EQ(f.points[1].y, 0);
    EXPECT_EQ(d.mem[0x814E], 0) << "the status register cleared after the read";
    EXPECT_EQ(d.writes.back(), (std::vector<uint8_t>{0x81, 0x4E, 0x00}));
}

TEST(Touch, Gt911AtItsOtherAddressFt5406OrNothing) {
    {
        reset_model();
        Bus bus;
        Device d = gt911(0x14, 480, 272);
        bus.devices = {&d};
        bus.attach();
        Lpi2c i2c(lpi2c::kLpi2c1);
        Touch touch;
        ASSERT_TRUE(touch.probe(i2c, 480, 272).ok());
        EXPECT_EQ(touch.chip(), Touch::Chip::Gt911);
    }
    {
        reset_model();
        Bus bus;
        Device ft;
        ft.address = 0x38;
        bus.devices = {&ft};
        bus.attach();
        Lpi2c i2c(lpi2c::kLpi2c1);
        Touch touch;
        ASSERT_TRUE(touch.probe(i2c, 480, 272).ok());
        EXPECT_EQ(touch.chip(), Touch::Chip::Ft5406);
        EXPECT_EQ(ft.writes.front(), (std::vector<uint8_t>{0x00, 0x00})) << "DEVICE_MODE 0: normal operation";
        // One finger in contact (event 2, ID 1) at the controller's x = 100, y = 200: the
        // panel's (200, 100) — the FT5406's axes are the panel's y and x.
        ft.mem[0x02] = 1;
        ft.mem[0x03] = 0x80 | 0x00, ft.mem[0x04] = 100, ft.mem[0x05] = 0x10, ft.mem[0x06] = 200;
        TouchFrame f;
        bool changed = false;
        ASSERT_TRUE(touch.read(f, changed).ok());
        ASSERT_EQ(f.count, 1u);
        EXPECT_EQ(f.points[0].x, 200);
        EXPECT_EQ(f.points[0].y, 100);
        EXPECT_EQ(f.points[0].id, 1);
        ft.mem[0x03] = 0x40; // lift-up event: no finger
        ASSERT_TRUE(touch.read(f, changed).ok());
        EXPECT_EQ(f.count, 0u);
    }
    {
        reset_model();
        Bus bus; // nobody on the bus: every address NACKs
        bus.attach();
        Lpi2c i2c(lpi2c::kLpi2c1);
        Touch touch;
        const Result r = touch.probe(i2c, 480, 272);
        EXPECT_EQ(r.status, Status::NotFound);
        EXPECT_EQ(touch.chip(), Touch::Chip::None);
        uint8_t b;
        const uint8_t reg = 0;
        EXPECT_EQ(i2c.transfer(0x38, &reg, 1, &b, 1).status, Status::NotFound);
    }
}


} // namespace

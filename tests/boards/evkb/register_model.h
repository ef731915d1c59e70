#pragma once
// The register model the EVKB's drivers run against on the host (register_model.cpp implements
// the drivers' mmio.h with it): a value per address, every write recorded in order, hooks for
// the bits a driver polls and for peripherals with behaviour (SET/CLR aliases, the LPI2C's
// FIFOs). What the drivers wrote is then decoded and checked against the reference manual.
#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <map>
#include <vector>

namespace facet::evkb::test {

struct Write {
    uint32_t address, value;
};

// polls and for peripherals with behaviour (SET/CLR aliases, the LPI2C's FIFOs).
struct Model {
    std::map<uint32_t, uint32_t> regs;
    std::vector<Write> log;
    std::function<bool(uint32_t, uint32_t&)> read_hook;  // true: answered
    std::function<bool(uint32_t, uint32_t)> write_hook; // true: handled (not stored)
    uint64_t delayed_us = 0;

    uint32_t last(uint32_t address) const {
        for (auto it = log.rbegin(); it != log.rend(); ++it)
            if (it->address == address) return it->value;
        ADD_FAILURE() << "no write to " << std::hex << address;
        return 0;
    }
    bool written(uint32_t address) const {
        for (const Write& w : log)
            if (w.address == address) return true;
        return false;
    }
    int index_of_first(uint32_t address, std::function<bool(uint32_t)> pred = nullptr) const {
        for (size_t i = 0; i < log.size(); ++i)
            if (log[i].address == address && (!pred || pred(log[i].value))) return int(i);
        return -1;
    }
};

extern Model model;

// An empty model: no registers, no writes, no hooks.
inline void reset_model() { model = Model{}; }

// Bits hi..lo of v.
inline uint32_t field(uint32_t v, int hi, int lo) { return (v >> lo) & ((1u << (hi - lo + 1)) - 1); }

} // namespace facet::evkb::test

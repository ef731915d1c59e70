#pragma once
// The value of a pure function of a few floats at the arguments of its last call, kept with
// their bits: called again with the same arguments, bit for bit, it is not evaluated again. For
// what soft float makes dear on a core without an FPU and a caller asks for over and over with
// the same arguments (the options, cosines and arcs every edge of a block shares).
//
//   LastCall<float, 2> arc;
//   const float a = arc({r, tol}, [&] { return max_arc_angle(r, tol); });
#include <bit>
#include <cstdint>

namespace facet {

template <typename Value, int N>
class LastCall {
public:
    template <typename Make>
    const Value& operator()(const float (&args)[N], Make make) {
        bool same = valid_;
        for (int i = 0; i < N; ++i) same = same && std::bit_cast<uint32_t>(args[i]) == key_[i];
        if (!same) {
            value_ = make();
            for (int i = 0; i < N; ++i) key_[i] = std::bit_cast<uint32_t>(args[i]);
            valid_ = true;
        }
        return value_;
    }

private:
    uint32_t key_[N] = {};
    bool valid_ = false;
    Value value_{};
};

} // namespace facet

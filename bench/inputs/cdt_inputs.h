#pragma once
// The named CDT benchmark inputs (issue 3), generated deterministically into caller-owned
// buffers so the host benchmark and the ARM firmware measure the same faces.
//
//   paper        the paper's face: a rectangle with a circular hole, 110 segments, 66 grid points
//   plate<N>     an outer rectangle plus 32-segment circular holes, N segments in all
//   plate<N>+grid  the same with an interior jittered grid of about N points
//   lattice317   a 317 x 317 integer lattice inside its boundary loop
//   circle100k   100,000 points on a circle as one loop
//   touch5000    5,000 square holes touching at corners (a checkerboard)
#include "cdt/face.h"

#include <cstddef>
#include <cstdint>

namespace facet::bench {

struct InputBuffers {
    cdt::Point* loop_points;
    size_t loop_capacity;
    uint32_t* loop_sizes;
    size_t loops_capacity;
    cdt::Point* interior;
    size_t interior_capacity;
};

struct Input {
    cdt::FaceInput face;
    uint32_t segments; // constraint segments (loop points)
    size_t points() const { return face.loop_points.size() + face.interior.size(); }
};

// Points and loops each named input needs (for sizing buffers).
struct InputSize {
    size_t loop_points, loops, interior;
};

// Returns false if `name` is unknown or the buffers are too small.
bool input_size(const char* name, InputSize& size);
bool make_input(const char* name, const InputBuffers& buffers, Input& out);

// Every named input, in benchmark order.
extern const char* const kInputNames[];
extern const size_t kInputCount;

} // namespace facet::bench

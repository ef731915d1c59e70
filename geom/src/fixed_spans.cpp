// Bézier extraction by knot insertion, for the surface patches and the curve spans.
#include "fixed_spans.h"

namespace facet::geom::detail {

// Bézier extraction of one span, on one row of control points (The NURBS Book A5.1, knot
// insertion): the span's ends a = knots[s] < b = knots[s+1] are inserted into the local knot
// vector until each has multiplicity p; the p + 1 points then left over the span are its
// Bézier control points. Only convex combinations with weights in [0, 1] (the knots are
// ordered): the points stay within the row's hull and the float rounding stays at its size.
// row: p + 1 points of `dims` floats, `stride` floats apart, read and overwritten.
void extract_span(const float* knots, int p, int s, float* row, int stride, int dims) {
    float T[4 * kBN], Q[3 * kBN][4];
    int nt = 2 * p + 2, nq = p + 1;
    for (int i = 0; i < nt; ++i) T[i] = knots[s - p + i];
    for (int i = 0; i < nq; ++i)
        for (int d = 0; d < dims; ++d) Q[i][d] = row[i * stride + d];
    int span_at = 0; // where the span [a, b) starts once a has multiplicity p: its last a
    const float ends[2] = {T[p], T[p + 1]};
    for (int end = 0; end < 2; ++end) {
        const float x = ends[end];
        const OrderKey kx = order_key(x); // (knots are finite: the pack's check)
        int k = 0, m = 0; // T[k] <= x < T[k+1]; m: x's multiplicity (an insertion adds one to each)
        for (int i = 0; i < nt; ++i) {
            const OrderKey ki = order_key(T[i]);
            if (ki <= kx) k = i;
            m += ki == kx;
        }
        for (; m < p; ++m, ++k, ++nt, ++nq) {
            for (int i = nq; i > k - m; --i)
                for (int d = 0; d < dims; ++d) Q[i][d] = Q[i - 1][d];
            for (int i = k - m; i >= k - p + 1; --i) {
                const float alpha = (x - T[i]) / (T[i + p] - T[i]);
                for (int d = 0; d < dims; ++d) Q[i][d] = alpha * Q[i][d] + (1 - alpha) * Q[i - 1][d];
            }
            for (int i = nt; i > k + 1; --i) T[i] = T[i - 1];
            T[k + 1] = x;
        }
        if (end == 0) span_at = k; // (b's insertions all come after it)
    }
    for (int i = 0; i <= p; ++i)
        for (int d = 0; d < dims; ++d) row[i * stride + d] = Q[span_at - p + i][d];
}


} // namespace facet::geom::detail

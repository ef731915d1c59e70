// The integer predicates against an independent exact reference (GMP), on random,
// near-degenerate and adversarial inputs across the whole stated range.
#include "cdt/predicates.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <random>

using namespace facet::cdt;

namespace {

int sign(const mpz_class& v) { return sgn(v); }

int orient_ref(int32_t ax, int32_t ay, int32_t bx, int32_t by, int32_t cx, int32_t cy) {
    const mpz_class r = (mpz_class(bx) - ax) * (mpz_class(cy) - ay) - (mpz_class(by) - ay) * (mpz_class(cx) - ax);
    return sign(r);
}

int incircle_ref(const int32_t* p) {
    mpz_class m[3][3];
    for (int i = 0; i < 3; ++i) {
        const mpz_class dx = mpz_class(p[2 * i]) - p[6], dy = mpz_class(p[2 * i + 1]) - p[7];
        m[i][0] = dx;
        m[i][1] = dy;
        m[i][2] = dx * dx + dy * dy;
    }
    const mpz_class det = m[0][0] * (m[1][1] * m[2][2] - m[2][1] * m[1][2]) -
                          m[1][0] * (m[0][1] * m[2][2] - m[2][1] * m[0][2]) +
                          m[2][0] * (m[0][1] * m[1][2] - m[1][1] * m[0][2]);
    return sign(det);
}

int s64(int64_t v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

void expect_both(const int32_t* p) {
    ASSERT_EQ(s64(orient2d(p[0], p[1], p[2], p[3], p[4], p[5])), orient_ref(p[0], p[1], p[2], p[3], p[4], p[5]));
    const int ref = incircle_ref(p);
    ASSERT_EQ(incircle(p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]), ref)
        << p[0] << "," << p[1] << " " << p[2] << "," << p[3] << " " << p[4] << "," << p[5] << " " << p[6] << "," << p[7];
    ASSERT_EQ(incircle_exact(p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]), ref);
}

} // namespace

TEST(Predicates, Int128MatchesGmpOnExtremes) {
    const int64_t vals[] = {0, 1, -1, INT64_MAX, INT64_MIN + 1, (int64_t(1) << 53), -(int64_t(1) << 53) + 7, 0x123456789ABCDEFLL};
    for (int64_t a : vals) {
        for (int64_t b : vals) {
            const mpz_class ref = mpz_class(std::to_string(a)) * mpz_class(std::to_string(b));
            for (const Int128 p : {Int128::mul(a, b), Int128::mul_portable(a, b)}) {
                const mpz_class got = mpz_class(std::to_string(p.hi)) * mpz_class("18446744073709551616") + mpz_class(std::to_string(p.lo));
                ASSERT_EQ(got, ref) << a << " * " << b;
            }
        }
    }
}

TEST(Predicates, PortableProductMatchesGmpOnRandomOperands) {
    std::mt19937_64 rng(4);
    for (int i = 0; i < 200000; ++i) {
        const int64_t a = int64_t(rng()) >> (rng() % 40), b = int64_t(rng()) >> (rng() % 40);
        const Int128 p = Int128::mul_portable(a, b);
        const mpz_class ref = mpz_class(std::to_string(a)) * mpz_class(std::to_string(b));
        const mpz_class got = mpz_class(std::to_string(p.hi)) * mpz_class("18446744073709551616") + mpz_class(std::to_string(p.lo));
        ASSERT_EQ(got, ref) << a << " * " << b;
    }
}

TEST(Predicates, RandomAcrossTheWholeRange) {
    std::mt19937_64 rng(1);
    for (int range : {100, 30000, 1 << 18, 1 << 20, kPredicateRange}) {
        std::uniform_int_distribution<int32_t> d(-range, range);
        for (int i = 0; i < 40000; ++i) {
            int32_t p[8];
            for (int32_t& v : p) v = d(rng);
            expect_both(p);
        }
    }
}

TEST(Predicates, NearDegenerateCollinearAndCocircular) {
    std::mt19937_64 rng(2);
    std::uniform_int_distribution<int32_t> d(-kPredicateRange / 4, kPredicateRange / 4);
    std::uniform_int_distribution<int32_t> j(-2, 2);
    for (int i = 0; i < 40000; ++i) {
        // c on (or one unit off) the line a-b; d on the line too.
        const int32_t ax = d(rng), ay = d(rng), dx = d(rng) / 1024, dy = d(rng) / 1024;
        const int32_t k = int32_t(rng() % 3) + 1;
        int32_t p[8] = {ax, ay, ax + dx, ay + dy, ax + k * dx + j(rng), ay + k * dy + j(rng), ax - dx, ay - dy};
        expect_both(p);
    }
    // Exactly cocircular lattice points (x^2 + y^2 = 5^8 has many solutions) and neighbours.
    const int32_t R2 = 390625;
    std::vector<std::pair<int32_t, int32_t>> on;
    for (int32_t x = -625; x <= 625; ++x) {
        const int32_t y2 = R2 - x * x;
        const int32_t y = int32_t(std::lround(std::sqrt(double(y2))));
        if (y * y == y2) {
            on.push_back({x, y});
            on.push_back({x, -y});
        }
    }
    ASSERT_GE(on.size(), 16u);
    for (size_t i = 0; i + 3 < on.size(); ++i) {
        for (int32_t s : {1, 256, 400, 4096, 30000}) {
            for (int32_t off : {-1, 0, 1}) {
                int32_t p[8] = {on[i].first * s, on[i].second * s, on[i + 1].first * s, on[i + 1].second * s,
                                on[i + 2].first * s, on[i + 2].second * s, on[i + 3].first * s + off, on[i + 3].second * s};
                expect_both(p);
            }
        }
    }
}

TEST(Predicates, AdversarialCornersOfTheRange) {
    const int32_t R = kPredicateRange, vals[] = {-R, -R + 1, -1, 0, 1, R - 1, R};
    std::mt19937_64 rng(3);
    for (int i = 0; i < 200000; ++i) {
        int32_t p[8];
        for (int32_t& v : p) v = vals[rng() % 7];
        expect_both(p);
    }
}

// The tier for differences under 2^19 (incircle_near) at its edges: every difference from d
// one of the extremes of that tier, or just past them, around a random d.
TEST(Predicates, AdversarialCornersOfTheNearTier) {
    constexpr int32_t N = 1 << 19;
    const int32_t offsets[] = {-N - 1, -N, -N + 1, -1, 0, 1, N - 2, N - 1, N};
    std::mt19937_64 rng(4);
    std::uniform_int_distribution<int32_t> d(-kPredicateRange / 2, kPredicateRange / 2);
    for (int i = 0; i < 200000; ++i) {
        int32_t p[8];
        p[6] = d(rng), p[7] = d(rng);
        for (int k = 0; k < 6; ++k) p[k] = p[6 + (k & 1)] + offsets[rng() % 9];
        expect_both(p);
    }
}

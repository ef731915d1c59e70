#pragma once
// What the C API's files share (c_api.cpp, c_api_product.cpp): a C viewer as the C++ one, a
// result as the C one, and the refusal of a NULL viewer.
#include "facet/facet.h"
#include "facet/viewer.h"
#include "public_result.h"

namespace facet::c_api {

// The public statuses (facet_status): what the C++ calls and events give (public_result.h),
// and the C module's own refusals.
inline facet_result to_c(const Result& r) {
    FACET_DEBUG_ASSERT("module", module::is_public(r.status));
    return {facet_status(r.status), r.what, r.where.kind, r.where.index, r.at.kind, r.at.index};
}

inline Viewer* cpp(facet_viewer* v) { return reinterpret_cast<Viewer*>(v); }
inline const Viewer* cpp(const facet_viewer* v) { return reinterpret_cast<const Viewer*>(v); }

} // namespace facet::c_api

// A NULL viewer: a call with a result says so; the others do nothing or return zeros.
#define FACET_NEED_VIEWER(v)                                                    \
    do {                                                                        \
        if (!(v)) return to_c(Result::fail(Status::OutOfRange, "no viewer")); \
    } while (0)

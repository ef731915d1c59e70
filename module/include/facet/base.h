/* facet: what the C API (facet/facet.h) and the C++ one (facet/viewer.h) share: the module's
 * version, and the one value that means "none" wherever an index or a count could be one. C99
 * and C++ alike. docs/module-api.md lists what changed from version to version. */
#ifndef FACET_BASE_H
#define FACET_BASE_H

#define FACET_VERSION_MAJOR 0
#define FACET_VERSION_MINOR 3
#define FACET_VERSION_PATCH 0
/* One number to compare: 0.2.0 is 200. */
#define FACET_VERSION (FACET_VERSION_MAJOR * 10000 + FACET_VERSION_MINOR * 100 + FACET_VERSION_PATCH)

/* No part, no face, no model (facet::kNone in C++). */
#define FACET_NONE 0xFFFFFFFFu

#endif /* FACET_BASE_H */

#pragma once
// facet-pack --annotations PACK: each annotation of a pack (geom/pmi.h) as a JSON line: its
// kind, type, text, values, faces and presentation.
#include <string>

namespace facet::packer {

// 0, or 1 with the reason in `error` (a file that is no pack, or a pack whose annotations lie).
int print_annotations(const char* path, std::string& error);

} // namespace facet::packer

// The one translation unit that compiles Cdt, for both index widths.
#include "constraint.ipp"
#include "inner.ipp"
#include "insert.ipp"
#include "locate.ipp"
#include "mesh.ipp"

namespace facet::cdt {
template class Cdt<uint16_t>;
template class Cdt<uint32_t>;
} // namespace facet::cdt

#pragma once
// The facet pack: exact B-rep geometry, packed on the host (tools/facet-pack) and read in place
// on the device (geom/pack.h, its records through geom/params.h). One header for both sides;
// docs/pack-format.md explains it.
//
// Layout: a 64-byte header, a table of sections, then each section's records, every part
// 4-byte aligned. Little-endian. Geometry is float32 (a 2 m part keeps ~0.1 um steps, far below
// the 0.1% visual tolerance); indices are uint32 with kNoIndex for "none".
//
// Stored or sent, a pack is usually compressed (LzmaHead below and a raw LZMA stream, or
// DeflatedHead and a raw DEFLATE stream): geom/pack_file.h turns any form into a pack ready to
// read in place.
#include <cstdint>
#include <initializer_list>

namespace facet::pack {

constexpr char kMagic[4] = {'F', 'P', 'K', '1'};
constexpr uint16_t kVersion = 3;
constexpr uint32_t kNoIndex = 0xFFFFFFFFu;
constexpr uint32_t kStraight = 0xFFFFFFFEu; // Edge::curve of a straight edge (no curve record)
constexpr uint32_t kMaxSections = 32;
constexpr uint32_t kMaxBytes = 64u << 20; // a pack larger than this is refused as corrupt
constexpr float kMaxMagnitude = 1e8f;     // every float of a pack lies within +-this

struct Header {
    char magic[4];
    uint16_t version;
    uint16_t header_bytes;  // sizeof(Header): lets later versions grow it
    uint32_t total_bytes;   // the whole pack
    uint32_t crc32;         // CRC-32 (IEEE) of bytes [header_bytes, total_bytes)
    uint32_t section_count; // entries in the section table that follows the header
    uint32_t flags;         // reserved, 0
    float bbox_min[3];      // of every vertex (a reader checks they lie inside), in millimetres
    float bbox_max[3];
    float source_unit_mm;   // the STEP file's length unit (coordinates are converted to mm)
    uint32_t reserved[3];
};
static_assert(sizeof(Header) == 64, "pack header is 64 bytes");

enum class SectionId : uint32_t {
    Floats = 1,    // float32 pool: every surface and curve keeps its parameters here
    Surfaces = 2,  // Surface records
    Curves3 = 3,   // 3D curves (edges)
    Curves2 = 4,   // 2D curves (pcurves, in a face's (u,v))
    Vertices = 5,  // float32 x, y, z
    Edges = 6,
    Coedges = 7,   // an edge as used by one loop of one face
    Loops = 8,
    Faces = 9,
    Shells = 10,   // a solid's (or a surface model's) faces
    Instances = 11,
    Colours = 12,  // RGBA8
    // Names (optional: a pack without them reads as before; a reader that does not know them
    // skips them). Names holds UTF-8 strings, each ended by a 0 byte, padded with 0 bytes to a
    // multiple of 4; the first is the model's own name (the STEP file's top product), possibly
    // empty. ShellNames and InstanceNames give, per shell and per instance, the byte in Names
    // where its name starts, or kNoIndex: a shell is named after the part (product) that holds
    // it, an instance after its occurrence in the assembly (when the file names it).
    Names = 13,
    ShellNames = 14,
    InstanceNames = 15,
    // SmoothEdges (optional, as the names): one bit per edge, in uint32 words (edge e: word
    // e / 32, bit e % 32), set where the edge's two faces meet tangentially (their normals
    // within kSmoothAngle along it, as Open CASCADE's regularity judges it): a fillet's sides,
    // the halves of a split cylinder. A viewer may leave these out of the drawing ("tangent
    // edges hidden"). Written only when some edge is smooth; its count is the words the edges
    // need.
    SmoothEdges = 16,
    // Needs (optional, one record): what the model takes on a device (pack::Needs), measured
    // by the packer. Written first after the table, so that its record lies in the pack's head
    // (facet::model_needs() reads it without decoding the rest). 17 is the index's Parts.
    Needs = 18,
};
constexpr float kSmoothAngle = 0.0174533f; // rad (1 degree)
constexpr uint32_t smooth_words(uint32_t edges) { return (edges + 31) / 32; }
constexpr uint32_t kMaxNameBytes = 255; // a longer name is cut (on a UTF-8 boundary) by the packer

// What a model takes on the device, measured by the packer with the device's own code: the edge
// samples and the mesh at the model's default level of detail (0.1% of its box's diagonal, as
// the viewer takes it from the header's box), and at kCoarsestFirst times its tolerance, the
// coarsest first level a viewer short of room takes. facet::model_needs() sizes the workspace
// from it (a pack without it: from estimates).
struct Needs {
    uint32_t samples, mesh_vertices, mesh_triangles;             // at the default level
    uint32_t coarse_samples, coarse_vertices, coarse_triangles; // at kCoarsestFirst times its tolerance
};
static_assert(sizeof(Needs) == 24, "pack::Needs is 6 words");
constexpr float kCoarsestFirst = 16.0f;
// The fewest triangles a viewer bounds a view to however small its screen (module's
// DetailScale): a model whose mesh, every instance's, passes it can be crowded, and facet-pack
// gives its parts proxies.
constexpr uint32_t kLeastTriangleBound = 8192;
// Why a Needs record cannot be what a packer measured (null: it can): a count past 2^31.
inline const char* needs_problem(const Needs& n) {
    for (uint32_t c : {n.samples, n.mesh_vertices, n.mesh_triangles, n.coarse_samples, n.coarse_vertices, n.coarse_triangles})
        if (c > 0x80000000u) return "a count of the Needs record is past 2^31";
    return nullptr;
}

struct SectionEntry {
    uint32_t id;           // SectionId
    uint32_t offset;       // from the start of the pack, 4-byte aligned
    uint32_t count;        // records
    uint32_t record_bytes; // must equal the record size this reader knows
};
static_assert(sizeof(SectionEntry) == 16);

// Elementary surfaces store their placement as origin, x, y and z axes: OCCT placements may be
// left-handed (z = -(x cross y)), and z gives the surface's own normal direction.
//   Plane     P(u,v) = O + u X + v Y                                   normal Z
//   Cylinder  P(u,v) = O + R (cos u X + sin u Y) + v Z
//   Cone      P(u,v) = O + (R + v sin a)(cos u X + sin u Y) + v cos a Z
//   Sphere    P(u,v) = O + R cos v (cos u X + sin u Y) + R sin v Z
//   Torus     P(u,v) = O + (R + r cos v)(cos u X + sin u Y) + r sin v Z
enum class SurfaceType : uint8_t {
    Plane = 1,      // PlaneParams
    Cylinder = 2,   // CylinderParams
    Cone = 3,       // ConeParams
    Sphere = 4,     // SphereParams
    Torus = 5,      // TorusParams
    BSpline = 6,    // BSplineSurfaceHead, then knots, poles, weights
    Revolution = 7, // RevolutionParams; ref = the revolved 3D curve: P(u,v) = C(v) turned by u
                    // about the axis
    Extrusion = 8,  // ExtrusionParams; ref = the extruded 3D curve: P(u,v) = C(u) + v D
};

enum class CurveType : uint8_t {
    Line = 1,    // Line3Params / Line2Params
    Circle = 2,  // Circle3Params / Circle2Params
    Ellipse = 3, // Ellipse3Params / Ellipse2Params
    BSpline = 4, // BSplineCurveHead, then knots, poles, weights
};

// The parameters of each kind of surface and curve, as they lie in the Floats pool from the
// record's `params` on: the packer writes these records and the reader reads them in place
// (geom/params.h); a record's float count is its size. A B-spline's head is followed by its
// knots (expanded by multiplicity), its poles (dim floats each, weight-free coordinates) and, if
// rational, its weights.
struct Frame {
    float origin[3], x[3], y[3], z[3];
};
struct PlaneParams {
    Frame frame;
};
struct CylinderParams {
    Frame frame;
    float radius;
};
struct ConeParams {
    Frame frame;
    float ref_radius; // the radius at v = 0
    float semi_angle; // rad
};
struct SphereParams {
    Frame frame;
    float radius;
};
struct TorusParams {
    Frame frame;
    float major_radius; // of the circle the tube's centre runs on
    float minor_radius; // the tube's
};
struct RevolutionParams {
    float axis_origin[3], axis_direction[3];
};
struct ExtrusionParams {
    float direction[3];
};
struct Line3Params {
    float origin[3], direction[3]; // P(t) = origin + t direction
};
struct Circle3Params {
    float origin[3], x[3], y[3], radius; // P(t) = origin + radius (cos t x + sin t y)
};
struct Ellipse3Params {
    float origin[3], x[3], y[3], major, minor; // P(t) = origin + major cos t x + minor sin t y
};
struct Line2Params {
    float origin[2], direction[2];
};
struct Circle2Params {
    float origin[2], x[2], y[2], radius;
};
struct Ellipse2Params {
    float origin[2], x[2], y[2], major, minor;
};
struct BSplineCurveHead {
    float degree, pole_count, knot_count, rational, periodic; // stored as floats in the pool
};
struct BSplineSurfaceHead {
    float u_degree, v_degree, u_poles, v_poles, u_knots, v_knots, rational, u_periodic, v_periodic;
};

// A record's length in floats (the reader's expected count; a B-spline's head alone).
template <typename Params>
constexpr uint32_t float_count = uint32_t(sizeof(Params) / sizeof(float));
static_assert(float_count<PlaneParams> == 12 && float_count<CylinderParams> == 13 && float_count<ConeParams> == 14 &&
                  float_count<SphereParams> == 13 && float_count<TorusParams> == 14 && float_count<RevolutionParams> == 6 &&
                  float_count<ExtrusionParams> == 3,
              "the surface records of pack version 3");
static_assert(float_count<Line3Params> == 6 && float_count<Circle3Params> == 10 && float_count<Ellipse3Params> == 11 &&
                  float_count<Line2Params> == 4 && float_count<Circle2Params> == 7 && float_count<Ellipse2Params> == 8 &&
                  float_count<BSplineCurveHead> == 5 && float_count<BSplineSurfaceHead> == 9,
              "the curve records of pack version 3");

struct Surface {
    uint8_t type;  // SurfaceType
    uint8_t flags; // reserved
    uint16_t pad;
    uint32_t params; // first float in the pool
    uint32_t count;  // floats
    uint32_t ref;    // Revolution/Extrusion: a Curves3 index; else kNoIndex
};
static_assert(sizeof(Surface) == 16);

struct Curve {
    uint8_t type; // CurveType
    uint8_t dim;  // 3 (Curves3) or 2 (Curves2)
    uint16_t pad;
    uint32_t params;
    uint32_t count;
};
static_assert(sizeof(Curve) == 12);

struct Vertex {
    float p[3];
};

struct Edge {
    uint32_t curve;     // Curves3 index; kStraight: the segment from v0 to v1, its parameter
                        // running linearly from t0 to t1 (a line's edge needs no curve record);
                        // kNoIndex: a degenerate edge (a pole or apex)
    float t0, t1;       // parameter range on the curve
    uint32_t v0, v1;    // Vertices at t0 and t1
    float tolerance;    // mm: the B-rep's own tolerance of the edge (how far its curve may be
                        // from its faces' surfaces and its ends from their vertices), as the STEP
                        // file and healing left it
    float max_sag;      // mm, 0 = none: the largest chord sag that keeps every loop through the
                        // edge simple (40% of its distance to the nearest edge of its faces that
                        // shares no vertex with it): a thin face's two sides must not cross
};
static_assert(sizeof(Edge) == 28);

// Which side of a periodic surface's parameter range a seam coedge lies on.
enum class Seam : uint8_t { None = 0, ULow = 1, UHigh = 2, VLow = 3, VHigh = 4 };

// An edge as used by a loop, in one word: the edge's index, whether the loop runs it from t1
// to t0, and (a seam edge of a periodic surface) the side of the face's (u,v) bounds this use
// lies on (its twin lies on the other). Its pcurve, if the face has them, is the face's
// first_pcurve + its position among the face's coedges.
struct Coedge {
    uint32_t bits; // edge (bits 0-27), reversed (bit 28), Seam (bits 29-31)

    static constexpr uint32_t kEdgeBits = 28, kMaxEdges = 1u << kEdgeBits;
    uint32_t edge() const { return bits & (kMaxEdges - 1); }
    bool reversed() const { return (bits >> kEdgeBits) & 1u; }
    Seam seam() const { return Seam(bits >> (kEdgeBits + 1)); }
    static constexpr Coedge make(uint32_t edge, bool reversed, Seam seam) {
        return {edge | uint32_t(reversed) << kEdgeBits | uint32_t(seam) << (kEdgeBits + 1)};
    }
};
static_assert(sizeof(Coedge) == 4);

struct Loop {
    uint32_t first_coedge;
    uint32_t coedge_count;
};

struct Face {
    uint32_t surface;
    uint32_t first_loop;   // the outer loop first; the loops' coedges follow each other
    uint32_t loop_count;
    uint32_t first_pcurve; // Curves2 index of the pcurve of the face's first coedge, the others'
                           // following in order; kNoIndex on elementary surfaces (plane,
                           // cylinder, cone, sphere, torus), where (u,v) comes from inverting
                           // the surface at the edges' 3D samples
    uint32_t colour;       // Colours index or kNoIndex
    uint8_t reversed;      // 1: the face's normal is opposite the surface's
    uint8_t pad[3];
    float uv_min[2], uv_max[2]; // parameter bounds of the face
};
static_assert(sizeof(Face) == 40);

struct Shell {
    uint32_t first_face;
    uint32_t face_count;
    uint32_t colour; // default colour of its faces, or kNoIndex
    uint32_t closed; // 1: a closed solid (every edge shared by two faces)
};

struct Instance {
    uint32_t shell;
    float m[12]; // row-major 3x4 placement (rotation | translation), mm
};
static_assert(sizeof(Instance) == 52);

// A placement places a part whole: its 3x3 part is a rotation, or a rotation and a mirror
// (determinant +1 or -1), orthonormal within this (each row a unit vector within it, each two at
// right angles within it): float32 keeps a double rotation to about 1e-7.
constexpr float kPlacementTolerance = 1e-4f;

// Null when m is such a placement with every entry within +-kMaxMagnitude (NaN refused); else
// what is wrong with it.
inline const char* placement_problem(const float m[12]) {
    for (int i = 0; i < 12; ++i) {
        if (!(m[i] >= -kMaxMagnitude && m[i] <= kMaxMagnitude)) return "placement is NaN, infinite or beyond +-1e8";
    }
    for (int i = 0; i < 3; ++i) {
        for (int j = i; j < 3; ++j) {
            const float d = m[4 * i] * m[4 * j] + m[4 * i + 1] * m[4 * j + 1] + m[4 * i + 2] * m[4 * j + 2];
            const float want = i == j ? 1.0f : 0.0f;
            if (!(d - want <= kPlacementTolerance && want - d <= kPlacementTolerance)) {
                return "placement is no rotation (its rows are not unit vectors at right angles: a part stretched or flattened)";
            }
        }
    }
    return nullptr;
}

struct Colour {
    uint8_t r, g, b, a;
};

// A deflated pack: this head, then the pack as a raw DEFLATE stream (RFC 1951).
constexpr char kDeflatedMagic[4] = {'F', 'P', 'Z', '1'};
struct DeflatedHead {
    char magic[4];
    uint32_t pack_bytes;   // the pack, inflated
    uint32_t stream_bytes; // the DEFLATE stream that follows
    uint32_t reserved;     // 0
};
static_assert(sizeof(DeflatedHead) == 16);

// An LZMA pack: this head, then the pack as a raw LZMA stream (geom/unlzma.h; about two thirds
// of the DEFLATE size on B-spline-heavy models). The default of facet-pack.
constexpr char kLzmaMagic[4] = {'F', 'P', 'X', '1'};
struct LzmaHead {
    char magic[4];
    uint32_t pack_bytes;   // the pack, decoded
    uint32_t stream_bytes; // the LZMA stream that follows
    uint8_t props;         // (pb * 5 + lp) * 9 + lc
    uint8_t reserved[3];   // 0
};
static_assert(sizeof(LzmaHead) == 16);

// A blocked pack (facet-pack's default): an index, read in place, then blocks. Each block is a
// pack of its own (the layout above: the faces, edges, curves, surfaces and colours of some
// shells, no instances, no names), stored as an LZMA file (LzmaHead and stream) or plain, and
// decoded alone when its shells are needed, so a device holds only what the view needs. The
// index says what the model is: its parts (a shell: which block holds it, its box, its counts),
// the instances that place them (pack::Instance, `shell` a part number) and the names.
//
//   IndexHeader, SectionEntry[section_count], the index's sections (ids below), then the
//   blocks at the offsets the Blocks section gives, each 4-byte aligned.
constexpr char kBlockedMagic[4] = {'F', 'P', 'B', '1'};
constexpr uint16_t kBlockedVersion = 1;
constexpr uint32_t kMaxBlockedBytes = 256u << 20; // a larger file is refused as corrupt

struct IndexHeader {
    char magic[4];          // FPB1
    uint16_t version;       // kBlockedVersion
    uint16_t header_bytes;  // sizeof(IndexHeader)
    uint32_t total_bytes;   // the whole file, blocks included
    uint32_t crc32;         // of bytes [kIndexCrcFrom, index_bytes): the rest of this header and
                            // the index (the blocks have their own)
    uint32_t index_bytes;   // where the index ends (the first block starts at or after it)
    uint32_t section_count;
    uint32_t flags;         // reserved, 0
    float bbox_min[3];      // the placed model (every instance's part box, placed), mm
    float bbox_max[3];
    float source_unit_mm;
    uint32_t reserved[2];
};
static_assert(sizeof(IndexHeader) == 64, "blocked pack header is 64 bytes");
constexpr uint32_t kIndexCrcFrom = 16; // the field after crc32

// The index's sections: Blocks and Parts, and the pack's own Instances, Names, ShellNames (per
// part) and InstanceNames records.
enum class IndexSectionId : uint32_t {
    Instances = uint32_t(SectionId::Instances),
    Names = uint32_t(SectionId::Names),
    PartNames = uint32_t(SectionId::ShellNames),
    InstanceNames = uint32_t(SectionId::InstanceNames),
    Blocks = 16,
    Parts = 17,
    Needs = uint32_t(SectionId::Needs), // (optional) the whole model's
    // Proxies (optional, all three or none): each part's coarse mesh, drawn where the view shows
    // the part small instead of its block's exact geometry (geom/host/proxies.h): ProxyParts a
    // record per part, ProxyVertices and ProxyTriangles the pools its records index.
    ProxyParts = 19,
    ProxyVertices = 20,
    ProxyTriangles = 21,
    // Groups (optional, with the proxies; all four or none): instances near each other, culled
    // as one and drawn as one proxy where the view shows them small (geom/host/groups.h): Groups
    // a record per group, GroupMembers their instances, GroupPieces their proxies' pieces (their
    // corners and triangles in the proxies' pools), InstanceGroups each instance's group (a
    // uint32_t per instance: a reader checks every instance is its group's member once).
    Groups = 22,
    GroupMembers = 23,
    GroupPieces = 24,
    InstanceGroups = 25,
};

struct Block {
    uint32_t offset;       // from the file's start, 4-byte aligned, after the index
    uint32_t stored_bytes; // as stored: an LZMA file, or a plain pack
    uint32_t pack_bytes;   // decoded (= stored_bytes for a plain one)
    uint32_t first_part;   // its parts are [first_part, first_part + part_count), its shells in order
    uint32_t part_count;
    float box_min[3];      // its parts where their instances place them, mm (empty: min > max)
    float box_max[3];
};
static_assert(sizeof(Block) == 44);

// A part: one shell of a block. The block's shells, faces and edges are its parts' in order:
// a part's faces follow the faces of the parts before it in its block, and so do its edges.
struct Part {
    uint32_t block;      // which block holds it; its shell there is its place among the block's parts
    uint32_t face_count; // its shell's
    uint32_t edge_count; // edges its faces use (each once)
    uint32_t closed;     // 1: a closed solid
    float box_min[3];    // its shell's box, shell coordinates (mm): every point of its faces
    float box_max[3];
};
static_assert(sizeof(Part) == 40);

// A part's proxy at one level: its corners and triangles in the pools, how far it may stray from
// the part's surface (mm), and its colour. ProxyParts holds a whole number of levels per part
// (1 to kMostProxyLevels): part p's level l at p x levels + l, the coarsest first, each as far
// as the next finer or farther. Levels alike may share their corners and triangles.
constexpr uint32_t kMostProxyLevels = 4;
struct ProxyPart {
    uint32_t first_vertex, vertex_count;     // ProxyVertices [first, first + count), at most 65,535
    uint32_t first_triangle, triangle_count; // ProxyTriangles
    float error_mm;
    Colour colour; // a = 0: none (the viewer's default colour)
};
static_assert(sizeof(ProxyPart) == 24);
// A corner over its part's box: box_min + q / 65535 x (box_max - box_min).
struct ProxyVertex {
    uint16_t q[3];
};
static_assert(sizeof(ProxyVertex) == 6);
// Three corners (the part's own numbers), wound as its faces, the unit normal x 127, and the
// triangle across each side (side k from v[k] to v[k + 1]; its level's own numbers;
// kNoProxyNeighbour at a rim): a hidden-line view draws a proxy's outline and creases by them.
constexpr uint16_t kNoProxyNeighbour = 0xFFFF;
struct ProxyTriangle {
    uint16_t v[3];
    int8_t n[3];
    uint8_t reserved; // 0
    uint16_t across[3];
};
static_assert(sizeof(ProxyTriangle) == 16);

// A group of instances: its members, GroupMembers [first_member, first_member + member_count)
// (instance numbers, ascending; every instance is in exactly one group: InstanceGroups), and its proxy's pieces, a piece
// per colour at each level: GroupPieces [first_piece + l x colours, + colours) level l's, the
// coarsest first; the levels (1 to kMostProxyLevels) are GroupPieces' records over every group's
// colours summed. A piece is a ProxyPart whose
// corners lie over the group's box (the model's coordinates, mm); each of a level's pieces
// carries the level's error, as far as the next finer or farther.
struct Group {
    uint32_t first_member, member_count;
    uint32_t first_piece, colours;
    float box_min[3], box_max[3];
    float member_radius_mm; // the largest member's part's box's half diagonal: how small its members are
};
static_assert(sizeof(Group) == 44);

// A library: several model files (any of the kinds above) in one, as a device's flash holds
// them: a LibraryHeader, LibraryEntry[count], then each file at its offset, 8-byte aligned, so
// each is read (or decoded) from where it lies. A bad table refuses the library; a bad file is
// found when it is opened, and the others still open.
constexpr char kLibraryMagic[4] = {'F', 'L', 'B', '1'};
constexpr uint16_t kLibraryVersion = 1;
constexpr uint32_t kMaxLibraryEntries = 256;
constexpr uint32_t kLibraryNameBytes = 56; // UTF-8, NUL-terminated within

struct LibraryHeader {
    char magic[4];          // FLB1
    uint16_t version;       // kLibraryVersion
    uint16_t count;         // entries, 1 to kMaxLibraryEntries
    uint32_t total_bytes;   // the whole library
    uint32_t crc32;         // of the entries' table
};
static_assert(sizeof(LibraryHeader) == 16);

struct LibraryEntry {
    uint32_t offset;              // from the library's start, 8-byte aligned, after the table
    uint32_t bytes;               // the model file's
    char name[kLibraryNameBytes]; // its model's name (the STEP file's top product)
};
static_assert(sizeof(LibraryEntry) == 64);

// CRC-32 (IEEE 802.3, reflected, as zlib) for the header's checksum.
uint32_t crc32(const void* data, uint32_t size, uint32_t crc = 0);

} // namespace facet::pack

/* facet: the sizes of the buffers an application gives the module, in bytes. C and C++ alike
 * (usable in #if and in the size of a static array). The module checks every buffer it is given
 * against these and refuses one that is too small.
 *
 *   buffer            what it holds                                   bytes
 *   draw buffer       RGB565 pixels of a frame or of a band of rows   FACET_DRAW_BYTES(w, lines)
 *   depth buffer      16-bit depth of the same rows                   FACET_DEPTH_BYTES(w, lines)
 *   workspace         the model: edges, samples, one face's CDT       FACET_WORKSPACE_BYTES(...)
 *                     arena, the mesh, per-face state, palettes
 *   pack memory       a compressed pack decoded, or a blocked pack's  facet_pack_memory_bytes()
 *                     blocks (plain packs are read in place from
 *                     flash or RAM)
 *
 * The workspace holds one face's working memory (laid out at create: FACET_WORKSPACE_BASE_BYTES
 * at the default capacity) and the model's arrays, which load() plans for the model's faces and
 * edges and the room left (and, given no pack memory, the decoded pack at its end). Size it for
 * the largest model the product opens: facet::model_needs() (facet_model_needs()) says what a
 * pack needs, and FACET_WORKSPACE_BYTES gives a workspace from counts. The boards hand the
 * module all the RAM nothing else uses.
 *
 *   configuration                                 draw buffers    depth buffers   workspace
 *   qemu-versatilepb: 640x480, full frames        2 x 614,400     2 x 614,400     the free RAM
 *   qemu-mps2-an500 (the EVKB panel): 480x272     2 x 261,120     2 x 261,120     the free RAM
 *   examples/minimal: 480x272 in bands of 16      2 x 15,360      1 x 15,360      FACET_WORKSPACE_BYTES_DEFAULT
 */
#ifndef FACET_SIZES_H
#define FACET_SIZES_H

#define FACET_DRAW_BYTES(width, lines) ((unsigned long)(width) * (unsigned long)(lines) * 2ul)
#define FACET_DEPTH_BYTES(width, lines) ((unsigned long)(width) * (unsigned long)(lines) * 2ul)

/* One face's working memory, laid out at create (the defaults). */
#define FACET_DEFAULT_FACE_POINTS 12000u   /* points of one face in its CDT (at most 32,760) */
#define FACET_DEFAULT_LOOPS 2048u          /* loops of one face (a plate of 1,600 holes: 1,601) */
#define FACET_DEFAULT_SLIVERS 1024u        /* loop points of one face closer than its CDT grid */

/* A model of about 8,000 faces at the default detail (FACET_WORKSPACE_BYTES_DEFAULT): counts
 * for sizing a workspace, not limits (load() plans the model's arrays from the room it has). */
#define FACET_DEFAULT_FACES 8192u          /* faces of the pack */
#define FACET_DEFAULT_EDGES 16384u         /* edges of the pack */
#define FACET_DEFAULT_SAMPLES 65536u       /* edge samples of the whole model */
#define FACET_DEFAULT_MESH_VERTICES 65536u /* the mesh of the whole model */
#define FACET_DEFAULT_MESH_TRIANGLES 98304u

/* Bytes per item of each capacity, and the fixed part (the viewer's state, 16 colour palettes,
 * 64 KB of a free-form face's fixed-point patches, 176 KB of the painter's projection cache,
 * alignment). They come from the workspace's
 * one plan (module/src/workspace.h, a face's part from geom/face_storage.h): the module's build
 * fails unless each equals what the plan takes per item, and the fixed part holds the rest. */
#define FACET_BYTES_PER_FACE 44ul
#define FACET_BYTES_PER_EDGE 7ul
#define FACET_BYTES_PER_SAMPLE 28ul
#define FACET_BYTES_PER_FACE_POINT 223ul
#define FACET_BYTES_PER_LOOP 4ul
#define FACET_BYTES_PER_SLIVER 60ul
#define FACET_BYTES_PER_MESH_VERTEX 20ul
#define FACET_BYTES_PER_MESH_TRIANGLE 6ul
#define FACET_WORKSPACE_FIXED_BYTES 345280ul

#define FACET_WORKSPACE_BYTES(faces, edges, samples, face_points, loops, slivers, mesh_vertices, mesh_triangles)      \
    (FACET_WORKSPACE_FIXED_BYTES + (unsigned long)(faces)*FACET_BYTES_PER_FACE +                                        \
     (unsigned long)(edges)*FACET_BYTES_PER_EDGE + (unsigned long)(samples)*FACET_BYTES_PER_SAMPLE +                    \
     (unsigned long)(face_points)*FACET_BYTES_PER_FACE_POINT + (unsigned long)(loops)*FACET_BYTES_PER_LOOP +            \
     (unsigned long)(slivers)*FACET_BYTES_PER_SLIVER + (unsigned long)(mesh_vertices)*FACET_BYTES_PER_MESH_VERTEX +     \
     (unsigned long)(mesh_triangles)*FACET_BYTES_PER_MESH_TRIANGLE)

/* The least workspace create() takes at the default capacity: one face's working memory. */
#define FACET_WORKSPACE_BASE_BYTES                                                                                      \
    FACET_WORKSPACE_BYTES(0, 0, 0, FACET_DEFAULT_FACE_POINTS, FACET_DEFAULT_LOOPS, FACET_DEFAULT_SLIVERS, 0, 0)

#define FACET_WORKSPACE_BYTES_DEFAULT                                                                                   \
    FACET_WORKSPACE_BYTES(FACET_DEFAULT_FACES, FACET_DEFAULT_EDGES, FACET_DEFAULT_SAMPLES, FACET_DEFAULT_FACE_POINTS,   \
                          FACET_DEFAULT_LOOPS, FACET_DEFAULT_SLIVERS, FACET_DEFAULT_MESH_VERTICES,                      \
                          FACET_DEFAULT_MESH_TRIANGLES)

#endif /* FACET_SIZES_H */

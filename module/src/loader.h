#pragma once
// A pack file opened into the scene, whatever its form: a plain pack read in place (or copied
// where it can be, when unaligned), a compressed one decoded into the pack memory, a blocked
// one's blocks decoded there one after the other behind a table of them (the index and plain
// blocks read in place). When the file itself lies inside the pack memory, it is first moved to the memory's
// end and decoded from there.
#include "geom/pack_file.h"
#include "reader.h"
#include "scene.h"

#include <cstdint>

namespace facet::module {

// A model larger than the memory keeps its largest blocks (by their boxes' diagonals, mm; the
// first of equal ones) and leaves the rest out (Block::left_out): those at least `above`
// across, and those at least `from` across up to block `through`. The default keeps all.
struct BlockCut {
    float above = 0, from = 0;
    uint32_t through = 0;
};
float block_size(const pack::Block& b);
bool kept(const geom::PackIndex& index, uint32_t b, const BlockCut& cut);
// Faces and edges of the blocks kept.
void kept_counts(const geom::PackIndex& index, const BlockCut& cut, uint32_t& faces, uint32_t& edges);

// The pack memory a file needs (facet::pack_memory_bytes()), with a blocked pack's blocks as
// `cut` keeps them; 0 for one read in place, or unreadable. A blocked pack on storage (its index
// at `file`, `file_bytes` long): the index, each block read, and the largest block's staging.
uint32_t pack_memory_need(const void* file, uint32_t file_bytes, const BlockCut& cut = {}, const Reader* reader = nullptr);
uint32_t pack_memory_need(const geom::PackIndex& index, const BlockCut& cut); // a blocked pack's, from its index

// A pack file made readable: a whole pack's bytes, or a blocked pack's index and its blocks
// decoded behind their table (each block's pack not yet opened).
struct Unpacked {
    const uint8_t* pack = nullptr; // a whole pack
    uint32_t bytes = 0;            // its size, or the pack memory the blocks and their table take
    geom::PackIndex index;         // a blocked pack's (read in place)
    std::span<Block> blocks;       // a blocked pack's, in the pack memory: each compressed block decoded
                                   // after the table and the blocks before it (4-byte aligned); a plain
                                   // block read in place
    // A blocked pack's pack memory, for the blocks the view brings in later: the table at
    // `memory`, the decoded blocks after it up to `bytes`, room for more up to `limit` (where
    // the file, moved there, or the decoder's state begins), and the decoder's state.
    uint8_t* memory = nullptr;
    uint32_t limit = 0;
    geom::LzmaProbs* probs = nullptr;
    Reader* reader = nullptr; // the blocks' file, on storage (null: in memory with the index)
};

// Blocks brought in and left out as the view asks (a model larger than the memory):
// The pack memory block b takes decoded (0 when it is read in place from the file).
uint32_t block_memory(const Unpacked& u, uint32_t b);
// The room block b takes while it is read from storage and decoded: its stored bytes (0 when
// it is in memory, or plain).
uint32_t block_staging(const Unpacked& u, uint32_t b);
// The pack memory free for decoded blocks: what the table and the blocks held leave up to
// u.limit (once compact_blocks() has moved them together).
uint32_t free_block_memory(const Unpacked& u);
// The decoded blocks moved down over those left out since, in the order they lie, each pack's
// views moved with its bytes: u.bytes then ends the last.
void compact_blocks(Unpacked& u);
// Block b (left out) begun: decoded at u.bytes by `decoder` (its run() to go on until done), or
// at once when read in place. Full when the room up to u.limit is short. From storage, its read
// begun (Busy while it goes on: u.reader->poll(), then decode_block()).
Result start_block(Unpacked& u, uint32_t b, geom::PackDecoder& decoder);
// Block b read from storage (start_block()'s read ended): its decoding begun (a plain one: done).
Result decode_block(Unpacked& u, uint32_t b, geom::PackDecoder& decoder);
// Block b decoded (`decoder` done; none for one read in place): opened, checked against the
// index and taken into the scene; u.bytes past it.
Result finish_block(Unpacked& u, uint32_t b, const geom::PackDecoder* decoder, Scene& scene);

// Decodes `file` into the pack memory as its form asks (the work a profile calls unpacking); a
// blocked pack's blocks `cut` does not keep are left out. With a reader, `file` is a blocked
// pack's index read from it (in the pack memory), and the blocks kept are read through it.
Result unpack(const void* file, uint32_t file_bytes, void* memory, uint32_t memory_bytes, const BlockCut& cut, Unpacked& out,
              Reader* reader = nullptr);
// Validates what unpack() made and opens it into the scene.
Result open_unpacked(Unpacked& u, Scene& scene);

} // namespace facet::module

#pragma once
// facet: the UART protocol's records (docs/protocol.md), written in one place. A record is one
// line: '@', its name, its words, '\n' -- "@frame triangles 1204 culled 310 pixels 52113 ...".
// The boards' firmware prints them on its console and the simulator on its standard output;
// tools/protocol.py reads them (its RECORDS table lists each record and its words).
//
//   char line[facet::kRecordBytes];
//   if (uint32_t n = facet::event_record(e, line, sizeof line)) console.write(line, n);
#include "facet/types.h"

#include <cstdint>

namespace facet {

// Room for any record these write (the longest: a face's failure with its reason).
constexpr uint32_t kRecordBytes = 256;

// The record of an event, NUL-terminated in `out`: its length, or 0 for an event that has none
// (work regions; a frame that was no full one: a band or an update).
// A record longer than `size` - 1 is cut there and its full length returned (>= size).
uint32_t event_record(const Event& event, char* out, uint32_t size);

// "@load_failed STATUS WHY": a model that could not be opened (load(), set_library()).
uint32_t load_failed_record(const Result& why, char* out, uint32_t size);

// "@memory": what the model needed at its peak (pack, the file it came from, the workspace).
uint32_t memory_record(const Stats& stats, char* out, uint32_t size);

// "@stats": the model's totals when the viewer ends (faces done, failed, left to the view; triangles).
uint32_t stats_record(const Stats& stats, char* out, uint32_t size);

} // namespace facet

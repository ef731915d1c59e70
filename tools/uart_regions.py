#!/usr/bin/env python3
"""A firmware's UART log read with the instruction counts of its regions (for the scripts).

The runner (tools/qemu/run.py --icount) names the plugin's numbered regions from the
firmware's '@begin NAME' lines, in order, into report.json's 'regions'. lines() walks the log
with them: each non-empty line's words, and for a '@begin NAME' line the region it opened
(its dict, with 'instructions'; None when the plugin has no such region, e.g. a run cut short).
"""


def lines(uart, regions):
    i = 0
    for line in uart.splitlines():
        w = line.split()
        if not w:
            continue
        region = None
        if w[0] == '@begin' and len(w) == 2:
            if i < len(regions) and regions[i]['name'] == w[1]:
                region = regions[i]
            i += 1
        yield w, region

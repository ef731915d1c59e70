#!/usr/bin/env python3
"""Maps a facet-icount profile (address instructions block_length) to functions of the
firmware ELF.

  profile.py FIRMWARE.elf PROFILE [--top N] [--callers]

--callers also splits the calls of each of the top library routines (soft-float arithmetic,
division, memset...) by the function that calls them: each translated block runs from its
address for block_length instructions, and the times it ran times its call instructions to a
routine are that caller's calls (the block's instructions / its length = its runs).
"""
import bisect
import re
import subprocess
import sys


def symbols(elf):
    syms = []
    out = subprocess.run(['arm-none-eabi-nm', '-C', '-S', '--defined-only', elf], capture_output=True, text=True).stdout
    for line in out.splitlines():
        p = line.split(None, 3)
        if len(p) == 4 and p[2].lower() in 'tw':
            syms.append((int(p[0], 16) & ~1, int(p[1], 16), p[3]))
    syms.sort()
    return syms


def call_sites(elf):
    """address -> called address, for every bl/blx instruction."""
    sites = {}
    out = subprocess.run(['arm-none-eabi-objdump', '-d', '--no-show-raw-insn', elf], capture_output=True, text=True).stdout
    pat = re.compile(r'^\s*([0-9a-f]+):\s+blx?\s+([0-9a-f]+)\b')
    for line in out.splitlines():
        m = pat.match(line)
        if m:
            sites[int(m.group(1), 16)] = int(m.group(2), 16)
    return sites


def main():
    args = [a for a in sys.argv[1:] if not a.startswith('--')]
    if len(args) < 2:
        print(__doc__)
        return 2
    elf, prof = args[0], args[1]
    top = int(sys.argv[sys.argv.index('--top') + 1]) if '--top' in sys.argv else 25
    syms = symbols(elf)
    starts = [s[0] for s in syms]

    def name_of(a):
        i = bisect.bisect_right(starts, a) - 1
        return syms[i][2] if i >= 0 and a < syms[i][0] + max(syms[i][1], 1) else hex(a)

    per, blocks, total = {}, [], 0
    for line in open(prof):
        p = line.split()
        a, n = int(p[0], 16), int(p[1])
        length = int(p[2]) if len(p) > 2 else 0
        total += n
        per[name_of(a)] = per.get(name_of(a), 0) + n
        if length:
            blocks.append((a, n // length, length))
    print(f'{total:,} instructions in measured regions')
    ranked = sorted(per.items(), key=lambda kv: -kv[1])[:top]
    for name, n in ranked:
        print(f'{n:>14,} {100.0 * n / total:5.1f}%  {name[:110]}')
    if '--callers' in sys.argv and blocks:
        sites = call_sites(elf)
        calls = {}  # callee -> caller -> calls
        for a, runs, length in blocks:
            for k in range(length):
                target = sites.get(a + 4 * k)
                callee = name_of(target) if target is not None else None
                if callee:
                    c = calls.setdefault(callee, {})
                    caller = name_of(a)
                    c[caller] = c.get(caller, 0) + runs
        for name, n in ranked:
            if name not in calls or re.match(r'facet::', name):
                continue
            total_calls = sum(calls[name].values())
            print(f'\n{name}: {total_calls:,} calls, {n / max(total_calls, 1):.0f} instructions each, from')
            for caller, c in sorted(calls[name].items(), key=lambda kv: -kv[1])[:8]:
                print(f'{c:>12,}  {caller[:100]}')
    return 0


if __name__ == '__main__':
    sys.exit(main())

#!/usr/bin/env python3
"""Maps a facet-icount profile (address instructions) to functions of the firmware ELF.

  profile.py FIRMWARE.elf PROFILE [--top N]
"""
import bisect
import subprocess
import sys


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    elf, prof = sys.argv[1], sys.argv[2]
    top = int(sys.argv[sys.argv.index('--top') + 1]) if '--top' in sys.argv else 25
    syms = []
    out = subprocess.run(['arm-none-eabi-nm', '-C', '-S', '--defined-only', elf], capture_output=True, text=True).stdout
    for line in out.splitlines():
        p = line.split(None, 3)
        if len(p) == 4 and p[2].lower() in 'tw':
            syms.append((int(p[0], 16) & ~1, int(p[1], 16), p[3]))
    syms.sort()
    starts = [s[0] for s in syms]
    per = {}
    total = 0
    for line in open(prof):
        a, n = line.split()
        a, n = int(a, 16), int(n)
        total += n
        i = bisect.bisect_right(starts, a) - 1
        name = syms[i][2] if i >= 0 and a < syms[i][0] + max(syms[i][1], 1) else hex(a)
        per[name] = per.get(name, 0) + n
    print(f'{total:,} instructions in measured regions')
    for name, n in sorted(per.items(), key=lambda kv: -kv[1])[:top]:
        print(f'{n:>14,} {100.0 * n / total:5.1f}%  {name[:110]}')
    return 0


if __name__ == '__main__':
    sys.exit(main())

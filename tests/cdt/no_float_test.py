#!/usr/bin/env python3
"""cdt/ uses no floating point. On the soft-float ARM926 build every float or double operation
becomes a call to a libgcc helper (__aeabi_fadd, __aeabi_dmul, __aeabi_i2d, __floatsidf...),
so the libraries' undefined symbols must contain none of them."""
import re
import subprocess
import sys

FLOAT = re.compile(r'^(__aeabi_[fd]\w*|__aeabi_[il]2[fd]|__aeabi_[ul]*[fd]2\w+|__(add|sub|mul|div|neg|cmp|eq|ne|lt|le|gt|ge|unord)[sd]f\d|__float\w+|__fix\w+|__extend\w+|__trunc\w+df\w*)$')

bad = []
for lib in sys.argv[1:]:
    out = subprocess.run(['arm-none-eabi-nm', '-u', lib], capture_output=True, text=True, check=True).stdout
    for line in out.split('\n'):
        sym = line.split()[-1] if line.split() else ''
        if FLOAT.match(sym):
            bad.append(f'{lib}: {sym}')
for b in bad:
    print('floating point used:', b)
print(f'{len(sys.argv) - 1} libraries checked, {len(bad)} floating-point helpers referenced')
sys.exit(1 if bad else 0)

#!/usr/bin/env python3
"""A memory card image as a technician's PC makes one: FAT32 (dosfstools' mkfs.fat), the pack
files copied onto it with mtools (no mounting, no root), in its root folder unless a name has a
folder in it.

  card.py IMAGE FILE[=NAME] ...      NAME: the name on the card (default: the file's)

The image's size is a power of two (QEMU's SD card wants one), at least 64 MiB, with room for
the files. From Python: card.make(image, [(path, name), ...]).
"""
import os
import shutil
import subprocess
import sys

MIB = 1 << 20


def tool(name):
    for d in ('/usr/sbin', '/sbin', '/usr/bin', '/bin'):
        p = os.path.join(d, name)
        if os.path.exists(p):
            return p
    found = shutil.which(name)
    if not found:
        raise SystemExit(f'card.py: {name} is missing (apt-get install dosfstools mtools)')
    return found


def size_for(total):
    size = 64 * MIB
    while size < total * 1.1 + 16 * MIB:
        size *= 2
    return size


def make(image, files):
    """The image with `files` ((path, name on the card) pairs) copied on; its size."""
    total = sum(os.path.getsize(p) for p, _ in files)
    size = size_for(total)
    if os.path.exists(image):
        os.unlink(image)
    r = subprocess.run([tool('mkfs.fat'), '-F', '32', '-n', 'FACET', '-C', image, str(size // 1024)], capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit(f'card.py: mkfs.fat failed: {r.stderr.strip()}')
    made = set()
    for path, name in files:
        folder = os.path.dirname(name.strip('/'))
        parts = folder.split('/') if folder else []
        for k in range(len(parts)):
            sub = '/'.join(parts[:k + 1])
            if sub not in made:
                subprocess.run([tool('mmd'), '-i', image, f'::/{sub}'], check=True, capture_output=True)
                made.add(sub)
        r = subprocess.run([tool('mcopy'), '-i', image, path, f'::/{name.strip("/")}'], capture_output=True, text=True)
        if r.returncode != 0:
            raise SystemExit(f'card.py: mcopy {path} failed: {r.stderr.strip()}')
    return size


def main():
    if len(sys.argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    files = []
    for arg in sys.argv[2:]:
        path, _, name = arg.partition('=')
        if not os.path.isfile(path):
            print(f'card.py: no such file: {path}', file=sys.stderr)
            return 2
        files.append((path, name or os.path.basename(path)))
    size = make(sys.argv[1], files)
    print(f'{sys.argv[1]}: {size // MIB} MiB FAT32, {len(files)} files')
    return 0


if __name__ == '__main__':
    sys.exit(main())

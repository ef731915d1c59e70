#!/usr/bin/env python3
"""facet-pack on mutated STEP text: a mutation fuzzer (Open CASCADE reads a file in tens of
milliseconds, far too slow to link into libFuzzer's loop of millions).

Each run takes a shared model (the small ones, so that a run stays short), makes one to three
edits of the kinds a broken exporter or an attacker makes, and runs facet-pack on it:
  * references: an entity's #id pointed at another entity, at itself, at one that does not exist;
  * numbers: a real or an integer replaced by an extreme (0, -0, 1E308, 1E-308, 1E400, huge
    integers, a number where a reference goes);
  * syntax: a comma, a parenthesis, a quote, a semicolon or an equals sign dropped or doubled,
    an entity's name misspelt, a line cut short;
  * units: the length unit's prefix and name changed (PICO, EXA, none; INCH, a made-up one).
What must hold: facet-pack ends within its time (no hang), with exit 0, 1 or 2 (no signal: a
crash is a finding), writes no pack when it fails, and a pack it writes opens (facet-pack
--check). Findings are kept in --out with the command that reproduces them.

  step_fuzz.py --packer P --models DIR --out DIR [--runs N] [--jobs J] [--seed S] [--timeout SEC]
"""
import argparse
import concurrent.futures as cf
import os
import random
import re
import shutil
import subprocess
import sys
import time

MODELS = ['nist_ftc_11.stp', 'ndr_pivot_pin.stp', 'sg1_c5_214.stp', 'mic6_bed.step', 'mechanism.stp', 'io1_cm_214.stp']
EXTREMES = ['0.', '-0.', '1.E308', '-1.E308', '1.E-308', '1.E400', '-1.E400', '9999999999999999999', '-2147483649',
            '3.4E38', '1.E-45', '#1', '*', '$']
PREFIXES = ['.PICO.', '.EXA.', '$', '.MICRO.', '.KILO.', '.NANO.']
NAMES = ['.METRE.', '.INCH.', '.FOOT.', '.PARSEC.', '$']


def mutate(text, rng):
    """One to three edits of the text; returns the new text and what was done."""
    done = []
    for _ in range(rng.randint(1, 3)):
        kind = rng.choice(['reference', 'number', 'syntax', 'unit'])
        if kind == 'reference':
            refs = [m for m in re.finditer(r'#(\d+)', text)]
            if not refs:
                continue
            m = rng.choice(refs)
            ids = re.findall(r'^#(\d+)=', text, re.M)
            target = rng.choice(['99999', m.group(1), rng.choice(ids) if ids else '1', '0'])
            text = text[:m.start()] + '#' + target + text[m.end():]
            done.append(f'#{m.group(1)} -> #{target} at {m.start()}')
        elif kind == 'number':
            nums = [m for m in re.finditer(r'(?<![#\w.])-?\d+\.\d*(?:E[-+]?\d+)?', text)]
            if not nums:
                continue
            m = rng.choice(nums)
            new = rng.choice(EXTREMES)
            text = text[:m.start()] + new + text[m.end():]
            done.append(f'{m.group(0)} -> {new} at {m.start()}')
        elif kind == 'syntax':
            data = text.split('DATA;', 1)
            if len(data) != 2:
                continue
            body = data[1]
            marks = [i for i, c in enumerate(body) if c in ",()';="]
            if not marks:
                continue
            i = rng.choice(marks)
            how = rng.choice(['drop', 'double', 'misspell', 'cut'])
            if how == 'drop':
                body = body[:i] + body[i + 1:]
            elif how == 'double':
                body = body[:i] + body[i] + body[i:]
            elif how == 'misspell':
                words = [m for m in re.finditer(r'[A-Z_]{4,}', body)]
                if words:
                    w = rng.choice(words)
                    body = body[:w.start()] + w.group(0)[::-1] + body[w.end():]
            else:
                end = body.find('\n', i)
                body = body[:i] + (body[end:] if end >= 0 else '')
            text = data[0] + 'DATA;' + body
            done.append(f'syntax {how} at {i}')
        else:
            units = [m for m in re.finditer(r'SI_UNIT\(([^,]*),([^)]*)\)', text)]
            if not units:
                continue
            m = rng.choice(units)
            new = f'SI_UNIT({rng.choice(PREFIXES)},{rng.choice(NAMES)})'
            text = text[:m.start()] + new + text[m.end():]
            done.append(f'{m.group(0)} -> {new}')
    return text, '; '.join(done)


def one(args, run, texts):
    rng = random.Random(args.seed * 1_000_003 + run)
    name = rng.choice(sorted(texts))
    text, what = mutate(texts[name], rng)
    # A folder of the run's own: runs that share one (a slow run and a later one) would see
    # each other's packs.
    d = os.path.join(args.out, 'work', str(run))
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    step, fpk = os.path.join(d, 'in.stp'), os.path.join(d, 'out.fpk')
    with open(step, 'w', encoding='latin-1') as f:
        f.write(text)
    problem = None
    # No hang: facet-pack ends a file Open CASCADE cannot finish after two minutes and a second
    # per 8 KB (tools/facet-pack/main.cpp), so a run is a finding past that and a margin (a
    # healing that takes 100 s over a wild pcurve and then refuses the face is slow, not hung).
    timeout = args.timeout or 120 + len(text.encode('latin-1')) // 8192 + 15
    try:
        p = subprocess.run([args.packer, step, '-o', fpk, '--quiet'], capture_output=True, text=True, timeout=timeout)
        if p.returncode < 0 or p.returncode not in (0, 1, 2):
            problem = f'exit {p.returncode}: {p.stderr.strip()[-300:]}'
        elif p.returncode != 0 and os.path.exists(fpk):
            problem = f'exit {p.returncode} but a pack was written'
        elif p.returncode == 0:
            c = subprocess.run([args.packer, '--check', fpk], capture_output=True, text=True, timeout=timeout)
            if c.returncode != 0:
                problem = f'exit 0 with a pack --check refuses: {c.stderr.strip()[-300:]}'
    except subprocess.TimeoutExpired:
        problem = f'no end within {timeout} s'
    shutil.rmtree(d, ignore_errors=True)
    if problem:
        keep = os.path.join(args.out, f'finding-{args.seed}-{run}.stp')
        with open(keep, 'w', encoding='latin-1') as f:
            f.write(text)
        return f'{name} run {run} ({what}): {problem}\n  reproduce: {args.packer} {keep} -o /tmp/x.fpk'
    return None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--packer', required=True)
    ap.add_argument('--models', required=True)
    ap.add_argument('--out', required=True)
    ap.add_argument('--runs', type=int, default=200)
    ap.add_argument('--jobs', type=int, default=os.cpu_count() or 2)
    ap.add_argument('--seed', type=int, default=1)
    ap.add_argument('--timeout', type=float, default=None, help="a run's limit (s); default facet-pack's own bound and 15 s")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    texts = {}
    for m in MODELS:
        path = os.path.join(args.models, m)
        if os.path.exists(path):
            texts[m] = open(path, encoding='latin-1').read()
    if not texts:
        print(f'step_fuzz: no models in {args.models}', file=sys.stderr)
        return 1
    start = time.time()
    findings = []
    with cf.ThreadPoolExecutor(max_workers=args.jobs) as ex:
        for r in ex.map(lambda run: one(args, run, texts), range(args.runs)):
            if r:
                findings.append(r)
                print('FINDING', r, flush=True)
    took = time.time() - start
    print(f'step_fuzz: {args.runs} runs of facet-pack on mutated STEP text in {took:.0f} s '
          f'({args.runs / max(took, 1e-9):.1f} a second, {args.jobs} jobs): {len(findings)} findings')
    return 1 if findings else 0


if __name__ == '__main__':
    sys.exit(main())

#!/usr/bin/env python3
"""Mutation test of slidesim's input boundary (issue 12).

Makes seeded, deterministic mutants of the shipped inputs (lines deleted,
duplicated or cut, values replaced by NaN, Inf, 1e308, -1, 2147483648, texts,
logicals, very long texts, names misspelt, group ends removed, files cut
inside a group ...) and runs each through `slidesim --check`; a share of those
that pass also runs fully, with a short duration. Every run must:

  - end by itself (no signal, within the time limit);
  - exit 0, 1, 2, 3 or 4, with its documented meaning: 0 (and 4, a limit
    exceeded where &evaluation asks to fail on it) a complete result file
    without NaN or Inf, 1 no file at all and a message naming the input file,
    a line or a group, and a variable of the input (unless the message is
    about the file's structure: a group not closed, text outside a group),
    2 a file marked incomplete, 3 no file kept;
  - leave no temporary file;
  - never refuse in the run (exit 1) what --check passed: --check builds
    the models.

The geometry files of the contact inputs (*.geo) are mutated in place and
run through the input that names them.

The output mutants (issue 27) then name as an output a file the run reads
(the input itself, every file it names, the input renamed like the result's
XDMF view): exit 1, the file unchanged; and a private full device node
(mknod c 1 7 in the work folder, never the machine's /dev/full) as every
writer's file (-o, --summary-json, a sweep's csv_output): exit 3 before any
work, the node still a device, no result file.

usage: mutants.py SLIDESIM ROOT [--count N] [--seed S] [--full-share F]
"""
import argparse
import os
import random
import re
import shutil
import stat
import subprocess
import sys
import tempfile

import h5py
import numpy as np

VALUES = ['NaN', 'Inf', '-Inf', '+Inf', 'nan', '1e308', '-1e308', '1e400', '1e-320', '0', '-1', '0.0',
          '2147483648', '-2147483649', '99999999999999999999', '1.5', '2.5e3', '-0.0', "'text'", '.true.',
          '.false.', 'T', 'x', "''", "'" + 'x' * 300 + "'", '1,2', '3*1.0', ',', '']
TEXTS = ["'straight" + 'x' * 292 + "'", "'nonsense'", "''", '1.0', '.true.', 'plane', "'PLANE'", "'pl''ane'"]
GARBAGE = ['garbage', '&', '/', '&end', '!', "'", '"', 'x = 1', '&run /', '=', '(', ')', '\x00', 'é',
           '1 2 3', '$end']

NUMBER = re.compile(r'(?<![\w.])[-+]?(\d+\.?\d*|\.\d+)([eEdD][-+]?\d+)?(?![\w.])')
TEXT = re.compile(r"'[^']*'")
NAME = re.compile(r'\b([a-z_][a-z0-9_]*)\s*(\([^)]*\))?\s*=')


def mutate(text, rng):
    """One mutation of the input text: (description, new text)."""
    lines = text.split('\n')
    content = [i for i, line in enumerate(lines) if line.strip() and not line.strip().startswith('!')]
    i = rng.choice(content) if content else 0
    kind = rng.choice(['delete', 'duplicate', 'cut', 'value', 'value', 'value', 'value', 'text', 'name',
                       'end', 'garbage', 'swap', 'extra', 'long_line', 'empty', 'value_twice'])
    line = lines[i]
    if kind == 'delete':
        del lines[i]
    elif kind == 'duplicate':
        lines.insert(i, line)
    elif kind == 'cut':
        cut = rng.randrange(len(text) + 1)
        return f'cut at byte {cut}', text[:cut]
    elif kind in ('value', 'value_twice'):
        numbers = list(NUMBER.finditer(line))
        if not numbers:
            return mutate(text, rng)
        m = rng.choice(numbers)
        new = rng.choice(VALUES)
        lines[i] = line[:m.start()] + new + line[m.end():]
        if kind == 'value_twice':
            others = [j for j in content if NUMBER.search(lines[j])]
            j = rng.choice(others)
            m2 = rng.choice(list(NUMBER.finditer(lines[j])))
            lines[j] = lines[j][:m2.start()] + rng.choice(VALUES) + lines[j][m2.end():]
        kind = f'value {m.group(0)} -> {new!r}'
    elif kind == 'text':
        texts = list(TEXT.finditer(line))
        if not texts:
            return mutate(text, rng)
        m = rng.choice(texts)
        new = rng.choice(TEXTS)
        lines[i] = line[:m.start()] + new + line[m.end():]
        kind = f'text {m.group(0)} -> {new[:20]!r}'
    elif kind == 'name':
        names = list(NAME.finditer(line))
        if not names:
            return mutate(text, rng)
        m = rng.choice(names)
        name = m.group(1)
        k = rng.randrange(len(name))
        new = name[:k] + name[k + 1:] if len(name) > 1 else name + 'x'
        lines[i] = line[:m.start(1)] + new + line[m.end(1):]
        kind = f'name {name} -> {new}'
    elif kind == 'end':
        ends = [j for j, l in enumerate(lines) if l.strip() == '/' or l.rstrip().endswith('/')]
        if not ends:
            return mutate(text, rng)
        j = rng.choice(ends)
        lines[j] = lines[j].rstrip()[:-1]
        i = j
    elif kind == 'garbage':
        lines.insert(i, rng.choice(GARBAGE))
    elif kind == 'swap':
        if i + 1 < len(lines):
            lines[i], lines[i + 1] = lines[i + 1], lines[i]
    elif kind == 'extra':
        numbers = list(NUMBER.finditer(line))
        if not numbers:
            return mutate(text, rng)
        m = numbers[-1]
        lines[i] = line[:m.end()] + ', ' + m.group(0) + line[m.end():]
    elif kind == 'long_line':
        lines[i] = line + ' ' * 600 + '! long'
    elif kind == 'empty':
        return 'empty file', ''
    return f'{kind} at line {i + 1}', '\n'.join(lines)


def non_finite(path):
    """Names of the numeric datasets and attributes holding NaN or Inf."""
    bad = []
    with h5py.File(path, 'r') as f:
        def visit(name, obj):
            if isinstance(obj, h5py.Dataset) and obj.dtype.kind in 'fc' and not np.all(np.isfinite(obj[()])):
                bad.append(name)
            for key, value in obj.attrs.items():
                a = np.asarray(value)
                if a.dtype.kind in 'fc' and not np.all(np.isfinite(a)):
                    bad.append(f'{name}@{key}')
        f.visititems(visit)
        status = f.attrs.get('status')
    return (status.decode() if isinstance(status, bytes) else status), bad


# exit-1 messages about the structure of the file, where no variable is involved; also a whole
# group the run does not read ("FILE:LINE: &water is not read: the sled rides dry (it is the plain
# bar: &sled gives no vehicle)": the group and its line are the place, as group_injection.py asks)
STRUCTURAL = re.compile(r'is not closed|text outside a group|is empty|is not text|&end without|'
                        r'unknown namelist group|no &run group|appears more than once|without "=" and a value|'
                        r'unexpected "|not a namelist|expected a variable name|is missing: |without a group name|'
                        r'error: [^ ]+:\d+: &[a-z_]+ is not read: ')
# how a message names a variable: "&group: var ...", "var = value", "var(i) = value", unknown variable "var"
VARIABLE_NAMED = [re.compile(r'&[a-z_]+: ([a-z_][a-z0-9_]*)'),
                  re.compile(r'(?<![\w&%])([a-z_][a-z0-9_]*)(?:\([^)]*\))? = '),
                  re.compile(r'variable "([a-z_][a-z0-9_]*)"'),
                  re.compile(r'&[a-z_]+ ([a-z_][a-z0-9_]*)'),
                  re.compile(r'subscript ([a-z_][a-z0-9_]*)\('),
                  re.compile(r'change (?:the start \()?([a-z_][a-z0-9_]*)')]


def names_the_input(message, name, variables):
    """An exit-1 message names the input file and a line of it, or a group;
    and a variable of the input, unless it is about the file's structure
    (a group not closed, text outside a group, an empty file ...)."""
    if name not in message:
        return False
    if not (re.search(re.escape(name) + r':\d+:', message) or re.search(r'&[a-z_]+', message)
            or 'is empty' in message):
        return False
    if STRUCTURAL.search(message):
        return True
    return any(m.group(1) in variables for pattern in VARIABLE_NAMED for m in pattern.finditer(message))


def variable_names(*texts):
    """The variables the texts assign (lower case)."""
    return {m.group(1).lower() for text in texts for m in NAME.finditer(text.lower())}


# a file an input names: variable = 'path' or variable(i) = 'path' (patch_file(3)) outside comments (not built-in inputs);
# a file variable is `file` or `<something>_file` (not `bowl_profile`)
FILE_NAMED = re.compile(r"\b((?:\w+_)?file)(?:\(\d+\))?\s*=\s*'([^']+)'")


def output_mutants(slidesim, tree, work, failures, counts):
    """Outputs that would overwrite a file the run reads (exit 1, the file
    unchanged) and a private full device as every writer's file (exit 3, the
    node left a device, no result file)."""
    device = os.path.join(work, 'full')
    try:
        os.mknod(device, 0o666 | stat.S_IFCHR, os.makedev(1, 7))   # a private /dev/full
    except PermissionError:
        print('note: no device node can be made here (not root): the full-device output mutants are left out')
        device = None
    result = os.path.join(work, 'output_mutant.h5')
    cases = []   # (label, folder, arguments, the file that must stay as it is, exit status)
    for path in sorted(os.path.join(d, f) for d, _, fs in os.walk(tree) for f in fs if f.endswith('.nml')):
        folder, name = os.path.dirname(path), os.path.basename(path)
        label = os.path.relpath(path, tree)
        with open(path, encoding='utf-8') as f:
            text = f.read()
        named = {m.group(2) for line in text.split('\n') for m in FILE_NAMED.finditer(line.split('!')[0])
                 if not m.group(2).startswith('builtin:')}
        cases.append((f'{label}: -o the input', folder, ['--check', '-o', name, name], path, 1))
        for other in sorted(named):
            cases.append((f'{label}: -o {other}', folder, ['--check', '-o', other, name],
                          os.path.join(folder, other), 1))
        view = os.path.splitext(name)[0] + '.xmf'
        shutil.copy(path, os.path.join(folder, view))
        cases.append((f'{label} as {view}: -o its .h5', folder, ['--check', '-o', view[:-4] + '.h5', view],
                      os.path.join(folder, view), 1))
        if device is None:
            continue
        cases.append((f'{label}: -o a full device', folder, ['-o', device, name], device, 3))
        cases.append((f'{label}: --summary-json a full device', folder,
                      ['--summary-json', device, '-o', result, name], device, 3))
        if "scenario = 'sweep'" in text:
            cases.append((f'{label}: csv_output a full device', folder,
                          ['--set', f"sweep%csv_output='{device}'", '-o', result, name], device, 3))
    for label, folder, arguments, kept, want in cases:
        before = open(kept, 'rb').read() if want == 1 else None
        try:
            p = subprocess.run([slidesim, '-q', *arguments], cwd=folder, capture_output=True, timeout=60)
        except subprocess.TimeoutExpired:
            failures.append(f'output mutant {label}: no end within 60 s')
            continue
        err = p.stderr.decode('utf-8', 'replace')
        counts[('output', p.returncode)] = counts.get(('output', p.returncode), 0) + 1
        if p.returncode != want:
            failures.append(f'output mutant {label}: exit status {p.returncode}, expected {want}: {err[:300]}')
        if want == 1 and open(kept, 'rb').read() != before:
            failures.append(f'output mutant {label}: {kept} was changed')
        if want == 3 and not stat.S_ISCHR(os.stat(device).st_mode):
            failures.append(f'output mutant {label}: the device node was replaced')
            os.remove(device)
            os.mknod(device, 0o666 | stat.S_IFCHR, os.makedev(1, 7))
        if want == 3 and os.path.exists(result):
            failures.append(f'output mutant {label}: a result file was written before the refusal')
            os.remove(result)
        if arguments[-1].endswith('.xmf'):
            os.remove(os.path.join(folder, arguments[-1]))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument('slidesim')
    parser.add_argument('root')
    parser.add_argument('--count', type=int, default=int(os.environ.get('SLIDESIM_MUTANTS', 500)))
    parser.add_argument('--seed', type=int, default=12)
    parser.add_argument('--full-share', type=float, default=0.5)
    parser.add_argument('--check-timeout', type=float, default=60)
    parser.add_argument('--run-timeout', type=float, default=120)
    parser.add_argument('--verbose', action='store_true', help='print every mutant and its exit status')
    args = parser.parse_args()
    slidesim = os.path.abspath(args.slidesim)
    rng = random.Random(args.seed)

    work = tempfile.mkdtemp(prefix='slidesim_mutants_')
    failures = []
    counts = {}
    try:
        # the inputs tree copied, so that relative paths (geometry files, CSV) resolve
        tree = os.path.join(work, 'inputs')
        shutil.copytree(os.path.join(args.root, 'inputs'), tree)
        originals = sorted(os.path.join(d, f) for d, _, fs in os.walk(tree) for f in fs
                           if f.endswith('.nml') or f.endswith('.geo'))
        inputs = [o for o in originals if o.endswith('.nml')]
        for number in range(args.count):
            original = originals[number % len(originals)]
            with open(original, encoding='utf-8') as f:
                text = f.read()
            what, mutant = mutate(text, rng)
            label = f'mutant {number} ({os.path.relpath(original, tree)}: {what})'
            out = os.path.join(work, f'mutant_{number:04d}.h5')
            if original.endswith('.geo'):
                # a geometry file: mutated in place, run through the input that names it
                runner = next(i for i in inputs if "'" + os.path.relpath(original, os.path.dirname(i)) + "'"
                              in open(i, encoding='utf-8').read())
                path, folder, name = original, os.path.dirname(runner), os.path.basename(runner)
                named, context = os.path.basename(original), open(runner, encoding='utf-8').read()
            else:
                folder = os.path.dirname(original)
                name = f'mutant_{number:04d}.nml'
                path, named, context = os.path.join(folder, name), name, ''
            variables = variable_names(text, mutant, context)
            with open(path, 'w', encoding='utf-8', errors='surrogateescape') as f:
                f.write(mutant)

            def run(extra, timeout, phase):
                try:
                    p = subprocess.run([slidesim, '-q', *extra, '-o', out, name], cwd=folder, capture_output=True,
                                       timeout=timeout)
                except subprocess.TimeoutExpired:
                    failures.append(f'{label}, {phase}: no end within {timeout} s')
                    return None, ''
                err = p.stderr.decode('utf-8', 'replace')
                if p.returncode < 0 or p.returncode > 4:
                    failures.append(f'{label}, {phase}: exit status {p.returncode} (a signal?): {err[-300:]}')
                    return None, err
                counts[(phase, p.returncode)] = counts.get((phase, p.returncode), 0) + 1
                if args.verbose:
                    print(f'{label}, {phase}: exit {p.returncode} {err.strip()[:200]}')
                kept = os.path.exists(out)
                temporaries = [t for t in os.listdir(work) if t.startswith(os.path.basename(out) + '.')]
                if temporaries:
                    failures.append(f'{label}, {phase}: temporary files left: {temporaries}')
                if p.returncode == 1:
                    if kept:
                        failures.append(f'{label}, {phase}: exit 1 but a result file was written')
                    if not names_the_input(err, named, variables):
                        failures.append(f'{label}, {phase}: exit-1 message names no line, group or variable: '
                                        f'{err[:300]}')
                    if phase == 'run':
                        failures.append(f'{label}: --check passed an input that the run refuses: {err[:300]}')
                elif p.returncode == 3:
                    if kept:
                        failures.append(f'{label}, {phase}: exit 3 but a result file was kept')
                elif p.returncode == 2:
                    if not kept:
                        failures.append(f'{label}, {phase}: exit 2 but no result file')
                    elif non_finite(out)[0] != 'incomplete':
                        failures.append(f'{label}, {phase}: exit 2 but the file is not marked incomplete')
                elif p.returncode in (0, 4) and phase == 'run':
                    if not kept:
                        failures.append(f'{label}, {phase}: exit 0 but no result file')
                    else:
                        status, bad = non_finite(out)
                        if status != 'complete':
                            failures.append(f'{label}, {phase}: exit 0 but the file is {status!r}')
                        if bad:
                            failures.append(f'{label}, {phase}: NaN or Inf in a complete file: {bad[:5]}')
                elif p.returncode == 0 and kept:
                    failures.append(f'{label}, {phase}: --check wrote a result file')
                if os.path.exists(out):
                    os.remove(out)
                return p.returncode, p.stdout.decode('utf-8', 'replace')

            code, stdout = run(['--check'], args.check_timeout, 'check')
            if code == 0 and rng.random() < args.full_share:
                scenario = re.search(r'scenario (\w+)', stdout)
                extra = []
                if scenario and scenario.group(1) == 'geometry':
                    extra = ['--set', 'grid%n_u=40', '--set', 'grid%n_v=12', '--set', 'grid%n_frames=40']
                elif scenario and scenario.group(1) == 'optimize':
                    extra = ['--set', 'optimize%ftol=0.1', '--set', 'optimize%xtol=0.1']   # a few iterations
                    if '&sweep' in mutant.lower():   # a population: one start, 10 of its 50 rides
                        extra += ['--set', 'sweep%heading0_deg=0', '--set', 'optimize%starts=1', '--unset',
                                  'optimize%seed']
                elif scenario:
                    extra = ['--set', 'solver%duration=0.5']
                # the short run is another input: checked as such first
                code, _ = run(['--check', *extra], args.check_timeout, 'check')
                if code == 0:
                    run(extra, args.run_timeout, 'run')
            if original.endswith('.geo'):
                with open(original, 'w', encoding='utf-8') as f:
                    f.write(text)
            else:
                os.remove(path)
        output_mutants(slidesim, tree, work, failures, counts)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    summary = ', '.join(f'{phase} exit {code}: {n}' for (phase, code), n in sorted(counts.items()))
    print(f'{args.count} mutants (seed {args.seed}): {summary}')
    for failure in failures:
        print('FAIL ' + failure)
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())

#!/usr/bin/env python3
"""Classify every repetition `duplicates` finds in src/ and write docs/duplicates.md.

`duplicates --repo src` (a tool outside the project; `duplicates --help`)
lists pairs of places in src/ that share six or more lines, the same or of
the same shape. Issue 24 asks that none of them be repeated logic: each pair
is written once, or classified here with its reason (shape-only,
boilerplate, kept-for-speed, ...).

The rules, scripts/duplicates_classes.tsv, match a pair by its CONTENT, not
by its files: a rule's key is a hash of both sides' files, their normalised
lines (blank and comment lines dropped, white space folded) and the number
of further runs the two files share (the tool's "(+N more runs)"). A new
repetition between two files already classified changes that number, or the
longest run, and so the key: it comes out unclassified. A rule whose key no
pair has any more is reported as stale.

Usage (from anywhere; it works in the repository root):
  classify_duplicates.py            write docs/duplicates.md; exit 1 if a
                                    pair is unclassified (marked so in the file)
  classify_duplicates.py --check    exit 0 when every pair is classified and
                                    docs/duplicates.md is what it would write;
                                    1 otherwise (saying why); 77 (ctest's
                                    SKIP_RETURN_CODE) when `duplicates` is not
                                    on this machine
  classify_duplicates.py --propose  print a rule line for each unclassified
                                    pair (class and reason to fill in)
  classify_duplicates.py --prune    remove the rules no pair matches (printed)
  classify_duplicates.py --import FILE  add rules from lines
                                    `fileA:lo-hi ~ fileB:lo-hi | class | reason`
                                    (paths below src/) matched to the current pairs
"""
import hashlib
import os
import re
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RULES = os.path.join(ROOT, 'scripts', 'duplicates_classes.tsv')
DOC = os.path.join(ROOT, 'docs', 'duplicates.md')
MOST = 200          # the tool lists at most 200 pairs; the rest are boilerplate (checked)
SECONDS = 300
SKIP = 77
CLASSES = {
    'shape-only': 'the same shape with other names, values or formulas: different logic',
    'boilerplate': 'declarations, interfaces, argument lists, a call sequence every such routine has',
    'kept-for-speed': 'the logic is the same, kept apart on a hot path (measured)',
    'data': 'tables of declarations or constants: data, not logic',
    'interface-body': "a submodule procedure's interface and its body (Fortran requires both)",
    'typed-twin': 'the same steps on two unrelated types; Fortran has no generic procedure over them',
    'open': 'repeated logic not yet written once: listed so that it is not lost (issue 24 is not met while '
            'any pair has this class)',
}
ROW = re.compile(r'^D\d+ (\S+):(\d+)-(\d+) ~ (\S+):(\d+)-(\d+)(.*)$')


def run_duplicates():
    """The tool's output lines for src/, or None when it is not installed."""
    tool = shutil.which('duplicates')
    if tool is None:
        return None
    done = subprocess.run([tool, '--repo', 'src', '--most', str(MOST), '--seconds', str(SECONDS)],
                          cwd=ROOT, capture_output=True, text=True, check=False)
    return done.stdout.splitlines()


def normalised(path, lo, hi):
    """Lines lo..hi of src/path without blank and comment lines, white space folded."""
    with open(os.path.join(ROOT, 'src', path), encoding='utf-8') as f:
        lines = f.read().splitlines()[lo - 1:hi]
    out = []
    for line in lines:
        text = ' '.join(line.split())
        if text and not text.startswith('!') and not text.startswith('#'):
            out.append(text)
    return out


class Pair:
    def __init__(self, match):
        a, alo, ahi, b, blo, bhi, rest = match.groups()
        self.sides = [(a, int(alo), int(ahi)), (b, int(blo), int(bhi))]
        more = re.search(r'\(\+(\d+) more runs?\)', rest)
        self.more = int(more.group(1)) if more else 0
        self.shape = ' shape' in rest
        self.boilerplate = ' boilerplate' in rest
        texts = [(path, normalised(path, lo, hi)) for path, lo, hi in self.sides]
        texts.sort()
        digest = hashlib.sha256()
        for path, lines in texts:
            digest.update(path.encode() + b'\0' + '\n'.join(lines).encode() + b'\0')
        digest.update(str(self.more).encode())
        self.key = digest.hexdigest()[:16]
        telling = [line for line in texts[0][1] if not re.match(r'^(end\b|contains$|else$|return$)', line)]
        self.first_line = (telling or texts[0][1] or [''])[0]

    def files(self):
        a, b = sorted(path for path, _, _ in self.sides)
        return f'{a} (twice)' if a == b else f'{a} ~ {b}'

    def where(self):
        return ' ~ '.join(f'{p}:{lo}-{hi}' for p, lo, hi in self.sides)

    def tool_marks(self):
        marks = [m for m, on in (('shape', self.shape), ('boilerplate', self.boilerplate)) if on]
        return ' '.join(marks) if marks else 'identical'


def parse(lines):
    """The pairs, the header line and the tool's closing lines; raises on an incomplete run."""
    pairs, notes, header = [], [], ''
    for line in lines:
        match = ROW.match(line)
        if match:
            pairs.append(Pair(match))
        elif line.startswith('incomplete:'):
            raise RuntimeError('duplicates did not read or pair everything: ' + line)
        elif re.match(r'^\d+ pairs of places|^no duplicates', line):
            header = line
        elif line.strip():
            notes.append(line.strip())
    cut = 0
    for note in notes:
        more = re.match(r'^\(\+(\d+) more pairs\)$', note)
        if more:
            cut = int(more.group(1))
    if cut and pairs and not pairs[-1].boilerplate:
        raise RuntimeError(f'{cut} pairs beyond the {MOST} listed and the last listed is not boilerplate: '
                           'pairs that are not boilerplate may be cut (the tool lists boilerplate last)')
    return pairs, header, [n for n in notes if not n.startswith('(+')], cut


def read_rules():
    rules = {}
    if not os.path.exists(RULES):
        return rules
    with open(RULES, encoding='utf-8') as f:
        for number, line in enumerate(f, 1):
            if not line.strip() or line.startswith('#'):
                continue
            fields = line.rstrip('\n').split('\t')
            if len(fields) < 3 or fields[1] not in CLASSES:
                raise RuntimeError(f'{RULES}:{number}: want key<TAB>class<TAB>reason[<TAB>files], class one of '
                                   f'{", ".join(CLASSES)}: {line.strip()}')
            rules[fields[0]] = (fields[1], fields[2])
    return rules


def write_rules(rules, pairs):
    """Rewrites the rules file: the header, then each rule with the files of its pair (sorted)."""
    by_key = {p.key: p for p in pairs}
    with open(RULES, encoding='utf-8') as f:
        head = [line for line in f if line.startswith('#')]
    rows = []
    for key, (cls, reason) in rules.items():
        files = by_key[key].files() if key in by_key else '(no pair now)'
        rows.append((files, key, cls, reason))
    rows.sort()
    with open(RULES, 'w', encoding='utf-8') as f:
        f.writelines(head)
        for files, key, cls, reason in rows:
            f.write(f'{key}\t{cls}\t{reason}\t{files}\n')


def document(pairs, header, notes, cut, rules):
    out = ['# Repetitions in src/ and why each stays',
           '',
           'Generated by `scripts/classify_duplicates.py` from `duplicates --repo src --most '
           f'{MOST}`',
           'and the rules in `scripts/duplicates_classes.tsv`; do not edit by hand (`python3',
           'scripts/classify_duplicates.py` writes it again; the test `duplicates_classified` fails',
           'when it is stale or a pair is unclassified). Issue 24 asks that `duplicates` find no',
           'repeated logic in src/: each pair below is one the tool lists, with its class and the',
           'reason, given by reading both sides (pairs of declarations, constructors and call',
           'sequences by their form, with spot checks). A rule matches a pair by content (a hash of',
           'both sides\' lines and of how many more runs the two files share), so an edit of either',
           'side, or a new repetition between the same files, needs a new look.',
           '',
           'Classes:',
           '']
    for cls, meaning in CLASSES.items():
        out.append(f'- **{cls}**: {meaning}.')
    out += ['', f'The tool: {header}.' if header else '', '']
    if cut:
        out.append(f'Beyond the {MOST} pairs it lists, {cut} more, all marked boilerplate by the tool (it lists '
                   'boilerplate last; the script checks that the last listed pair is boilerplate), are not '
                   'classified one by one.')
    for note in notes:
        out.append(f'The tool also says: "{note}".')
    out += ['', '| files | first shared line | tool | class | reason |', '| --- | --- | --- | --- | --- |']
    rows = []
    for p in pairs:
        cls, reason = rules.get(p.key, ('UNCLASSIFIED', 'no rule matches this content: read both sides, write '
                                        'the logic once or add a rule (--propose)'))
        first = p.first_line.replace('|', '\\|')
        if len(first) > 60:
            first = first[:57] + '...'
        rows.append((p.files(), first, p.tool_marks(), cls, reason.replace('|', '\\|')))
    rows.sort()
    for row in rows:
        out.append('| ' + ' | '.join(f'`{c}`' if i < 2 and c else c for i, c in enumerate(row)) + ' |')
    counts = {}
    for row in rows:
        counts[row[3]] = counts.get(row[3], 0) + 1
    out += ['', 'Pairs per class: ' + ', '.join(f'{k} {v}' for k, v in sorted(counts.items())) + '.', '']
    return '\n'.join(out)


def import_rules(path, pairs, rules):
    """Rules from `fileA:lo-hi ~ fileB:lo-hi | class | reason` lines, matched to the pairs by overlap."""
    added = 0
    with open(path, encoding='utf-8') as f:
        for line in f:
            parts = [x.strip() for x in line.split('|')]
            if len(parts) < 3 or '~' not in parts[0]:
                continue
            sides = []
            for side in parts[0].split('~'):
                m = re.match(r'^(?:src/)?(\S+):(\d+)-(\d+)$', side.strip())
                if m:
                    sides.append((m.group(1), int(m.group(2)), int(m.group(3))))
            cls = parts[1]
            if len(sides) != 2 or cls not in CLASSES:
                print(f'not imported (form or class): {line.strip()}', file=sys.stderr)
                continue
            found = None
            for p in pairs:
                if all(any(path == q[0] and lo <= q[2] and q[1] <= hi for q in p.sides) for path, lo, hi in sides):
                    found = p
                    break
            if found is None:
                print(f'not imported (no such pair now): {line.strip()}', file=sys.stderr)
                continue
            rules[found.key] = (cls, '|'.join(parts[2:]).strip())
            added += 1
    return added


def main(argv):
    mode = argv[1] if len(argv) > 1 else ''
    if mode not in ('', '--check', '--propose', '--import', '--prune'):
        print(__doc__, file=sys.stderr)
        return 2
    lines = run_duplicates()
    if lines is None:
        print('duplicates_classified: skipped: the `duplicates` command is not on this machine '
              '(it is not part of the project; a fresh CI machine has none)')
        return SKIP if mode == '--check' else 1
    try:
        pairs, header, notes, cut = parse(lines)
        rules = read_rules()
    except RuntimeError as e:
        print(f'classify_duplicates: {e}', file=sys.stderr)
        return 1
    unclassified = [p for p in pairs if p.key not in rules]
    stale = sorted(set(rules) - {p.key for p in pairs})
    if mode == '--propose':
        for p in unclassified:
            print(f'{p.key}\tCLASS\tREASON\t{p.files()}\t# {p.where()} ({p.tool_marks()}, +{p.more} runs)')
        return 0
    if mode == '--prune':
        for key in stale:
            print(f'removed {key}\t{rules[key][0]}\t{rules[key][1]}')
            del rules[key]
        write_rules(rules, pairs)
        return 0
    if mode == '--import':
        added = import_rules(argv[2], pairs, rules)
        write_rules(rules, pairs)
        print(f'{added} rules imported')
        return 0
    text = document(pairs, header, notes, cut, rules)
    for key in stale:
        print(f'classify_duplicates: the rule {key} ({rules[key][0]}) matches no pair now: remove it',
              file=sys.stderr)
    for p in unclassified:
        print(f'classify_duplicates: UNCLASSIFIED {p.where()} ({p.tool_marks()}, +{p.more} runs)',
              file=sys.stderr)
    if mode == '--check':
        current = open(DOC, encoding='utf-8').read() if os.path.exists(DOC) else ''
        ok = not unclassified and not stale and current == text
        if current != text:
            print('classify_duplicates: docs/duplicates.md is stale: run python3 scripts/classify_duplicates.py',
                  file=sys.stderr)
        print(f'duplicates_classified: {len(pairs)} pairs, {len(unclassified)} unclassified, '
              f'{len(stale)} stale rules, docs/duplicates.md {"current" if current == text else "stale"}')
        return 0 if ok else 1
    with open(DOC, 'w', encoding='utf-8') as f:
        f.write(text)
    print(f'docs/duplicates.md: {len(pairs)} pairs, {len(unclassified)} unclassified, {len(stale)} stale rules')
    return 1 if unclassified or stale else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))

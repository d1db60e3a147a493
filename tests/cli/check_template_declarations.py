"""Checks the templates of --default-input against the declarations.

    check_template_declarations.py REFERENCE.md TEMPLATE.nml [TEMPLATE.nml ...]

REFERENCE.md is what `slidesim --input-reference` prints: one table per
declared group (unit, default, allowed). In every template, an assignment of
a declared group whose comment starts with a unit (`mass = 68.5  ! kg, ...`)
must name the declared unit, a comment of a single assignment that gives a
range (`! kg, 10 .. 300`, `> 0 .. 50`) must give the declared one, and each
number given must lie in the declared range and each word among the
declared words. So a template cannot show a unit or a range the reader does
not check. Prints failures; exit status 1 if any.
"""
import re
import sys

NUMBER = r'[-+]?(?:\d+\.?\d*|\.\d+)(?:[eEdD][-+]?\d+)?'
failures = []


def number(text):
    return float(text.replace('d', 'e').replace('D', 'e'))


def read_reference(path):
    """{group: {name: (unit, low, high, open_low, words)}}; a group read
    differently by two scenarios is keyed 'group scenario'."""
    groups, group = {}, None
    for line in open(path, encoding='utf-8'):
        heading = re.match(r'### &(\w+)(?: \(scenario (\w+)\))?', line)
        if heading:
            group = groups.setdefault(' '.join(h for h in heading.groups() if h), {})
            continue
        cells = [c.strip() for c in line.strip().strip('|').split('|')]
        if group is None or len(cells) != 5 or not cells[0].startswith('`'):
            continue
        name, unit, allowed = cells[0].strip('`'), cells[2], cells[4]
        bounds = re.fullmatch(r'(> )?(?:whole number )?(\S+) … (\S+)', allowed)
        words = re.findall(r'`([^`]+)`', allowed) if allowed.startswith('`') else None
        if bounds:
            group[name] = (unit, number(bounds.group(2)), number(bounds.group(3)), bool(bounds.group(1)), None)
        else:
            group[name] = (unit, None, None, False, words)
    # the ride's water integrator has the variables of &solver
    groups['water_solver'] = groups.get('solver', {})
    return groups


def assignments(code):
    """[(name, values text)] of `a = 1, 2, b = 'x'` (no '=' inside values)."""
    parts = re.split(r'(\b[A-Za-z_]\w*)\s*=', code)
    return [(parts[i].lower(), parts[i + 1].strip().rstrip(',').strip()) for i in range(1, len(parts) - 1, 2)]


def check(template, reference):
    units = sorted({d[0] for g in reference.values() for d in g.values() if d[0] not in ('–', '1')},
                   key=len, reverse=True)
    group = None
    text = open(template, encoding='utf-8').read()
    scenario = re.search(r"scenario\s*=\s*'(\w+)'", text)
    scenario = scenario.group(1) if scenario else 'ride'
    for number_, line in enumerate(text.splitlines(), 1):
        where = f'{template}:{number_}'
        opened = re.match(r'\s*&(\w+)', line)
        if opened:
            name = opened.group(1).lower()
            group = reference.get(f'{name} {scenario}', reference.get(name))
            continue
        if re.match(r'\s*/', line):
            group = None
            continue
        if group is None or line.lstrip().startswith('!'):
            continue
        code, _, comment = line.partition('!')
        comment = comment.strip()
        given = assignments(code)
        for name, values in given:
            if name not in group:
                continue   # refused by slidesim --check (cli_check_option)
            unit, low, high, open_low, words = group[name]
            # the comment's unit
            shown = next((u for u in units if re.match(re.escape(u) + r'(?=$|[ ,:;)])', comment)), None)
            if shown is not None and shown != unit and unit != '–':   # '–': the comment is another's
                failures.append(f'{where}: {name}: the comment says {shown!r}, the declaration {unit!r}')
            # the comment's range (one assignment on the line)
            shown_range = re.search(r'(>\s*)?(' + NUMBER + r')\s*\.\.\s*(' + NUMBER + r')', comment)
            if shown_range and len(given) == 1 and low is not None:
                if (number(shown_range.group(2)), number(shown_range.group(3)), bool(shown_range.group(1))) != \
                        (low, high, open_low):
                    failures.append(f'{where}: {name}: the comment gives the range {shown_range.group(0)!r}, '
                                    f'the declaration {"> " if open_low else ""}{low} .. {high}')
            # the values
            for value in re.findall(r"'[^']*'|[^,\s]+", values):
                if value.startswith("'"):
                    if words and value.strip("'").lower() not in words:
                        failures.append(f'{where}: {name} = {value}: not one of the declared words {words}')
                elif low is not None and re.fullmatch(NUMBER, value):
                    x = number(value)
                    if not (x <= high and (x > low if open_low else x >= low)):
                        failures.append(f'{where}: {name} = {value}: outside the declared range {low} .. {high}')


def main():
    reference = read_reference(sys.argv[1])
    if not reference.get('water') or not reference.get('rider'):
        failures.append(f'{sys.argv[1]}: no tables of &water and &rider')
    for template in sys.argv[2:]:
        check(template, reference)
    for failure in failures:
        print('FAIL ' + failure)
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())

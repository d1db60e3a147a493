#!/usr/bin/python3
"""Reference table for base_text::format_real (the number texts of every
message, report and JSON file), made independently of slidesim's code: the
fewest significant digits come from Python's repr (the shortest text that
reads back as the double, David Gay's / Ryu's algorithm in CPython), the
layout from the rule docs/outputs.md states for format_real:

- plain notation when the shortest text's decimal exponent e (x ~ d.ddd 10^e)
  lies in -3..6, with max(n - 1 - e, 1) decimals (n = repr's significant
  digits), trailing zeros removed down to one decimal;
- otherwise exponent notation d.ddd with at least one decimal, the letter E,
  a sign and at least two exponent digits (1.0E+308, 5.0E-324);
- NaN, Inf, -Inf as such (not in the table: tests/base/test_base.f90 checks them).

Run from the repository root with Debian's interpreter (no packages needed):
    /usr/bin/python3 scripts/reference/number_texts.py
It writes tests/reference/number_texts.txt: '#' comment lines, then one double
per line as its 64 bits in 16 hexadecimal digits and the expected text,
read by tests/base/test_base.f90.
"""
import math
import os
import random
import struct
from decimal import Decimal

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'tests', 'reference',
                   'number_texts.txt')


def bits(x):
    return struct.unpack('<Q', struct.pack('<d', x))[0]


def from_bits(b):
    return struct.unpack('<d', struct.pack('<Q', b))[0]


def expected_text(x):
    """format_real's text for a finite double x, by the rule above."""
    shortest = Decimal(repr(x))   # repr: the shortest digits that read back
    sign, digits, exponent = shortest.as_tuple()
    digits = list(digits)
    while len(digits) > 1 and digits[-1] == 0:   # 123.0 -> digits 123
        digits.pop()
        exponent += 1
    n = len(digits)
    e = exponent + n - 1   # of the shortest text d.ddd x 10^e (0 for zero)
    if -3 <= e <= 6:
        text = format(shortest, '.%df' % max(n - 1 - e, 1))   # repr's digits, laid out plain
        while len(text) > 2 and text.endswith('0') and text[-2] != '.':
            text = text[:-1]
        return text
    mantissa = ''.join(str(d) for d in digits)
    if len(mantissa) == 1:
        mantissa += '0'
    return '%s%s.%sE%+03d' % ('-' if sign else '', mantissa[0], mantissa[1:], e)


def doubles():
    rng = random.Random(20261124)
    values = [0.0, 2.2250738585072014e-308]
    for _ in range(500):   # every magnitude
        values.append((rng.random() - 0.5) * 10.0 ** int(615 * rng.random() - 307))
    for _ in range(500):   # random bit patterns, either sign, below 2**1023 (finite)
        x = from_bits(rng.getrandbits(62) | (rng.getrandbits(1) << 63))
        if math.isfinite(x) and x != 0:
            values.append(x)
    for k in range(-1074, 1024):   # every power of two (asymmetric read-back intervals)
        values.append(math.ldexp(1.0, k))
        values.append(math.ldexp(-3.0, k - 2))
    for k in (-20, -7, -5, -4, -3, -2, -1, 0, 1, 2, 5, 6, 7, 8, 20):   # one and two digits
        for i in range(1, 100):
            values.append(float(Decimal(i) * Decimal(10) ** k))
    for k in range(0, 1001):   # as the outputs have: hundredths, sevenths
        values.append(0.01 * k)
        values.append(k / 7.0)
    for x in (1.7976931348623157e308, -1.7976931348623157e308, 1e308, 1e100, 1e-100, 1e-320,
              -1.5e-310, 5e-324, 1.5e-323, 1e23, 9.999999999999999e22, 0.001, 0.0009999999999999998,
              9999999.999999998, 1e7, 999999.9999999999, 0.1, 0.2, 0.30000000000000004):
        values.append(x)
    return values


def main():
    values = doubles()
    lines = ['# format_real reference: 64-bit pattern (hex), expected text.',
             '# Made by scripts/reference/number_texts.py (Python repr for the fewest digits;',
             '# the layout rule in its docstring). %d doubles.' % len(values)]
    for x in values:
        lines.append('%016x %s' % (bits(x), expected_text(x)))
    with open(OUT, 'w') as f:
        f.write('\n'.join(lines) + '\n')
    print('wrote %s (%d doubles)' % (os.path.normpath(OUT), len(values)))


if __name__ == '__main__':
    main()

#!/usr/bin/env python3
"""Checks a slidesim result file: prints its status ('complete' or 'incomplete')
and exits 1 if a file marked complete holds a non-finite number (NaN, Inf) in
any numeric dataset or attribute, 2 if it cannot be read as a result file.

usage: check_result.py FILE
"""
import sys

import h5py
import numpy as np


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def main():
    path = sys.argv[1]
    try:
        f = h5py.File(path, 'r')
    except OSError as error:
        print(f'unreadable: {error}')
        return 2
    with f:
        status = text(f.attrs.get('status', 'none'))
        bad = []

        def visit(name, obj):
            if isinstance(obj, h5py.Dataset) and obj.dtype.kind in 'fc':
                if not np.all(np.isfinite(obj[()])):
                    bad.append(name)
            for key, value in obj.attrs.items():
                array = np.asarray(value)
                if array.dtype.kind in 'fc' and not np.all(np.isfinite(array)):
                    bad.append(f'{name}@{key}')

        f.visititems(visit)
        print(status)
        if status == 'complete' and bad:
            print('non-finite numbers in a complete file: ' + ', '.join(bad))
            return 1
    return 0


if __name__ == '__main__':
    sys.exit(main())

#!/usr/bin/python3
"""Median process CPU time (user + system) of a command run N times.

usage: process_cpu.py N command [args ...]
Prints one line: median, user and system medians, min, max (seconds). The
command's output is discarded; it must exit 0. Measures what a user's shell
would report for the whole process (start-up, work, files, exit).
"""
import resource
import statistics
import subprocess
import sys


def main(argv):
    if len(argv) < 3:
        print(__doc__)
        return 1
    n = int(argv[1])
    command = argv[2:]
    user, system = [], []
    for _ in range(n):
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        user.append(after.ru_utime - before.ru_utime)
        system.append(after.ru_stime - before.ru_stime)
    total = [u + s for u, s in zip(user, system)]
    print(f"{statistics.median(total):.4f} {statistics.median(user):.4f} {statistics.median(system):.4f} "
          f"{min(total):.4f} {max(total):.4f}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

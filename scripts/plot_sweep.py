#!/usr/bin/python3
"""Plots a sweep's envelope: felt g, top speed, lever arm against a swept variable.

    scripts/plot_sweep.py RESULT.h5 [--x mass] [-o PICTURE] [--show]

is `slidesim-plot --kind sweep` of the slidesim Python package (python/), used
from this checkout without installing it.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), os.pardir, "python"))
from slidesim.plot import main  # noqa: E402  (the standard library only: a missing module is named)

sys.exit(main(["--kind", "sweep", *sys.argv[1:]]))

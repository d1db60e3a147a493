#!/usr/bin/python3
"""Plots the rider-friction identification: measured against simulated.

    scripts/plot_identify_rider.py RESULT.h5 [-o PICTURE] [--show]

is `slidesim-plot --kind identify_rider` of the slidesim Python package (python/), used
from this checkout without installing it.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), os.pardir, "python"))
from slidesim.plot import main  # noqa: E402  (the standard library only: a missing module is named)

sys.exit(main(["--kind", "identify_rider", *sys.argv[1:]]))

#!/usr/bin/python3
"""Plots the water: the unrolled slide (thesis fig. 4.11), speed and height, the band in 3-D.

    scripts/plot_water.py RESULT.h5 [-o PICTURE] [--show]

is `slidesim-plot --kind water` of the slidesim Python package (python/), used
from this checkout without installing it.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), os.pardir, "python"))
from slidesim.plot import main  # noqa: E402  (the standard library only: a missing module is named)

sys.exit(main(["--kind", "water", *sys.argv[1:]]))

#!/usr/bin/python3
"""Plots a ride: the contacts and the water band unrolled, speed, felt g, normal forces, 3-D.

    scripts/plot_ride.py RESULT.h5 [-o PICTURE] [--show]

is `slidesim-plot --kind ride` of the slidesim Python package (python/), used
from this checkout without installing it.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), os.pardir, "python"))
from slidesim.plot import main  # noqa: E402  (the standard library only: a missing module is named)

sys.exit(main(["--kind", "ride", *sys.argv[1:]]))

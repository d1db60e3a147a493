#!/usr/bin/python3
"""Plots a slidesim result, the plot chosen by its scenario:

    scripts/plot.py RESULT.h5 [-o PICTURE] [--show] [--kind KIND]

is `slidesim-plot` of the slidesim Python package (python/), used from this
checkout without installing it (scripts/plot.py --help lists the plots).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), os.pardir, "python"))
from slidesim.plot import main  # noqa: E402  (the standard library only: a missing module is named)

sys.exit(main())

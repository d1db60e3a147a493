"""The plain reader of slidesim results, kept importable from scripts/ for
scripts that did `sys.path.insert(0, 'scripts'); from slidesim_results import
open_result`: it is slidesim.results of the Python package (python/)."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), os.pardir, "python"))
from slidesim.results import Quantity, Result, ResultFileError, open_result  # noqa: E402,F401

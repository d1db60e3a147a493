"""python -m slidesim.plot RESULT.h5 [-o PICTURE] ...: as slidesim-plot."""
import sys

from . import main

sys.exit(main())

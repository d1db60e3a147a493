"""slidesim's results in Python: open a result file as xarray Datasets, the
ride report as a pandas DataFrame, every plot (slidesim.plot, slidesim-plot).

    import slidesim
    run = slidesim.open("ride.h5")
    run.scenario, run.status           # 'ride', 'complete'
    run["/rider"]                      # an xarray Dataset with its coordinates
    run.ride_report()                  # a pandas DataFrame, one row per output time

The layout of the files is docs/outputs.md; slidesim.results.open_result is
the plain reader (h5py and numpy only). The modules this package needs
(h5py, numpy, xarray, pandas, matplotlib) are imported when used, so a
missing one is named with the package to install.
"""

__version__ = "0.1.0"


def open(path):
    """The result file at `path` as a slidesim.data.Run (xarray Datasets)."""
    from .data import Run
    return Run(path)

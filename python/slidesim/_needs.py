"""A clear message when a module the package needs is missing: which one,
and which package brings it (Debian's or PyPI's)."""

DEBIAN = {"h5py": "python3-h5py", "numpy": "python3-numpy", "matplotlib": "python3-matplotlib",
          "xarray": "python3-xarray", "pandas": "python3-pandas"}


class MissingModule(ImportError):
    """A module slidesim needs is not installed where this Python looks."""


def need(error):
    """The MissingModule for a ModuleNotFoundError, naming the packages."""
    import sys
    name = (error.name or "?").split(".")[0]
    debian = DEBIAN.get(name, f"python3-{name}")
    return MissingModule(
        f"the Python module '{name}' is missing for {sys.executable}: install it with "
        f"'apt-get install {debian}' (Debian's, for /usr/bin/python3: scripts/install-dependencies.sh) "
        f"or 'python3 -m pip install ./python' from the repository (in a virtual environment: "
        f"the slidesim package and what it needs)")

"""cueball: physics of billiard balls (closed forms, no time steps).

The package holds the extension module ``cueball._cueball`` (the C++ library's
bindings, python/src/) and re-exports all of it, so ``cueball.simulate``,
``cueball.Result``, ``cueball.InvalidArgument``... are the extension's own.
Pure-Python layers sit beside it and are imported on demand:

- ``cueball.dask``: ``simulate_many`` in chunks across a Dask distributed
  cluster (Debian's python3-distributed), bit-identical to a local run.

Units, sign conventions and defaults: see ``help(cueball._cueball)`` and
python/README.md.
"""

from ._cueball import *  # noqa: F401,F403 (the extension's public API is the package's)
from ._cueball import __doc__ as _extension_doc
from ._cueball import __version__ as __version__
from ._cueball import _time_run_scenario as _time_run_scenario

__doc__ = f"{__doc__}\n{_extension_doc}"

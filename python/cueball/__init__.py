"""cueball: physics of billiard balls (closed forms, no time steps).

The package holds the extension module ``cueball._cueball`` (the C++ library's
bindings, python/src/) and re-exports all of it, so ``cueball.simulate``,
``cueball.Result``, ``cueball.InvalidArgument``... are the extension's own.
Pure-Python layers sit beside it and are imported on demand:

- ``cueball.dask``: ``simulate_many`` in chunks across a Dask distributed
  cluster (Debian's python3-distributed), bit-identical to a local run.
- ``cueball.games``: games by their rules (states, actions, play, agents,
  records), the extension's submodule ``games`` (stubs: games.pyi).
- ``cueball._arguments``: applied at import, names an argument of the wrong
  Python type (``cueball.InvalidArgumentType``) where pybind11 would list every
  signature.

Units, sign conventions and defaults: see ``help(cueball._cueball)`` and
python/README.md.
"""

from . import _cueball
from ._arguments import name_wrong_types as _name_wrong_types

_name_wrong_types(_cueball)  # wrong argument types as InvalidArgumentType naming the argument

from ._cueball import *  # noqa: E402,F401,F403 (the extension's public API is the package's)
from ._cueball import __doc__ as _extension_doc
from ._cueball import __version__ as __version__
from ._cueball import _time_run_scenario as _time_run_scenario
from . import games as games  # the extension's submodule, put here by the * import above

import sys as _sys

_sys.modules[__name__ + ".games"] = games  # `import cueball.games` and `from cueball.games import ...`

__doc__ = f"{__doc__}\n{_extension_doc}"

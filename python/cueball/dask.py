"""simulate_many across a Dask distributed cluster, bit-identical to a local run.

    from distributed import Client, LocalCluster
    import cueball.dask

    with LocalCluster(n_workers=2, threads_per_worker=1) as cluster, Client(cluster) as client:
        out = cueball.dask.simulate_many(client, None, actions, noise=True, seed=7)

The rows are split into chunks; chunk ``[lo, hi)`` runs on a worker as
``cueball.simulate_many(scenario, actions[lo:hi], layouts[lo:hi], ...,
first_shot=lo)``, so its shots draw the noise of rows ``lo .. hi-1`` of the
whole study (shot k's noise depends on the seed and k only) and its errors name
the whole study's rows. The concatenated arrays are therefore exactly those of
``cueball.simulate_many(scenario, actions, layouts, ...)`` on one machine,
whatever the number of workers or the chunk size, and a study may hold more
than the million rows one local call takes.

Every worker needs this same version of cueball importable (install it on each
machine; the task fails on a worker that has another). The scenario is read on
the client (a path is read there, not on the workers) and sent once to every
worker.
"""

from __future__ import annotations

import math
import os
import time
from typing import TYPE_CHECKING, Any, Mapping, cast

import numpy as np
from numpy.typing import NDArray

from . import _cueball
if TYPE_CHECKING:  # a TypedDict of the stubs only
    from ._cueball import ManyOutcomes

# The per-shot arrays of simulate_many's result, concatenated along the rows.
PER_SHOT = ("present", "pocketed", "pocket", "final_position", "first_contact", "cushions_before_contact", "cushions",
            "events", "miscue", "failure", "speed_reflected", "elevation_reflected")
# Default chunks per worker thread: enough for the faster workers to take
# over the slower ones' share, few enough that scheduling costs nothing.
CHUNKS_PER_THREAD = 4
# Most rows of one chunk: a local simulate_many call's limit.
MAX_CHUNK = 1_000_000


def chunk_bounds(shots: int, chunk_size: int) -> list[tuple[int, int]]:
    """[lo, hi) of each chunk of `shots` rows, `chunk_size` rows each (the last may be shorter)."""
    return [(lo, min(shots, lo + chunk_size)) for lo in range(0, shots, chunk_size)]


def _resolved_scenario(scenario: Any) -> Any:
    """The scenario as the workers get it: a path is read here, on the client."""
    if isinstance(scenario, os.PathLike) or (isinstance(scenario, str) and not scenario.lstrip().startswith("{")):
        try:
            with open(scenario, encoding="utf-8") as f:
                return f.read()
        except OSError:
            return scenario  # the first chunk raises the module's own error for it
    return scenario


def _play_chunk(scenario: Any, actions: NDArray[np.float64], layouts: NDArray[np.float64] | None, seed: int,
                noise: Any, first_shot: int, threads: int, present: NDArray[np.bool_] | None = None) -> ManyOutcomes:
    """Runs on a worker: one chunk, as a local call."""
    return _cueball.simulate_many(scenario, actions, layouts, threads=threads, seed=seed, noise=noise,
                                  first_shot=first_shot, present=present)


def _invalid(field: str, message: str) -> _cueball.InvalidArgument:
    error = _cueball.InvalidArgument(message)
    error.field = field
    return error


def simulate_many(client: Any, scenario: None | _cueball.Scenario | str | os.PathLike[str] | Mapping[str, Any],
                  actions: Any,
                  layouts: Any = None, *, seed: int = 0,
                  noise: bool | str | Mapping[str, float] | None = False, chunk_size: int | None = None,
                  threads: int = 1, present: Any = None) -> ManyOutcomes:
    """cueball.simulate_many on a Dask cluster: the same arguments (without `threads`' meaning), the same dict back.

    client:     a distributed.Client (LocalCluster or tcp://scheduler:8786)
    chunk_size: rows per task, [1, 1e6]; default: the rows spread over 4 tasks per worker thread
    threads:    threads of each task's simulate_many (1 suits workers started with one thread
                per core: a worker runs one task per thread, the GIL released)

    The arrays are bit-identical to a local call's whatever the cluster and chunk size; the
    first failing chunk's error (by row) is raised, as the local call would raise it.
    seconds and shots_per_second are the client's wall clock, scheduling and transfer included.
    """
    start = time.perf_counter()
    a: NDArray[np.float64] | None
    try:
        a = np.ascontiguousarray(actions, dtype=np.float64)
    except (TypeError, ValueError):
        a = None
    if a is None or a.ndim != 2 or a.shape[0] == 0 or a.shape[1] != 5:
        # Malformed or empty: the module's own check says what is wrong, with its wording.
        return _cueball.simulate_many(scenario, actions, layouts, seed=seed, noise=noise, present=present)
    shots = int(a.shape[0])
    lay: NDArray[np.float64] | None = None
    if layouts is not None:
        lay = np.ascontiguousarray(layouts, dtype=np.float64)
        if lay.ndim != 3 or lay.shape[0] != shots:
            shape = "x".join(str(n) for n in lay.shape)
            raise _invalid("layouts", f"layouts: an ({shots}, n_balls, 2) array, one layout per row of actions; "
                                      f"got shape ({shape})")
    on: NDArray[np.bool_] | None = None
    if present is not None:
        on = np.asarray(present)
        if on.dtype != np.bool_ or on.ndim != 2 or on.shape[0] != shots:
            shape = "x".join(str(n) for n in on.shape)
            raise _invalid("present", f"present: an ({shots}, n_balls) bool array, one row per row of actions; "
                                      f"got a {on.dtype} array of shape ({shape})")
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or not 0 <= int(seed) < 2**64:
        raise _invalid("seed", f"seed = {seed!r}, allowed: an integer in [0, 2^64)")
    if isinstance(threads, bool) or not isinstance(threads, (int, np.integer)) or not 1 <= int(threads) <= 256:
        raise _invalid("threads", f"threads = {threads!r}, allowed: an integer in [1, 256]")
    if chunk_size is None:
        worker_threads = max(1, sum(client.nthreads().values()))
        chunk_size = max(1, min(MAX_CHUNK, math.ceil(shots / (CHUNKS_PER_THREAD * worker_threads))))
    elif isinstance(chunk_size, bool) or not isinstance(chunk_size, (int, np.integer)) \
            or not 1 <= int(chunk_size) <= MAX_CHUNK:
        raise _invalid("chunk_size", f"chunk_size = {chunk_size!r}, allowed: an integer in [1, {MAX_CHUNK}]")

    # hash=False: a key of this call's own (a content key shared with an earlier call could be
    # released by that call's clean-up while this one's tasks wait on it).
    [shared] = client.scatter([_resolved_scenario(scenario)], broadcast=True, hash=False)
    futures = [client.submit(_play_chunk, shared, a[lo:hi], None if lay is None else lay[lo:hi], int(seed),
                             noise, lo, int(threads), None if on is None else on[lo:hi], pure=False)
               for lo, hi in chunk_bounds(shots, int(chunk_size))]
    try:
        parts = [cast("ManyOutcomes", f.result()) for f in futures]  # in row order: the first failing chunk raises
    except BaseException:
        client.cancel(futures)
        raise
    out: dict[str, Any] = {"ids": parts[0]["ids"]}
    for name in PER_SHOT:
        joined = np.concatenate([cast(NDArray[Any], p[name]) for p in parts])  # type: ignore[literal-required]
        joined.setflags(write=False)
        out[name] = joined
    out["seconds"] = time.perf_counter() - start
    out["shots_per_second"] = shots / out["seconds"] if out["seconds"] > 0 else 0.0
    return cast("ManyOutcomes", out)

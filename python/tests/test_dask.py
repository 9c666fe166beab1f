"""cueball.dask: simulate_many across a Dask LocalCluster of 2 worker processes,
bit-identical to one local call whatever the chunk size.

Not run under the sanitizers (CUEBALL_SKIP_DASK, set by python/CMakeLists.txt):
the workers are fresh interpreters, and the C++ side of chunking (first_shot)
is tested there by test_batch's ManyOutcomes.ChunksWithTheirFirstShotAreTheWholeStudy.
"""

import logging
import os
import pathlib
import unittest
import warnings

import numpy as np

import cueball
import cueball.dask

CUT = pathlib.Path(__file__).resolve().parents[2] / "docs" / "example-cut-shot.json"


def identical(test: unittest.TestCase, a: dict, b: dict) -> None:
    """Every per-shot array the same, bit for bit (NaN rows included)."""
    test.assertEqual(sorted(a), sorted(b))
    for key, value in a.items():
        if isinstance(value, np.ndarray):
            other = b[key]
            test.assertEqual((value.dtype, value.shape), (other.dtype, other.shape), key)
            test.assertEqual(value.tobytes(), other.tobytes(), key)


@unittest.skipIf(os.environ.get("CUEBALL_SKIP_DASK"), "Dask workers are not run under the sanitizers")
class DaskTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls) -> None:
        from distributed import Client, LocalCluster

        with warnings.catch_warnings():  # tornado's DeprecationWarnings, from inside distributed
            warnings.simplefilter("ignore", DeprecationWarning)
            cls.cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                                       silence_logs=logging.ERROR)
            cls.client = Client(cls.cluster)
        rng = np.random.default_rng(11)
        n = 90
        cls.actions = np.column_stack([
            rng.uniform(0.5, 6.0, n), rng.uniform(-180, 180, n), rng.uniform(0, 20, n),
            rng.uniform(-0.3, 0.3, n), rng.uniform(-0.3, 0.3, n)])

    @classmethod
    def tearDownClass(cls) -> None:
        cls.client.close()
        cls.cluster.close()

    def test_two_worker_processes(self) -> None:
        workers = self.client.scheduler_info()["workers"]
        self.assertEqual(len(workers), 2)
        pids = set(self.client.run(os.getpid).values())
        self.assertEqual(len(pids), 2)
        self.assertNotIn(os.getpid(), pids)

    def test_bit_identical_to_a_local_run_whatever_the_chunks(self) -> None:
        local = cueball.simulate_many(None, self.actions, seed=7, noise=True)
        self.assertGreater(int((~local["miscue"]).sum()), 0)
        for chunk_size in (None, 1, 13, 45, 90):
            with self.subTest(chunk_size=chunk_size):
                remote = cueball.dask.simulate_many(self.client, None, self.actions, seed=7, noise=True,
                                                    chunk_size=chunk_size)
                identical(self, local, remote)
                self.assertFalse(remote["pocketed"].flags.writeable)
        # Another seed gives other shots (the noise does reach the workers).
        other = cueball.dask.simulate_many(self.client, None, self.actions, seed=8, noise=True, chunk_size=30)
        self.assertNotEqual(local["final_position"].tobytes(), other["final_position"].tobytes())

    def test_layouts_and_a_scenario_file(self) -> None:
        # The cut shot (cue ball 0, balls 1 and 9) from 20 layouts: the cue ball moved along x.
        self.assertEqual(list(cueball.simulate_many(str(CUT), self.actions[:1])["ids"]), [0, 1, 9])
        layouts = np.zeros((20, 3, 2))
        layouts[:, 0] = np.column_stack([np.linspace(0.4, 0.9, 20), np.full(20, 0.5)])
        layouts[:, 1] = (1.8, 0.9)
        layouts[:, 2] = (0.8, 1.0)
        actions = self.actions[:20]
        local = cueball.simulate_many(CUT, actions, layouts)
        remote = cueball.dask.simulate_many(self.client, CUT, actions, layouts, chunk_size=6)
        identical(self, local, remote)
        np.testing.assert_array_equal(remote["ids"], local["ids"])

    def test_absent_balls_and_named_noise(self) -> None:
        present = np.random.default_rng(4).random((40, 10)) > 0.3
        present[:, 0] = True  # the cue ball
        local = cueball.simulate_many(None, self.actions[:40], present=present, seed=5, noise="tournament")
        remote = cueball.dask.simulate_many(self.client, None, self.actions[:40], present=present, seed=5,
                                            noise="tournament", chunk_size=9)
        identical(self, local, remote)
        np.testing.assert_array_equal(remote["present"], present)
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.dask.simulate_many(self.client, None, self.actions[:40], present=present[:39])
        self.assertEqual(caught.exception.field, "present")

    def test_a_scenario_object(self) -> None:
        # Pickled to the workers through its JSON: the same rows as a local run of it, or of its dict.
        s = cueball.Scenario.from_document(cueball.simulate(CUT).to_json())
        local = cueball.simulate_many(s.to_dict(), self.actions[:30], seed=3, noise=True)
        remote = cueball.dask.simulate_many(self.client, s, self.actions[:30], seed=3, noise=True, chunk_size=7)
        identical(self, local, remote)

    def test_errors_name_the_whole_studys_row(self) -> None:
        bad = self.actions.copy()
        bad[57, 0] = 0.0  # speed
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.dask.simulate_many(self.client, None, bad, chunk_size=10)
        self.assertEqual(caught.exception.field, "actions[57].speed")
        with self.assertRaises(cueball.InvalidArgument) as local:
            cueball.simulate_many(None, bad)
        self.assertEqual(str(caught.exception), str(local.exception))
        for kwargs, field in (({"chunk_size": 0}, "chunk_size"), ({"seed": -1}, "seed"), ({"threads": 0}, "threads")):
            with self.subTest(field=field), self.assertRaises(cueball.InvalidArgument) as e:
                cueball.dask.simulate_many(self.client, None, self.actions, **kwargs)
            self.assertEqual(e.exception.field, field)
        with self.assertRaises(cueball.InvalidArgument) as shape:
            cueball.dask.simulate_many(self.client, None, self.actions[:, :4])
        self.assertEqual(shape.exception.field, "actions")
        with self.assertRaises(cueball.InvalidArgument) as layouts:
            cueball.dask.simulate_many(self.client, None, self.actions, np.zeros((3, 10, 2)))
        self.assertEqual(layouts.exception.field, "layouts")

    def test_chunk_bounds_cover_every_row_once(self) -> None:
        for shots, size in ((1, 1), (10, 3), (90, 90), (91, 45)):
            bounds = cueball.dask.chunk_bounds(shots, size)
            rows = [k for lo, hi in bounds for k in range(lo, hi)]
            self.assertEqual(rows, list(range(shots)))
            self.assertTrue(all(0 < hi - lo <= size for lo, hi in bounds))


if __name__ == "__main__":
    unittest.main()

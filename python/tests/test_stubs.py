"""python/cueball/_cueball.pyi against the built extension module: the same public names, the same
class members, the same parameter names; and the typed program that
`mypy --strict` checks against the stubs (ctest python_stubs) runs."""

import ast
import importlib
import inspect
import pathlib
import re
import sys
import unittest

import cueball
from cueball import _cueball

STUB = pathlib.Path(__file__).resolve().parents[1] / "cueball" / "_cueball.pyi"
# The extension's submodule games has its own stub (cueball/games.pyi).
GAMES_STUB = STUB.with_name("games.pyi")
SUBMODULES = {"games", "_rl"}  # _rl: cueball.rl's native part, typed by rl.py itself
# Names only for type checkers: the dicts' TypedDicts and the private aliases.
STUB_ONLY = {"EventArrays", "BallArrays", "SegmentArrays", "StateArrays", "ManyOutcomes", "_Float", "_Int", "_Vec", "_Scenario", "_Noise"}


def stub_tree(path=STUB):
    return ast.parse(path.read_text())


def defined_names(body):
    names = {}
    for node in body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names.setdefault(node.name, node)
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            names[node.target.id] = node
        elif isinstance(node, ast.Assign):
            for target in node.targets:
                if isinstance(target, ast.Name):
                    names[target.id] = node
    return names


def stub_parameters(fn):
    a = fn.args
    return [x.arg for x in a.posonlyargs + a.args + a.kwonlyargs]


def module_parameters(obj):
    """Parameter names from pybind11's signature line, e.g. 'f(x: float, *, y: int = 1) -> float'."""
    first = (obj.__doc__ or "").splitlines()[0]
    inside = first[first.index("(") + 1 : first.rindex(") ->")]
    return re.findall(r"(?:^|[(,]\s*)(\w+):", inside)


def public(names, module=None):
    return {n for n in names if not (n.startswith("__") and n.endswith("__")) and not (module is _cueball and n in SUBMODULES)}


class StubTest(unittest.TestCase):
    def test_every_name_of_the_module_is_in_the_stub_and_back(self):
        stub = defined_names(stub_tree().body)
        module = public(dir(_cueball), _cueball)
        self.assertEqual(sorted(module - set(stub)), [], "in the module, missing from _cueball.pyi")
        self.assertEqual(sorted(set(stub) - module - STUB_ONLY - {"__version__"}), [], "in _cueball.pyi, not in the module")
        self.assertIn("__version__", stub)
        self.assertIsInstance(cueball.__version__, str)

    def test_the_package_is_the_extension_and_its_python_layer(self):
        for name in sorted(public(dir(_cueball)) - {"_rl"}):  # _rl: cueball.rl's native part, not re-exported
            self.assertIs(getattr(cueball, name), getattr(_cueball, name), name)
        self.assertIs(importlib.import_module("cueball.games"), _cueball.games)
        self.assertIs(cueball._time_run_scenario, _cueball._time_run_scenario)
        self.assertEqual(cueball.__version__, _cueball.__version__)
        package = pathlib.Path(cueball.__file__).parent
        for name in ("py.typed", "_cueball.pyi", "games.pyi", "dask.py", "rl.py"):
            self.assertTrue((package / name).is_file(), name)

    def test_the_games_stub_has_the_submodules_names(self):
        stub = defined_names(stub_tree(GAMES_STUB).body)
        module = public(dir(_cueball.games))
        self.assertEqual(sorted(module - set(stub)), [], "in cueball.games, missing from games.pyi")
        self.assertEqual(sorted(set(stub) - module - {"_Region"}), [], "in games.pyi, not in cueball.games")

    def test_class_members_and_parameters_agree(self):
        self.check_members(_cueball, defined_names(stub_tree().body))
        self.check_members(_cueball.games, defined_names(stub_tree(GAMES_STUB).body))

    def check_members(self, module, stub):
        for name in sorted(public(dir(module), module)):
            obj = getattr(module, name)
            node = stub[name]
            with self.subTest(name=name):
                if inspect.isclass(obj):
                    self.assertIsInstance(node, ast.ClassDef)
                    if issubclass(obj, BaseException):
                        continue
                    members = defined_names(node.body)
                    mine = {m for m in vars(obj) if not m.startswith("_")}
                    self.assertEqual(sorted(mine ^ (set(members) - {"__init__"})), [])
                    if "__init__" in members:
                        self.assertEqual(stub_parameters(members["__init__"]), module_parameters(obj.__init__))
                    for m in mine:
                        if isinstance(members[m], ast.FunctionDef) and callable(getattr(obj, m)):
                            self.assertEqual(stub_parameters(members[m]), module_parameters(getattr(obj, m)), m)
                elif callable(obj):
                    self.assertIsInstance(node, ast.FunctionDef)
                    self.assertEqual(stub_parameters(node), module_parameters(obj))
                    self.assertTrue(ast.get_docstring(node), f"{name} has no docstring in the stub")

    def test_the_typed_program_runs(self):
        sys.path.insert(0, str(pathlib.Path(__file__).parent))
        try:
            import typed_usage
        finally:
            sys.path.pop(0)
        typed_usage.main()


if __name__ == "__main__":
    unittest.main()

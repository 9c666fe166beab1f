"""The Python sessions of the READMEs are doctests: every ```pycon block of
python/README.md and of the main README.md runs, from the repository's root,
and must print what the README shows.

The blocks of one file share their names (a tour goes on from block to block).
A block that uses cueball.dask is not run where CUEBALL_SKIP_DASK is set (the
sanitizer build; see test_dask.py).
"""

import doctest
import os
import pathlib
import re
import unittest
import warnings

ROOT = pathlib.Path(__file__).resolve().parents[2]
READMES = [ROOT / "python" / "README.md", ROOT / "README.md"]
BLOCK = re.compile(r"^```pycon[ \t]*\n(.*?)^```[ \t]*$", re.M | re.S)
OPTIONS = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE


def pycon_blocks(path: pathlib.Path) -> list[tuple[int, str]]:
    """(line number, text) of every ```pycon block."""
    text = path.read_text(encoding="utf-8")
    return [(text.count("\n", 0, m.start()) + 2, m.group(1)) for m in BLOCK.finditer(text)]


class ReadmeSessionTest(unittest.TestCase):
    def setUp(self) -> None:
        self.cwd = os.getcwd()
        os.chdir(ROOT)  # the sessions name files relative to the repository's root

    def tearDown(self) -> None:
        os.chdir(self.cwd)

    def test_every_session_prints_what_the_readme_shows(self) -> None:
        parser = doctest.DocTestParser()
        for readme in READMES:
            blocks = pycon_blocks(readme)
            self.assertGreater(len(blocks), 0, f"{readme}: no ```pycon block")
            names: dict[str, object] = {"__name__": "readme"}
            for line, text in blocks:
                if os.environ.get("CUEBALL_SKIP_DASK") and "cueball.dask" in text:
                    continue
                name = f"{readme.relative_to(ROOT)}:{line}"
                test = parser.get_doctest(text, names, name, str(readme), line - 1)
                self.assertGreater(len(test.examples), 0, f"{name}: a pycon block without >>> examples")
                runner = doctest.DocTestRunner(optionflags=OPTIONS)
                report: list[str] = []
                with warnings.catch_warnings():  # tornado's DeprecationWarnings, from inside distributed
                    warnings.simplefilter("ignore", DeprecationWarning)
                    runner.run(test, out=report.append, clear_globs=False)
                with self.subTest(block=name):
                    self.assertEqual(runner.failures, 0, "".join(report))
                names = test.globs


if __name__ == "__main__":
    unittest.main()

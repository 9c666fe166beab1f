"""ctest python_install: the two ways to install the module, from a clean scratch dir.

(a) `cmake --install BUILD --prefix SCRATCH/prefix` (the layout of
    /usr/local), then /usr/bin/python3 imports cueball from that prefix's
    Python directory, and the same directory under /usr/local is on that
    interpreter's own sys.path (so the real `--prefix /usr/local` install needs
    no PYTHONPATH).
(b) A venv made by Debian's `python3 -m venv --system-site-packages`, then
    `pip install --no-build-isolation --no-index` of a copy of the source tree,
    packaging the module of this build tree (setup.py's CUEBALL_CMAKE_BUILD_DIR:
    pip's own compile of the library and module was most of the Release test
    run's time, and compiles the same sources the build tree did); cueball is
    imported there, with its metadata, and simulates a shot.

Every command is an argument list; nothing is downloaded (--no-index).
"""

import argparse
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path


def run(command, **kwargs):
    print("+ " + " ".join(str(c) for c in command), flush=True)
    return subprocess.run([str(c) for c in command], check=True, **kwargs)


def clean_env():
    env = dict(os.environ)
    for name in ("PYTHONPATH", "PYTHONHOME", "PYTHONSTARTUP", "PYTHONUSERBASE",
                 "PIP_INDEX_URL", "PIP_EXTRA_INDEX_URL", "VIRTUAL_ENV"):
        env.pop(name, None)
    env["PYTHONDONTWRITEBYTECODE"] = "1"
    env["PIP_DISABLE_PIP_VERSION_CHECK"] = "1"
    env["PIP_NO_INPUT"] = "1"
    env["PIP_CONFIG_FILE"] = os.devnull  # no index or options from the user's pip.conf
    return env


# Run by the installed module's interpreter, in the scratch directory (so that
# nothing is imported from the source or build tree): prints what it found.
PROBE = r"""
import json, pathlib, sys
import cueball, cueball.dask
result = cueball.simulate(sys.argv[1])
doc = result.to_dict()
pockets = {b["name"]: b["pocket"] for b in doc["balls"]}
package = pathlib.Path(cueball.__file__).parent
print(json.dumps({"file": cueball.__file__, "version": cueball.__version__,
                  "events": len(doc["events"]), "pockets": pockets,
                  "typed": sorted(p.name for p in package.iterdir() if p.suffix in (".pyi", ".typed"))}))
"""


def probe(python, shot, cwd, env):
    out = run([python, "-c", PROBE, shot], cwd=cwd, env=env,
              stdout=subprocess.PIPE, text=True).stdout
    found = json.loads(out.strip().splitlines()[-1])
    print("  found", found, flush=True)
    return found


def check_probe(found, root, version, what):
    if not Path(found["file"]).resolve().is_relative_to(root.resolve()):
        sys.exit(f"FAIL {what}: cueball imported from {found['file']}, not from {root}")
    if found["version"] != version:
        sys.exit(f"FAIL {what}: cueball.__version__ {found['version']!r}, expected {version!r}")
    if found["events"] < 1 or found["pockets"].get("1") != "top-right":
        sys.exit(f"FAIL {what}: the cut shot gave {found}")
    if found["typed"] != ["_cueball.pyi", "games.pyi", "py.typed"]:
        sys.exit(f"FAIL {what}: the package's type information is {found['typed']}, not _cueball.pyi, games.pyi and py.typed")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--source-dir", type=Path, required=True)
    parser.add_argument("--build-dir", type=Path, required=True)
    parser.add_argument("--install-dir", required=True, help="CUEBALL_PYTHON_INSTALL_DIR")
    parser.add_argument("--scratch", type=Path, required=True)
    parser.add_argument("--version", required=True, help="the CMake project's VERSION")
    parser.add_argument("--python", default="/usr/bin/python3")
    parser.add_argument("--skip-venv", action="store_true")
    args = parser.parse_args()

    env = clean_env()
    scratch = args.scratch.resolve()
    if scratch.exists():
        shutil.rmtree(scratch)
    scratch.mkdir(parents=True)
    shot = (args.source_dir / "docs" / "example-cut-shot.json").resolve()

    # (a) cmake --install into a prefix laid out as /usr/local.
    prefix = scratch / "prefix"
    run(["cmake", "--install", args.build_dir, "--prefix", prefix], env=env)
    site_dir = prefix / args.install_dir
    sys_path = json.loads(run([args.python, "-c", "import json, sys; print(json.dumps(sys.path))"],
                              cwd=scratch, env=env, stdout=subprocess.PIPE, text=True).stdout)
    local_dir = os.path.normpath(os.path.join("/usr/local", args.install_dir))
    if local_dir not in sys_path:
        sys.exit(f"FAIL cmake --install: {local_dir} (CUEBALL_PYTHON_INSTALL_DIR "
                 f"{args.install_dir} under /usr/local) is not on {args.python}'s sys.path {sys_path}")
    env_a = dict(env, PYTHONPATH=str(site_dir))
    check_probe(probe(args.python, shot, scratch, env_a), site_dir, args.version, "cmake --install")
    print(f"ok cmake --install: {args.python} imports cueball from {site_dir}", flush=True)

    if args.skip_venv:
        return
    # (b) pip install into a venv, from a copy of the source tree.
    source = scratch / "src"
    top_ignored = {"build", "out", ".git"}
    ignored = {"node_modules", "__pycache__"}

    def ignore(directory, names):
        skip = {n for n in names if n in ignored or n.endswith(".egg-info")}
        if Path(directory).resolve() == args.source_dir.resolve():
            skip |= {n for n in names if n in top_ignored}
        return skip

    shutil.copytree(args.source_dir, source, ignore=ignore, symlinks=True)
    venv = scratch / "venv"
    run([args.python, "-m", "venv", "--system-site-packages", venv], env=env)
    vpython = venv / "bin" / "python"
    # setup.py packages this build tree's module (it brings it up to date
    # with cmake --build, a no-op here) instead of compiling its own.
    env_b = dict(env, CUEBALL_CMAKE_BUILD_DIR=str(args.build_dir.resolve()))
    run([vpython, "-m", "pip", "install", "--no-build-isolation", "--no-index", "--no-cache-dir", source],
        cwd=scratch, env=env_b)
    check_probe(probe(vpython, shot, scratch, env), venv, args.version, "pip install")
    meta = run([vpython, "-c",
                "import json, importlib.metadata as m; d = m.metadata('cueball'); "
                "print(json.dumps({'version': d['Version'], 'license': d['License'], "
                "'requires': m.requires('cueball'), 'python': d['Requires-Python']}))"],
               cwd=scratch, env=env, stdout=subprocess.PIPE, text=True).stdout
    meta = json.loads(meta)
    print("  metadata", meta, flush=True)
    expected = {"version": args.version, "license": "MIT", "requires": ["numpy"], "python": ">=3.11"}
    if meta != expected:
        sys.exit(f"FAIL pip install: metadata {meta}, expected {expected}")
    run([vpython, "-c", "import numpy"], cwd=scratch, env=env)
    print(f"ok pip install: {vpython} imports cueball from the venv", flush=True)


if __name__ == "__main__":
    main()

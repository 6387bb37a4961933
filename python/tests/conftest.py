"""Shared fixtures: where SOFA's data and the sinew command are.

CTest sets PYTHONPATH to this build's python folder, SINEW_BIN and
SINEW_DATA_DIR; run by hand, the defaults are ../shared/sofa-data and the
command found next to the imported module (build/python/../bin/sinew).
"""
import os
import pathlib
import subprocess

import pytest

import _sinew

REPO = pathlib.Path(__file__).resolve().parents[2]


def _data_dir():
    return pathlib.Path(os.environ.get("SINEW_DATA_DIR", REPO.parent / "shared" / "sofa-data")).resolve()


@pytest.fixture(scope="session")
def sofa_data():
    d = _data_dir()
    if not (d / "examples").is_dir():
        pytest.skip("SOFA data not found at %s (set SINEW_DATA_DIR)" % d)
    return d


@pytest.fixture(scope="session")
def sinew_bin():
    b = os.environ.get("SINEW_BIN")
    if not b:
        b = str(pathlib.Path(_sinew.__file__).resolve().parent.parent / "bin" / "sinew")
    if not os.path.exists(b):
        pytest.skip("the sinew command was not found (set SINEW_BIN)")
    return b


@pytest.fixture
def run_sinew(sinew_bin, sofa_data):
    """Runs `sinew run SCENE -n N` with SOFA's data folders; returns the CompletedProcess."""

    def run(scene, steps=10, *extra, timeout=600):
        cmd = [sinew_bin, "run", str(scene), "-n", str(steps), "--hideProgressBar",
               "--data-path", str(sofa_data / "share"), str(sofa_data / "examples")] + list(extra)
        return subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)

    return run


@pytest.fixture(scope="session")
def display():
    """A private X display (Xvfb) for the viewer's window; skips when Xvfb is absent."""
    import shutil

    xvfb = shutil.which("Xvfb")
    if not xvfb:
        pytest.skip("Xvfb is not installed (Debian: xvfb)")
    # -displayfd: Xvfb picks a free display number and writes it to the pipe when ready.
    r, w = os.pipe()
    proc = subprocess.Popen([xvfb, "-displayfd", str(w), "-screen", "0", "1280x1024x24", "-nolisten", "tcp"],
                            pass_fds=(w,), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(w)
    with os.fdopen(r) as f:
        number = f.readline().strip()
    if not number:
        proc.kill()
        pytest.skip("Xvfb did not start")
    yield ":" + number
    proc.terminate()
    proc.wait(timeout=10)

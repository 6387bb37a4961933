"""`sinew view` in a real window under Xvfb (issue 15, done-when 2): every visible SOFA
regression scene opens and closes cleanly with a screenshot, and a scripted shift-drag grabs
a body that then moves towards the cursor. Skips with the reason when Xvfb is absent."""
import os
import re
import shutil
import subprocess
import tempfile

import pytest

from conftest import REPO, _data_dir

DATA = str(_data_dir())
HERE = str(REPO / "tests" / "viewer")  # grab_cube.scn


@pytest.fixture(scope="module")
def view(display, sinew_bin):
    """Runs `sinew view ARGS` on the test display; returns the CompletedProcess."""

    def run(args, timeout=300):
        env = dict(os.environ, DISPLAY=display)
        return subprocess.run([sinew_bin, "view"] + args, env=env, capture_output=True, text=True, timeout=timeout)

    return run


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    assert head[:8] == b"\x89PNG\r\n\x1a\n", path
    return int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")


def regression_scenes():
    tsv = os.path.join(DATA, "SCENES.tsv")
    if not os.path.exists(tsv):
        return []
    scenes = []
    with open(tsv) as f:
        for line in f:
            cols = line.rstrip("\n").split("\t")
            if cols and cols[0].endswith((".scn", ".xml", ".py")) and not line.startswith("#"):
                scenes.append(cols[0])
    return scenes


SCENES = regression_scenes()


def test_the_scene_list_is_there():
    if not SCENES:
        pytest.skip("SOFA data not found at %s (set SINEW_DATA_DIR to the sofa-data folder)" % DATA)
    assert len(SCENES) == 88


@pytest.mark.parametrize("scene", SCENES)
def test_every_regression_scene_opens_and_quits_with_a_screenshot(view, sinew_bin, scene, tmp_path):
    path = os.path.join(DATA, "examples", scene)
    check = subprocess.run([sinew_bin, "check", path, "--data-path", os.path.join(DATA, "share"),
                            os.path.join(DATA, "examples")], capture_output=True, text=True, timeout=300)
    shot = tmp_path / "shot.png"
    r = view([path, "--play", "--quit-after", "3", "--size", "320x240", "--screenshot", str(shot),
                       "--data-path", os.path.join(DATA, "share"), os.path.join(DATA, "examples")])
    if check.returncode != 0:
        # A scene Sinew cannot load (missing components) is refused with a message, not a crash.
        assert r.returncode == 1, r.stderr
        assert "cannot run" in r.stderr
        return
    assert r.returncode == 0, r.stdout + r.stderr
    assert png_size(shot) == (320, 240)


GRAB_SCRIPT = """
0 play
2 shift down
2 move 400 300
3 press left
3 report
{moves}
40 report
41 release left
42 shift up
43 quit
"""


def test_shift_drag_pulls_the_body_towards_the_cursor(view, tmp_path):
    moves = "\n".join("%d move 400 %d" % (4 + 2 * k, 280 - 20 * k) for k in range(6))  # up to y = 180
    script = tmp_path / "grab.txt"
    script.write_text(GRAB_SCRIPT.format(moves=moves))
    r = view([os.path.join(HERE, "grab_cube.scn"), "--size", "800x600", "--script", str(script)])
    assert r.returncode == 0, r.stdout + r.stderr
    num = r"([-\d.e+]+)"
    point = r"\(" + num + " " + num + " " + num + r"\)"
    reports = re.findall(r"frame (\d+): grabbed point at " + point + ", mouse at " + point, r.stdout)
    assert len(reports) == 2, r.stdout
    start = [float(v) for v in reports[0][1:4]]
    end = [float(v) for v in reports[1][1:4]]
    mouse = [float(v) for v in reports[1][4:7]]
    # Grabbed on the front face (z = 1) at the centre of the window, which looks at the cube's centre.
    assert abs(start[2] - 1) < 1e-6 and abs(start[0]) < 0.05 and abs(start[1]) < 0.05
    # The cursor went up by 120 pixels: the mouse point is above, and the body followed it.
    assert mouse[1] > 0.5
    assert end[1] > 0.5 * mouse[1]
    dist = lambda a, b: sum((x - y) ** 2 for x, y in zip(a, b)) ** 0.5
    assert dist(end, mouse) < 0.3 * dist(start, mouse)
    assert "released at" in r.stdout


def test_grabbing_while_paused_moves_nothing(view, tmp_path):
    script = tmp_path / "paused.txt"
    script.write_text("1 shift down\n1 move 400 300\n2 press left\n3 report\n4 quit\n")
    r = view([os.path.join(HERE, "grab_cube.scn"), "--size", "800x600", "--script", str(script)])
    assert r.returncode == 0, r.stderr
    assert "nothing grabbed (Animation is not running" in r.stdout


def test_without_a_display_the_error_says_what_to_do(sinew_bin, tmp_path):
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    r = subprocess.run([sinew_bin, "view", os.path.join(HERE, "grab_cube.scn"), "--quit-after", "1"], env=env,
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 1
    assert "cannot open a window" in r.stderr and "xvfb-run" in r.stderr


def test_bad_script_and_size_are_refused(view, tmp_path):
    script = tmp_path / "bad.txt"
    script.write_text("0 play\n1 fly away\n")
    r = view([os.path.join(HERE, "grab_cube.scn"), "--script", str(script)])
    assert r.returncode == 1 and "bad.txt:2: unknown command 'fly'" in r.stderr
    r = view([os.path.join(HERE, "grab_cube.scn"), "--size", "0x10"])
    assert r.returncode == 1 and "--size" in r.stderr


def lit_extent(path):
    """Width and height of the lit part of a picture (black background)."""
    image = pytest.importorskip("matplotlib.image").imread(str(path))
    lit = image[:, :, :3].max(axis=2) > 0.05
    rows, cols = lit.any(axis=1).nonzero()[0], lit.any(axis=0).nonzero()[0]
    return cols[-1] - cols[0] + 1, rows[-1] - rows[0] + 1


def test_the_scene_camera_file_is_applied(view, tmp_path):
    # W saves <scene>.view next to the scene: work on a copy in a temporary folder.
    scene = tmp_path / "cube.scn"
    shutil.copy(os.path.join(HERE, "grab_cube.scn"), scene)
    (tmp_path / "cube.scn.view").write_text(
        '<?xml version="1.0" ?>\n<Camera version="1.0">\n  <position value="0 0 30" />\n'
        '  <orientation value="0 0 0 1" />\n  <distance value="30" />\n</Camera>\n')
    far = tmp_path / "far.png"
    r = view([str(scene), "--size", "200x200", "--quit-after", "2", "--screenshot", str(far)])
    assert r.returncode == 0, r.stderr
    (tmp_path / "cube.scn.view").unlink()
    near = tmp_path / "near.png"
    r = view([str(scene), "--size", "200x200", "--quit-after", "2", "--screenshot", str(near)])
    assert r.returncode == 0, r.stderr
    # The front face (2 x 2, at z = 1) seen with a 45 deg field of view from distance d covers
    # a square of 200 / (tan 22.5 deg (d - 1)) pixels: SOFA's default view stands 3
    # half-diagonals (3 sqrt 3) from the centre, the camera file 30.
    side = lambda d: 200 / (0.41421356 * (d - 1))
    # Multisampling lights a partial pixel on each side.
    for picture, d in ((near, 3 * 3 ** 0.5), (far, 30)):
        w, h = lit_extent(picture)
        assert abs(w - side(d)) <= 2 and abs(h - side(d)) <= 2, (picture, w, h, side(d))

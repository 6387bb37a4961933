"""`sinew render`: the command writes PNG pictures of a scene written here, and of a Python
scene; skipped (with the reason) where no off-screen OpenGL context can be created."""
import struct
import subprocess
import zlib

import pytest

SCENE = """<Node name="root" dt="0.01" gravity="0 -9.81 0">
  <DefaultAnimationLoop/>
  <BackgroundSetting color="0 0 1"/>
  <Node name="falling">
    <EulerImplicitSolver/> <CGLinearSolver iterations="25" tolerance="1e-9" threshold="1e-9"/>
    <MechanicalObject name="dofs" position="0 0 0  1 0 0  1 1 0  0 1 0"/>
    <UniformMass totalMass="1"/>
    <Node name="visual">
      <OglModel name="m" color="red" quads="0 1 2 3"/>
      <IdentityMapping input="@../dofs" output="@m"/>
    </Node>
  </Node>
</Node>
"""

PY_SCENE = '''
def createScene(root):
    root.addObject("DefaultAnimationLoop")
    root.addObject("OglModel", name="m", color="green", position=[[0, 0, 0], [1, 0, 0], [0, 1, 0]],
                   triangles=[[0, 1, 2]])
'''


def png_size(path):
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    width, height = struct.unpack(">II", data[16:24])
    return width, height


def render(sinew_bin, args):
    r = subprocess.run([sinew_bin, "render"] + args, capture_output=True, text=True, timeout=120)
    if r.returncode != 0 and "no off-screen OpenGL context" in r.stderr:
        pytest.skip(r.stderr.strip())
    return r


def test_render_writes_the_final_picture_and_frames(sinew_bin, tmp_path):
    scene = tmp_path / "fall.scn"
    scene.write_text(SCENE)
    frames = tmp_path / "frames"
    frames.mkdir()
    out = tmp_path / "out.png"
    r = render(sinew_bin, [str(scene), "-n", "3", "-o", str(out), "--frames", str(frames), "--size", "64x48"])
    assert r.returncode == 0, r.stderr
    assert png_size(out) == (64, 48)
    assert sorted(p.name for p in frames.iterdir()) == ["frame_%05d.png" % k for k in range(4)]
    # The body falls: the pictures of step 0 and step 3 differ.
    assert (frames / "frame_00000.png").read_bytes() != (frames / "frame_00003.png").read_bytes()


def test_render_of_a_python_scene(sinew_bin, tmp_path):
    scene = tmp_path / "tri.py"
    scene.write_text(PY_SCENE)
    out = tmp_path / "tri.png"
    r = render(sinew_bin, [str(scene), "-o", str(out), "--size", "32x32"])
    assert r.returncode == 0, r.stderr
    assert png_size(out) == (32, 32)


def test_render_errors_are_one_line(sinew_bin, tmp_path):
    scene = tmp_path / "nothing.scn"
    scene.write_text('<Node name="root"><DefaultAnimationLoop/><MechanicalObject position="0 0 0"/></Node>')
    r = render(sinew_bin, [str(scene), "-o", str(tmp_path / "x.png")])
    assert r.returncode == 1
    assert "nothing is visible" in r.stderr
    r = render(sinew_bin, [str(scene), "--size", "big"])
    assert r.returncode == 1
    assert "--size must be WIDTHxHEIGHT" in r.stderr

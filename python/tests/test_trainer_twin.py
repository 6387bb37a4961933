"""The skin-suture trainer's Python scene gives bit for bit the states of its XML twin
(scenes/trainer: the needle enters the skin and carving starts within the 300 steps)."""
import pathlib

from test_twins import dumped_states

TRAINER = pathlib.Path(__file__).resolve().parents[2] / "scenes" / "trainer"


def test_trainer_python_twin_equals_xml(run_sinew, tmp_path):
    a, b = tmp_path / "xml", tmp_path / "py"
    a.mkdir()
    b.mkdir()
    r = run_sinew(TRAINER / "skin_suture.scn", 300, "--dump-states", str(a))
    assert r.returncode == 0, r.stderr[-2000:]
    r = run_sinew(TRAINER / "skin_suture.py", 300, "--dump-states", str(b))
    assert r.returncode == 0, r.stderr[-2000:]
    xs, ps = dumped_states(a), dumped_states(b)
    assert len(xs) == 3  # skin, needle frame, scalpel frame
    for i, (x, p) in enumerate(zip(xs, ps)):
        assert x == p, "state %d differs between skin_suture.scn and skin_suture.py" % i

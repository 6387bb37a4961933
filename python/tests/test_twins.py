"""A Python scene gives bit for bit the states of its XML twin (same SOFA regression result)."""
import pathlib

import pytest

TWINS = {
    "FEMBAR_CGLinearSolver": ("Component/LinearSolver/Iterative/FEMBAR_CGLinearSolver.scn", 100),
    "liver": ("Demos/liver.scn", 100),
    "FrictionContact": ("Component/Collision/Response/FrictionContact.scn", 100),
}


def dumped_states(directory):
    """The dumped state files' contents, in the order of the states (k in reference_<k>_<name>)."""
    files = sorted(pathlib.Path(directory).glob("*_mstate.txt*"),
                   key=lambda p: int(p.name.split(".reference_")[1].split("_")[0]))
    assert files, "no state dumped in %s" % directory
    return [f.read_bytes() for f in files]


@pytest.mark.parametrize("twin", sorted(TWINS))
def test_python_twin_equals_xml(twin, sofa_data, run_sinew, tmp_path):
    xml, steps = TWINS[twin]
    py = pathlib.Path(__file__).parent / "twins" / (twin + ".py")
    a, b = tmp_path / "xml", tmp_path / "py"
    a.mkdir()
    b.mkdir()
    r = run_sinew(sofa_data / "examples" / xml, steps, "--dump-states", str(a))
    assert r.returncode == 0, r.stderr[-2000:]
    r = run_sinew(py, steps, "--dump-states", str(b))
    assert r.returncode == 0, r.stderr[-2000:]
    xs, ps = dumped_states(a), dumped_states(b)
    assert len(xs) == len(ps)
    for i, (x, p) in enumerate(zip(xs, ps)):
        assert x == p, "state %d differs between %s and its Python twin" % (i, xml)

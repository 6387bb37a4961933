"""VTKExporter and MeshExporter files open in VTK's own readers: `sinew run` on a scene
written here, in a temporary working directory (relative export paths are relative to it),
then every .vtu, the .pvd collection and a legacy .vtk are read back with python3-vtk9.
Skipped, with the reason, when the vtk module cannot be imported."""
import pathlib
import subprocess
import xml.etree.ElementTree as ET

import pytest

vtk = pytest.importorskip("vtk", reason="python3-vtk9 is not installed: VTK's readers cannot check the files")
from vtk.util.numpy_support import vtk_to_numpy  # noqa: E402

# A 3x3x3 grid (27 points, 8 hexahedra) falling under gravity; min corner at (0, 0, 0).
SCENE = """<Node name="root" dt="0.01" gravity="0 -10 0">
  <DefaultAnimationLoop/>
  <EulerImplicitSolver rayleighStiffness="0" rayleighMass="0"/>
  <CGLinearSolver iterations="25" tolerance="1e-12" threshold="1e-15"/>
  <MechanicalObject name="dofs"/>
  <RegularGridTopology name="grid" n="3 3 3" min="0 0 0" max="2 2 2"/>
  <UniformMass totalMass="1"/>
  <VTKExporter name="vtk" filename="out/series" edges="0" hexas="1" pointsDataFields="v=dofs.velocity"
               exportAtBegin="1" exportEveryNumberOfSteps="2"/>
  <VTKExporter name="legacy" filename="out/legacy.vtk" XMLformat="0" edges="0" hexas="1" exportAtEnd="1"/>
  <MeshExporter name="mesh" filename="out/mesh" format="vtkxml" edges="0" triangles="0" quads="0" exportAtBegin="1"/>
</Node>
"""


@pytest.fixture(scope="module")
def exported(tmp_path_factory, sinew_bin):
    work = tmp_path_factory.mktemp("vtk_export")
    (work / "scene.scn").write_text(SCENE)
    r = subprocess.run([sinew_bin, "run", "scene.scn", "-n", "6"], cwd=work, capture_output=True, text=True,
                       timeout=120)
    assert r.returncode == 0, r.stdout + r.stderr
    return work / "out"


def read_vtu(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(path))
    reader.Update()
    grid = reader.GetOutput()
    assert grid is not None
    return grid


def points(grid):
    return vtk_to_numpy(grid.GetPoints().GetData())


def test_every_vtu_opens_with_the_grid(exported):
    # exportAtBegin gives k = 0, then steps 2, 4, 6 give 1, 2, 3.
    files = sorted(exported.glob("series*.vtu"))
    assert [f.name for f in files] == ["series0.vtu", "series1.vtu", "series2.vtu", "series3.vtu"]
    for f in files:
        grid = read_vtu(f)
        assert grid.GetNumberOfPoints() == 27
        assert grid.GetNumberOfCells() == 8
        assert grid.GetCellType(0) == vtk.VTK_HEXAHEDRON
        v = grid.GetPointData().GetArray("v")
        assert v is not None and v.GetNumberOfComponents() == 3 and v.GetNumberOfTuples() == 27
    first, last = points(read_vtu(files[0])), points(read_vtu(files[-1]))
    assert tuple(first[0]) == (0.0, 0.0, 0.0)
    assert tuple(first[26]) == (2.0, 2.0, 2.0)
    # Falling: y went down, x and z did not move.
    assert last[0][1] < -1e-3
    assert last[0][0] == 0.0 and last[0][2] == 0.0


def test_pvd_collection_lists_the_series_with_times(exported):
    root = ET.parse(exported / "series.pvd").getroot()
    assert root.get("type") == "Collection"
    sets = root.find("Collection").findall("DataSet")
    assert [d.get("file") for d in sets] == ["series0.vtu", "series1.vtu", "series2.vtu", "series3.vtu"]
    times = [float(d.get("timestep")) for d in sets]
    assert times == pytest.approx([0.0, 0.02, 0.04, 0.06], abs=1e-12)
    for d in sets:
        reader = vtk.vtkXMLGenericDataObjectReader()
        reader.SetFileName(str(exported / d.get("file")))
        reader.Update()
        out = reader.GetOutput()
        assert out.GetNumberOfPoints() == 27 and out.GetNumberOfCells() == 8


def test_pvd_opens_in_vtk_pvd_reader_when_available(exported):
    if not hasattr(vtk, "vtkPVDReader"):
        pytest.skip("this VTK build has no vtkPVDReader (ParaView's); the collection is checked by parsing above")
    reader = vtk.vtkPVDReader()
    reader.SetFileName(str(exported / "series.pvd"))
    reader.Update()
    assert reader.GetNumberOfTimeSteps() == 4


def test_legacy_vtk_written_at_close_opens(exported):
    reader = vtk.vtkUnstructuredGridReader()
    reader.SetFileName(str(exported / "legacy_0.vtk"))
    reader.Update()
    grid = reader.GetOutput()
    assert grid.GetNumberOfPoints() == 27 and grid.GetNumberOfCells() == 8
    # Written when the run ended: the grid has fallen for 6 steps.
    assert points(grid)[0][1] < points(read_vtu(exported / "series3.vtu"))[0][1] + 1e-12


def test_mesh_exporter_vtu_opens(exported):
    grid = read_vtu(exported / "mesh.vtu")
    assert grid.GetNumberOfPoints() == 27 and grid.GetNumberOfCells() == 8
    assert tuple(points(grid)[13]) == (1.0, 1.0, 1.0)

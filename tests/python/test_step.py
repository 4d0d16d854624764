"""STEP models from Python (issue 28): read_step, section and intersect against closed forms and
against the CLI's JSON of the same command."""
import json
import math
import subprocess
from pathlib import Path

import pytest

import ssimarch


def total(trace) -> float:
    return sum(c.length for i in trace.intersections for c in i.curves)


def test_read_step_lists_placed_faces_and_the_unit(source_dir):
    m = ssimarch.read_step(str(source_dir / "tests/step/data/rod_assembly.step"))
    assert m["unit"]["name"] == "unspecified" and m["unit"]["metres"] == 0
    assert [f["face"] for f in m["faces"]] == [1, 2, 3, 4]
    assert [f["instance"] for f in m["faces"]] == ["rod_1", "sub_1/rod_2", "rod_3", "plate_1"]
    lo, hi = m["faces"][0]["box"]
    assert lo[0] == pytest.approx(3.5) and hi[0] == pytest.approx(6.5)  # rod_1 placed at x = 5
    assert all(f["error"] is None for f in m["faces"])
    with pytest.raises(ssimarch.InputError, match="no such file"):
        ssimarch.read_step(str(source_dir / "missing.step"))


def test_section_equals_the_closed_form_and_the_cli(source_dir, cli):
    model = str(source_dir / "tests/step/data/plate_with_hole.step")
    t = ssimarch.section(model, [[0, 0, 0, 1, 0, 0], [2.9, 0, 0, 1, 0, 0]])
    by_plane = {k: sum(c.length for i in t.intersections if i.name.endswith(k) for c in i.curves)
                for k in ("-plane1", "-plane2")}
    assert by_plane["-plane1"] == pytest.approx(4 + math.pi, abs=1e-9)
    assert by_plane["-plane2"] == pytest.approx(6, abs=1e-9)
    one = ssimarch.section(model, (0, 0, 0, 1, 0, 0), faces="1")
    assert total(one) == pytest.approx(4, abs=1e-9)
    out = subprocess.run([cli, "section", model, "--plane", "0,0,0,1,0,0", "--plane", "2.9,0,0,1,0,0", "-q"],
                         capture_output=True, text=True, check=True).stdout
    cli_lengths = sorted(c["length"] for i in json.loads(out)["intersections"] for c in i["curves"])
    assert sorted(c.length for i in t.intersections for c in i.curves) == pytest.approx(cli_lengths, abs=1e-12)
    for bad, key in (([0, 0, 0, 0, 0, 0], "planes"), ([[0, 0, 0, 1, 0]], r"planes\[0\]"), ([], "planes")):
        with pytest.raises(ssimarch.InputError, match=key):
            ssimarch.section(model, bad)
    with pytest.raises(ssimarch.InputError, match="faces"):
        ssimarch.section(model, (0, 0, 0, 1, 0, 0), faces="3")


def test_intersect_parts_by_name(source_dir):
    model = str(source_dir / "tests/step/data/rod_assembly.step")
    t = ssimarch.intersect(model, a_faces="part:plate", b_faces="part:rod")
    assert sorted(i.name for i in t.intersections) == ["face1-face4", "face2-face4", "face3-face4"]
    assert total(t) == pytest.approx(4 * math.pi + 20, rel=1e-9)
    assert ssimarch.intersect(model, a_faces="1", b_faces="3").intersections == []  # boxes apart: nothing traced
    with pytest.raises(ssimarch.InputError, match="a_faces"):
        ssimarch.intersect(model, a_faces="part:nothing")
    with pytest.raises(ssimarch.InputError, match="tolerence"):
        ssimarch.intersect(model, tolerence=1e-9)


def _in_millimetres(source: Path, name: str, tmp_path: Path) -> str:
    """A copy of a test model that declares the millimetre (the test models declare no unit)."""
    text = (source / "tests/step/data" / name).read_text()
    at = text.index("ENDSEC;", text.index("DATA;"))
    path = tmp_path / ("mm_" + name)
    path.write_text(text[:at] + "#999999=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.));\n" + text[at:])
    return str(path)


def test_unit_converts_the_model_as_the_cli_does(source_dir, tmp_path):
    plate = _in_millimetres(source_dir, "plate_with_hole.step", tmp_path)
    rods = _in_millimetres(source_dir, "rod_assembly.step", tmp_path)
    m = ssimarch.read_step(rods, unit="in")
    assert m["unit"]["name"] == "inch" and m["converted_from"]["name"] == "millimetre"
    lo, hi = m["faces"][0]["box"]
    assert lo[0] == pytest.approx(3.5 / 25.4) and hi[0] == pytest.approx(6.5 / 25.4)
    assert ssimarch.read_step(rods)["converted_from"] is None
    assert total(ssimarch.section(plate, (0, 0, 0, 1, 0, 0), unit="m")) == pytest.approx((4 + math.pi) * 1e-3, abs=1e-12)
    assert total(ssimarch.intersect(rods, unit="cm")) == pytest.approx((4 * math.pi + 20) / 10, abs=1e-9)
    with pytest.raises(ssimarch.InputError, match='unit: unknown length unit "furlong"'):
        ssimarch.section(plate, (0, 0, 0, 1, 0, 0), unit="furlong")
    with pytest.raises(ssimarch.InputError, match="declares no length unit"):
        ssimarch.read_step(str(source_dir / "tests/step/data/plate_with_hole.step"), unit="mm")


def test_faces_of_one_solid_meet_at_their_shared_edges(source_dir):
    model = str(source_dir / "tests/step/data/solids.step")
    t = ssimarch.intersect(model)
    assert len(t.intersections) == 29  # the octahedron's 4 pairs of opposite faces left out
    assert total(t) == pytest.approx(12 * math.sqrt(2) + 2 + 4 * math.pi, abs=1e-12)
    assert len(ssimarch.intersect(model, solid_topology=False).intersections) == 33

"""ssimarch.trace against closed forms and against the CLI's JSON of the same scene."""
import json
import math
import subprocess

import numpy as np
import pytest

import ssimarch


def viviani_length(a: float) -> float:
    """Length of Viviani's curve, sphere of radius 2a and cylinder of radius a through its centre.

    With x = a(1 + cos t), y = a sin t, z = 2a sin(t/2), t in [0, 4 pi): |r'| = a sqrt(1 + cos^2(t/2)),
    so L = 8a int_0^{pi/2} sqrt(1 + cos^2 w) dw = 8 sqrt(2) a E(1/sqrt 2). The periodic integrand makes
    the trapezoid rule exponentially accurate.
    """
    w = np.linspace(0.0, 2.0 * math.pi, 4097)[:-1]
    return 2.0 * a * float(np.mean(np.sqrt(1.0 + np.cos(w) ** 2))) * 2.0 * math.pi


def strip_timing(x):
    """The JSON without its wall-clock fields (time_ms), which differ between two runs."""
    if isinstance(x, dict):
        return {k: strip_timing(v) for k, v in x.items() if k != "time_ms"}
    if isinstance(x, list):
        return [strip_timing(v) for v in x]
    return x


def test_reference_length_is_eight_root_two_e():
    # E(1/sqrt 2) = 1.3506438810476755 (A&S 17.3, tabulated); independent of the quadrature above.
    assert viviani_length(1.0) == pytest.approx(8.0 * math.sqrt(2.0) * 1.3506438810476755, rel=1e-12)


def test_viviani_length_and_points_on_both_surfaces(viviani):
    result = ssimarch.trace(viviani, only="viviani")
    assert len(result) == 1
    run = result["viviani"]
    assert run.surfaces == ("sphere", "cyl")
    total = sum(c.length for c in run.curves)
    assert total == pytest.approx(viviani_length(1.0), rel=1e-4)
    for c in run.curves:
        xyz = c.xyz
        assert xyz.shape == (len(c), 3) and xyz.dtype == np.float64
        assert np.max(np.abs(np.sum(xyz**2, axis=1) - 4.0)) < 1e-6  # sphere of radius R = 2
        assert np.max(np.abs(xyz[:, 0] ** 2 + (xyz[:, 1] + 1.0) ** 2 - 1.0)) < 1e-6  # the cylinder
        assert c.params.shape == (len(c), len(run.unknowns))
        assert set(c.ends) == {"start", "end"}
    assert isinstance(run.stats["points"], int) and run.stats["points"] > 0
    # The node of the figure eight at (0, -2, 0), where the curve crosses itself.
    nodes = [p for p in run.singular_points if np.allclose(p["xyz"], [0.0, -2.0, 0.0], atol=1e-6)]
    assert nodes, run.singular_points


def test_to_json_equals_the_cli_output(viviani, cli):
    out = subprocess.run([cli, "trace", "-q", str(viviani)], check=True, capture_output=True, text=True).stdout
    mine = ssimarch.trace(str(viviani)).to_json()
    assert strip_timing(json.loads(mine)) == strip_timing(json.loads(out))
    # Same text apart from the timing values: same key order, number formatting, indentation.
    assert len(mine.splitlines()) == len(out.splitlines())


def test_dict_string_and_path_give_the_same_curves(viviani):
    scene = json.loads(viviani.read_text())
    a = ssimarch.trace(scene, only=["viviani"])
    b = ssimarch.trace(json.dumps(scene), only="viviani")
    c = ssimarch.trace(viviani, only="viviani")
    for x in (a, b):
        for cx, cc in zip(x["viviani"].curves, c["viviani"].curves):
            np.testing.assert_array_equal(cx.xyz, cc.xyz)
            np.testing.assert_array_equal(cx.params, cc.params)


def test_overrides_change_the_trace_and_are_reported(viviani):
    coarse = ssimarch.trace(viviani, only="viviani", step_length=0.2)["viviani"]
    fine = ssimarch.trace(viviani, only="viviani", step_length="R/100")["viviani"]
    assert json.loads(coarse.to_json())["options"]["step_length"] == 0.2
    assert json.loads(fine.to_json())["options"]["step_length"] == pytest.approx(0.02)
    # A tenth of the step: several times the points (the chordal rule also shortens steps where
    # the curve bends, so not ten times), and the same closed curve of the closed-form length.
    assert sum(len(c) for c in fine.curves) > 3 * sum(len(c) for c in coarse.curves)
    for r in (coarse, fine):
        assert [c.closed for c in r.curves] == [True]
        assert r.curves[0].length == pytest.approx(viviani_length(1.0), abs=1e-6)
    for c in fine.curves:
        assert np.max(np.abs(np.sum(c.xyz**2, axis=1) - 4.0)) < 1e-6


def test_override_is_the_cli_flag(viviani, cli):
    out = subprocess.run([cli, "trace", "-q", str(viviani), "--intersection", "viviani", "--step-length", "R/100"],
                         check=True, capture_output=True, text=True).stdout
    mine = ssimarch.trace(viviani, only="viviani", step_length="R/100").to_json()
    assert strip_timing(json.loads(mine)) == strip_timing(json.loads(out))


def test_geometry_option_gives_curvature_columns(viviani):
    run = ssimarch.trace(viviani, only="viviani", geometry="exact")["viviani"]
    c = max(run.curves, key=len)
    g = c.geometry
    assert g["t"].shape == (len(c), 3) and g["kappa"].shape == (len(c),)
    # A curve on a sphere of radius 2 has curvature >= 1/2 (Meusnier), wherever it is determined.
    k = g["kappa"][np.isfinite(g["kappa"])]
    assert k.size > len(c) // 2 and np.all(k >= 0.5 - 1e-6)
    assert ssimarch.trace(viviani, only="viviani")["viviani"].curves[0].geometry is None


# A valid value other than the default for every trace option. The key set must equal
# ssimarch.trace_options(), so an option added to the table fails here until it is listed.
NON_DEFAULT_OPTION_VALUES = {
    "predictor": "parabola", "corrector": "projection", "step": "angular", "step_length": 0.1,
    "min_step_length": 1e-4, "deviation": 1e-3, "turn_angle": 0.2, "min_step": 1e-8, "taylor_order": 3,
    "tolerance": 1e-11, "max_corrector_iterations": 20, "max_turn_angle": 0.5, "max_correction_ratio": 0.6,
    "max_points": 100000, "max_length": 100.0, "start_samples": 12, "certified_start_points": False,
    "start_box_budget": 20000, "closed_form": False, "hunt_isolated_points": False, "solid_topology": False,
    "geometry": "estimate", "bspline": True, "bspline_tolerance": 1e-8,
}


def test_every_option_is_documented_in_trace_from_the_table():
    # The keywords' help is the option table's: each key with its rule and default.
    doc = ssimarch.trace.__doc__
    for key in ssimarch.trace_options():
        assert f"  {key}: " in doc
    assert "step_length: the constant rule's step L" in doc
    assert "default 0 = automatic" in doc


def test_every_option_list_is_the_table():
    assert set(ssimarch.trace_options()) == set(NON_DEFAULT_OPTION_VALUES)


@pytest.mark.parametrize("key", sorted(NON_DEFAULT_OPTION_VALUES))
def test_every_option_key_is_accepted_by_name(viviani, key):
    # Each option alone (on the marcher: closed_form off), by keyword: the trace still gives
    # Viviani's one closed curve of the closed-form length, so none of them is ignored into an error.
    options = {"closed_form": False, key: NON_DEFAULT_OPTION_VALUES[key]}
    run = ssimarch.trace(viviani, only="viviani", **options)["viviani"]
    assert [c.closed for c in run.curves] == [True]
    assert run.curves[0].length == pytest.approx(viviani_length(1.0), abs=1e-5)


def test_unknown_option_is_an_input_error_naming_the_key(viviani):
    with pytest.raises(ssimarch.InputError, match="step_lenght: unknown option") as e:
        ssimarch.trace(viviani, step_lenght=0.1)
    assert isinstance(e.value, ValueError)
    assert "step_length" in str(e.value)  # the known options are listed


@pytest.mark.parametrize("value", [-1.0, float("nan"), "nonsense+", True])
def test_bad_option_value_is_an_input_error(viviani, value):
    with pytest.raises(ssimarch.InputError, match="^step_length: "):
        ssimarch.trace(viviani, step_length=value)


def test_bad_choice_lists_the_choices(viviani):
    with pytest.raises(ssimarch.InputError, match="predictor") as e:
        ssimarch.trace(viviani, predictor="psychic")
    assert "taylor" in str(e.value)


def test_scene_errors_carry_the_cli_message(viviani, cli, tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"surfaces": {"s": {"sphere": {"radius": -1}}}, "intersections": []}')
    cli_err = subprocess.run([cli, "trace", "-q", str(bad)], capture_output=True, text=True).stderr.strip()
    with pytest.raises(ssimarch.InputError) as e:
        ssimarch.trace(str(bad))
    assert cli_err == "ssimarch: error: " + str(e.value)
    with pytest.raises(ssimarch.InputError, match="no_such_file.json"):
        ssimarch.trace(str(tmp_path / "no_such_file.json"))
    with pytest.raises(ssimarch.InputError, match="only"):
        ssimarch.trace(viviani, only="nope")
    with pytest.raises(TypeError):
        ssimarch.trace(42)


def test_dict_scene_of_the_docs_is_a_circle():
    # docs/python.md: unit sphere and the plane z = 1/2 meet in a circle of radius sqrt(3)/2.
    scene = {"surfaces": {"s": {"sphere": {"center": [0, 0, 0], "radius": 1}},
                          "p": {"plane": {"point": [0, 0, 0.5], "normal": [0, 0, 1]}}},
             "intersections": [{"name": "circle", "surfaces": ["s", "p"]}]}
    result = ssimarch.trace(scene)
    assert result.complete
    (c,) = result["circle"].curves
    assert c.closed
    assert c.length == pytest.approx(2 * math.pi * math.sqrt(3) / 2, rel=1e-4)
    np.testing.assert_allclose(c.xyz[:, 2], 0.5, atol=1e-7)
    with pytest.raises(KeyError):
        result["nope"]


def test_topology_of_the_figure_eight(viviani):
    run = ssimarch.trace(viviani, only="viviani")["viviani"]
    topo = run.topology
    assert json.loads(topo.to_json()) == json.loads(run.to_json())["topology"]
    assert topo.complete and topo.failures == []
    # One closed curve through the node at (0, -2, 0): one vertex, two loops as edges, one component.
    nodes = [v for v in topo.vertices if v["kind"] == "singular_point"]
    assert len(nodes) == 1 and nodes[0]["type"] == "node"
    np.testing.assert_allclose(nodes[0]["xyz"], [0.0, -2.0, 0.0], atol=1e-6)
    assert len(topo.branches) == len(run.curves) == 1 and topo.branches[0]["closed"]
    assert len(topo.edges) == 2 and all(e["vertices"] == [nodes[0]["id"]] * 2 for e in topo.edges)
    assert sum(e["length"] for e in topo.edges) == pytest.approx(viviani_length(1.0), rel=1e-3)
    assert topo.components == [{"branches": [0], "vertices": [nodes[0]["id"]]}]


def test_singular_expansions_follow_the_traced_curve(viviani):
    """Each half-branch at the node: the Puiseux expansion W(X) = sum c X^e (singular/puiseux.hpp)
    describes the curve over the common tangent plane at the node, the same for every pair kind
    (singular/tangent_plane_expansion.hpp): X = (P - P0) . tangent, W = (P - P0) . normal for the
    curve's 3D points P. The curve's own points must follow it; on Viviani's node
    W = +-(X^3/32 + X^5/256)."""
    run = ssimarch.trace(viviani, only="viviani", step_length=0.01)["viviani"]
    (node,) = [p for p in run.singular_points if p["type"] == "node"]
    w3 = np.vstack([c.xyz for c in run.curves]) - np.array(node["xyz"])
    assert len(node["half_branches"]) == 4
    for hb in node["half_branches"]:
        t, n = np.array(hb["tangent"]), np.array(hb["expansion"]["normal"])
        terms = hb["expansion"]["terms"]
        assert terms[0]["exponent"] == hb["expansion"]["exponent"]
        # The leading term twice: measured on the curve at 1e-2 from the node (O(X^2) relative
        # here, the branch being odd in X), and refined by the Newton-Puiseux step.
        assert terms[0]["coefficient"] == pytest.approx(hb["expansion"]["coefficient"], rel=1e-4)
        assert abs(terms[0]["coefficient"]) == pytest.approx(1 / 32, rel=1e-12)
        X, W = w3 @ t, w3 @ n
        mine = (X > 0.02) & (X < 0.15) & (np.abs(W) < 0.5 * X)
        assert mine.sum() >= 5, hb
        expected = sum(term["coefficient"] * X[mine] ** term["exponent"] for term in terms)
        # Truncated at order 6: the remainder is O(X^7), far below the tolerance.
        np.testing.assert_allclose(W[mine], expected, rtol=0, atol=1e-8)

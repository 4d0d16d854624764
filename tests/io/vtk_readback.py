#!/usr/bin/python3
"""ParaView's files read back by VTK's own XML readers (Debian's python3-vtk9) and compared with
the JSON and CSV outputs of the same runs: `ssimarch trace --format vtp` (curves and the curve
network's vertices, a multiblock of both) and `ssimarch porosity --format vtk` (profiles .vtp,
map .vti). Run by ctest (tests/io/CMakeLists.txt): vtk_readback.py SSIMARCH SOURCE_DIR WORK_DIR."""
import csv
import json
import math
import subprocess
import sys
from pathlib import Path

from vtkmodules.vtkIOXML import (vtkXMLImageDataReader, vtkXMLMultiBlockDataReader,
                                 vtkXMLPolyDataReader)

SSIMARCH, SOURCE, WORK = sys.argv[1], Path(sys.argv[2]), Path(sys.argv[3])
WORK.mkdir(parents=True, exist_ok=True)
failures = []
checks = [0]


def check(ok, what):
    checks[0] += 1
    if not ok:
        failures.append(what)
        print("FAIL:", what)


def run(*args):
    subprocess.run([SSIMARCH, *map(str, args)], check=True, stdout=subprocess.DEVNULL)


def read(reader_class, path):
    r = reader_class()
    r.SetFileName(str(path))
    r.Update()
    return r.GetOutput()


def values(data, name):
    a = data.GetAbstractArray(name)
    check(a is not None, f"array {name} present")
    if a is None:
        return []
    n = a.GetNumberOfComponents()
    if n == 1:
        return [a.GetValue(i) for i in range(a.GetNumberOfValues())]
    return [a.GetTuple(i) for i in range(a.GetNumberOfTuples())]


def close(a, b, tol=1e-12):
    if a is None or b is None:  # null in JSON: NaN in VTK
        return (a is None or math.isnan(a)) and (b is None or math.isnan(b))
    return abs(a - b) <= tol * max(1.0, abs(a), abs(b))


def check_trace(scene):
    name = Path(scene).stem
    out_json = WORK / f"{name}.json"
    run("trace", SOURCE / scene, "-q", "--geometry", "mixed", "-o", out_json)
    run("trace", SOURCE / scene, "-q", "--format", "vtp", "-o", WORK / f"{name}.vtp")
    run("trace", SOURCE / scene, "-q", "--format", "vtp-ascii", "-o", WORK / f"{name}_ascii.vtm")
    js = json.loads(out_json.read_text())["intersections"]
    for vtp in (WORK / f"{name}.vtp", WORK / f"{name}_ascii.vtp"):
        curves = read(vtkXMLPolyDataReader, vtp)
        pd = curves.GetPointData()
        xyz = [curves.GetPoint(i) for i in range(curves.GetNumberOfPoints())]
        kappa, tau, arc = values(pd, "kappa"), values(pd, "tau"), values(pd, "arc_length")
        branch, inter, params = values(pd, "branch"), values(pd, "intersection"), values(pd, "params")
        expected = [(ri, ci, p, c) for ri, r in enumerate(js) for ci, c in enumerate(r["curves"]) for p in c["points"]]
        check(len(xyz) == len(expected), f"{vtp.name}: {len(xyz)} points, JSON {len(expected)}")
        check(curves.GetNumberOfLines() == sum(len(r["curves"]) for r in js), f"{vtp.name}: one polyline per curve")
        for i, (ri, ci, p, c) in enumerate(expected[:len(xyz)]):
            check(all(close(a, b) for a, b in zip(xyz[i], p["xyz"])), f"{vtp.name} point {i}: xyz")
            check(all(close(a, b) for a, b in zip(params[i], p["params"])), f"{vtp.name} point {i}: params")
            check(close(kappa[i], p.get("kappa")) and close(tau[i], p.get("tau")), f"{vtp.name} point {i}: kappa, tau")
            check(branch[i] == ci and inter[i] == ri, f"{vtp.name} point {i}: branch and intersection ids")
            last = i + 1 == len(expected) or expected[i + 1][1] != ci or expected[i + 1][0] != ri
            if last:
                check(close(arc[i], c["length"], 1e-9), f"{vtp.name} curve {ci}: arc length {arc[i]} vs {c['length']}")
        points = read(vtkXMLPolyDataReader, vtp.with_name(vtp.stem + "_points.vtp"))
        vertices = [v for r in js for v in r["topology"]["vertices"]]
        check(points.GetNumberOfPoints() == len(vertices) and points.GetNumberOfVerts() == len(vertices),
              f"{vtp.name}: {points.GetNumberOfPoints()} network vertices, JSON {len(vertices)}")
        kinds = values(points.GetFieldData(), "kind_names")
        for i, (k, t) in enumerate(zip(values(points.GetPointData(), "kind"), values(points.GetPointData(), "type"))):
            check(kinds[k] == vertices[i]["kind"], f"{vtp.name} vertex {i}: kind {kinds[k]}")
            check(t == (vertices[i]["type"] or vertices[i]["kind"]), f"{vtp.name} vertex {i}: type {t}")
            check(all(close(a, b) for a, b in zip(points.GetPoint(i), vertices[i]["xyz"])), f"{vtp.name} vertex {i}: xyz")
    blocks = read(vtkXMLMultiBlockDataReader, WORK / f"{name}_ascii.vtm")
    check(blocks.GetNumberOfBlocks() == 2, f"{name}_ascii.vtm: two blocks")
    check(blocks.GetBlock(0).GetNumberOfLines() == sum(len(r["curves"]) for r in js), f"{name}_ascii.vtm: curves block")
    return sum(1 for r in js for v in r["topology"]["vertices"] if v["kind"] == "singular_point")


def csv_rows(path):
    with open(path) as f:
        return [[float(x) for x in row] for row in list(csv.reader(f))[1:]]


def check_porosity():
    packing = WORK / "bed.csv"
    run("packing", "spheres", "--container-radius", 3, "--count", 150, "--seed", 3, "-q", "-o", packing)
    common = ["porosity", packing, "--container-radius", 3, "-q", "--radii", 17, "--axial", 9, "--map", "5,4"]
    run(*common, "-o", WORK / "p.csv")
    run(*common, "-o", WORK / "p.vtm", "--summary", WORK / "p.json")
    summary = json.loads((WORK / "p.json").read_text())["outputs"]
    radial = read(vtkXMLPolyDataReader, WORK / "p_radial.vtp")
    rows = csv_rows(WORK / "p.csv")
    check(values(radial.GetPointData(), "porosity") == [r[1] for r in rows], "radial porosity equals the CSV's")
    check([radial.GetPoint(i)[0] for i in range(radial.GetNumberOfPoints())] == [r[0] for r in rows], "radial r")
    axial = read(vtkXMLPolyDataReader, WORK / "p_axial.vtp")
    rows = csv_rows(WORK / "p_axial.csv")
    check(values(axial.GetPointData(), "porosity") == [r[1] for r in rows], "axial porosity equals the CSV's")
    check([axial.GetPoint(i)[2] for i in range(axial.GetNumberOfPoints())] == [r[0] for r in rows], "axial z")
    image = read(vtkXMLImageDataReader, WORK / "p_map.vti")
    check(image.GetDimensions() == (5, 1, 4), f"map dimensions {image.GetDimensions()}")
    rows = csv_rows(WORK / "p_map.csv")
    por = values(image.GetPointData(), "porosity")
    check(len(por) == len(rows) and all(close(a, r[2]) for a, r in zip(por, rows)), "map porosity equals the CSV's")
    check(all(close(image.GetPoint(i)[0], r[0]) and close(image.GetPoint(i)[2], r[1]) for i, r in enumerate(rows)),
          "map points at the CSV's (r, z)")
    check(summary["map"]["file"].endswith("p_map.vti") and summary["multiblock"].endswith("p.vtm"), "summary names the files")
    blocks = read(vtkXMLMultiBlockDataReader, WORK / "p.vtm")
    check(blocks.GetNumberOfBlocks() == 3, "p.vtm: radial, axial and map blocks")


singular = check_trace("examples/thesis_ex12_three_petals.json")
check(singular >= 1, "the three petals' triple point is in the points block")
check_porosity()
print("vtk_readback:", "FAILED" if failures else "OK", f"({len(failures)} failures of {checks[0]} checks)")
sys.exit(1 if failures else 0)

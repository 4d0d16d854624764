"""The type stubs (.pyi) name exactly the module's public attributes with their parameters, and
py.typed is shipped."""
import ast
import inspect
import pathlib
import re

import ssimarch


def stub_tree(path: pathlib.Path) -> dict:
    """{top-level name: {member: [FunctionDef, ...]} for classes, [FunctionDef] for functions, None}."""
    tree = ast.parse(path.read_text())
    out = {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            members = {}
            for n in node.body:
                if isinstance(n, ast.FunctionDef):
                    members.setdefault(n.name, []).append(n)
            out[node.name] = members
        elif isinstance(node, ast.FunctionDef):
            out[node.name] = [node]
        elif isinstance(node, ast.ImportFrom) and node.level == 1:
            out.update({a.asname or a.name: None for a in node.names})
    return out


def public(obj) -> set:
    return {n for n in dir(obj) if not n.startswith("_")}


def stub_parameters(fn: ast.FunctionDef) -> list:
    a = fn.args
    names = [x.arg for x in a.posonlyargs + a.args + a.kwonlyargs]
    if a.kwarg:
        names.append("**" + a.kwarg.arg)
    return [n for n in names if n != "self"]


def module_parameters(obj) -> list:
    """Parameter names of each signature of a function: pybind11's from the first docstring lines
    (one per overload), a Python function's from inspect."""
    doc = obj.__doc__ or ""
    if not isinstance(obj, type(len)) and not type(obj).__name__ == "instancemethod":
        try:
            sig = inspect.signature(obj)
            names = [("**" + p.name) if p.kind == p.VAR_KEYWORD else p.name for p in sig.parameters.values()]
            return [[n for n in names if n != "self"]]
        except (TypeError, ValueError):
            pass
    out = []
    for m in re.finditer(r"^(?:\d+\. )?\w+\((.*)\) ->", doc, re.M):
        names = []
        for part in re.split(r",\s*(?![^\[]*\])", m.group(1)):
            part = part.strip()
            if part in ("", "*"):
                continue
            name = part.split(":")[0].strip()
            names.append(name)
        out.append([n for n in names if n != "self"])
    return out


def check(stub: pathlib.Path, module) -> None:
    names = stub_tree(stub)
    assert set(names) == public(module) - {"annotations"}, stub
    for name, members in names.items():
        obj = getattr(module, name)
        if isinstance(members, dict):
            assert {m for m in members if not m.startswith("__")} == public(obj) - public(Exception), name
            for m, defs in members.items():
                if m.startswith("__") or isinstance(getattr(obj, m), property):
                    continue
                assert sorted(stub_parameters(d) for d in defs) == sorted(module_parameters(getattr(obj, m))), \
                    f"{name}.{m}"
        elif isinstance(members, list):
            assert [stub_parameters(d) for d in members] == module_parameters(obj), name


def test_package_stubs_match_the_module():
    pkg = pathlib.Path(ssimarch.__file__).parent
    assert (pkg / "py.typed").exists()
    check(pkg / "__init__.pyi", ssimarch)
    check(pkg / "porosity.pyi", ssimarch.porosity)


def test_the_checker_sees_a_wrong_parameter(tmp_path):
    # The check can fail: a stub whose trace has a misspelt keyword is rejected.
    stub = tmp_path / "bad.pyi"
    stub.write_text((pathlib.Path(ssimarch.__file__).parent / "__init__.pyi").read_text()
                    .replace("only: Union", "olny: Union"))
    try:
        check(stub, ssimarch)
    except AssertionError:
        return
    raise AssertionError("a misspelt parameter passed the stub check")

"""The type stubs (.pyi) name exactly the module's public attributes, and py.typed is shipped."""
import ast
import pathlib

import ssimarch


def stub_names(path: pathlib.Path) -> dict:
    """{top-level name: set of member names (classes) or None}."""
    tree = ast.parse(path.read_text())
    out = {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            out[node.name] = {n.name for n in node.body if isinstance(n, ast.FunctionDef)}
        elif isinstance(node, ast.FunctionDef):
            out[node.name] = None
        elif isinstance(node, ast.ImportFrom) and node.module is None:
            out.update({a.asname or a.name: None for a in node.names})
    return out


def public(obj) -> set:
    return {n for n in dir(obj) if not n.startswith("_")}


def check(stub: pathlib.Path, module) -> None:
    names = stub_names(stub)
    assert set(names) == public(module) - {"annotations"}, stub
    for name, members in names.items():
        if members is not None:
            cls = getattr(module, name)
            assert members - {"__len__", "__getitem__"} == public(cls) - public(Exception), name


def test_package_stubs_match_the_module():
    pkg = pathlib.Path(ssimarch.__file__).parent
    assert (pkg / "py.typed").exists()
    check(pkg / "__init__.pyi", ssimarch)
    check(pkg / "porosity.pyi", ssimarch.porosity)

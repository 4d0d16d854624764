"""The README's Python snippet (section "From Python") runs as written and prints what it says."""
import os
import re
import subprocess
import sys


def test_readme_python_snippet_runs(source_dir):
    readme = (source_dir / "README.md").read_text()
    blocks = re.findall(r"```sh\n(PYTHONPATH=(\S+) /usr/bin/python3 - <<'PY'\n(.*?)\nPY\n)```", readme, re.S)
    assert len(blocks) == 1, "the README should hold one Python snippet run from the shell"
    _, pythonpath, code = blocks[0]
    # As written it runs from the source directory against the build tree of `make demo` (preset
    # release: ./build); here against the package of the build tree under test (PYTHONPATH of ctest).
    assert pythonpath == "build/python"
    out = subprocess.run([sys.executable, "-"], input=code, cwd=source_dir, env=dict(os.environ), check=True,
                         capture_output=True, text=True).stdout.splitlines()
    # Viviani's curve: one closed curve of length 8 sqrt(2) E(1/sqrt 2) = 15.2808 through the node.
    assert re.match(r"^\[\(True, 15\.2808, \(\d+, 3\)\)\] node$", out[0]), out
    # The torus point F(0, 0.5) = (3 + cos 0.5, 0, sin 0.5) and the two circles cut by z = 1/2.
    rest = "\n".join(out[1:])  # numpy prints the 2 x 3 array on two lines
    assert "3.87758256" in rest and "0.47942554" in rest and rest.endswith("<ssimarch.Intersection a-b, 2 curve(s)>"), out

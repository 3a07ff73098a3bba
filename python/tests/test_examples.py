"""Every examples/python/*.py script (except the Dask renderer, tested in test_dask_render.py) runs and
writes its pictures and meshes, so the examples cannot rot."""
import glob
import os
import subprocess
import sys

import pytest

EXAMPLES = os.path.join(os.path.dirname(__file__), "..", "..", "examples", "python")
SCRIPTS = sorted(p for p in glob.glob(os.path.join(EXAMPLES, "*.py")) if not p.endswith("dask_render.py"))


@pytest.mark.parametrize("script", SCRIPTS, ids=[os.path.basename(p) for p in SCRIPTS])
def test_example_runs(script, tmp_path):
    subprocess.run([sys.executable, script, str(tmp_path)], check=True, capture_output=True, text=True, timeout=900)
    written = [f for f in os.listdir(tmp_path) if f.endswith((".png", ".obj"))]
    assert written, f"{os.path.basename(script)} wrote no PNG or OBJ"

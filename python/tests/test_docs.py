"""The NumPy round trip docs/python.md shows runs as written, and gives the
shapes and types its comments promise."""
import math
import os
import re

import numpy as np

from conftest import REPO


def test_the_documented_round_trip_runs(monkeypatch):
    text = open(os.path.join(REPO, "docs", "python.md")).read()
    code = re.search(r"```python\n(.*?)```", text, re.S).group(1)
    assert len(code.strip().splitlines()) <= 10
    monkeypatch.chdir(REPO)  # it names scenes/whitted.json
    names = {}
    exec(compile(code, "docs/python.md", "exec"), names)
    assert names["image"].shape == (48, 64, 4) and names["image"].dtype == np.float32
    depth, hits = names["depth"], names["hits"]
    assert depth.shape == (60, 80)
    assert math.isinf(depth[0, 0]) and abs(depth[30, 40] - 3.0) < 1e-3  # near the sphere's front, 4 - 1 away
    assert len(hits) == 1000 and ((hits["prim"] == 0) == np.isfinite(hits["t"])).all()

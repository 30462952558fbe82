"""Each script of examples/python/ runs at its --quick sizes, draws its PNG, and its checks pass
(ctest runs one script per test: `-k NAME`)."""
import os
import subprocess
import sys

import pytest

from conftest import SOURCE

SCRIPTS = sorted(path.stem for path in (SOURCE / "examples/python").glob("*.py") if path.stem != "teaching")


@pytest.mark.parametrize("name", SCRIPTS)
def test_script_passes_its_checks(name, tmp_path):
    script = SOURCE / "examples/python" / f"{name}.py"
    completed = subprocess.run([sys.executable, script, "--quick", "--out", tmp_path], capture_output=True, text=True,
                               env={**os.environ, "MPLBACKEND": "Agg"})
    assert completed.returncode == 0, completed.stdout + completed.stderr
    assert "FAIL" not in completed.stdout and "all checks passed" in completed.stdout
    assert (tmp_path / f"{name}.png").stat().st_size > 10_000

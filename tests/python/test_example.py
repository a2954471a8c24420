"""The example study (examples/python) runs and writes its plot."""
import subprocess
import sys

from conftest import SOURCE


def test_example_study_writes_its_png(tmp_path):
    out = tmp_path / "growth.png"
    p = subprocess.run([sys.executable, str(SOURCE / "examples" / "python" / "solve_time_growth.py"), "--quick",
                        str(out)], capture_output=True, text=True, timeout=600)
    assert p.returncode == 0, p.stderr
    assert "discrete   n= 5" in p.stdout and "continuous n= 3" in p.stdout
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and out.stat().st_size > 10000

"""examples/python/ run as a user runs them (docs/python.md "Examples"): each writes its PNG and
prints what it drew. Short versions: three sweep points, two 300 s runs."""
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def run_example(name, *args, cwd):
    env = dict(os.environ, MPLBACKEND="Agg")
    return subprocess.run([sys.executable, os.path.join(ROOT, "examples", "python", name), *args],
                          capture_output=True, text=True, cwd=cwd, env=env)


def is_png(path):
    with open(path, "rb") as f:
        return f.read(8) == b"\x89PNG\r\n\x1a\n"


def test_gamma_sweep_draws_the_certified_curve(tmp_path):
    run = run_example("gamma_sweep.py", "--lo", "0", "--hi", "1", "--points", "3", "-o", "g.png", cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    assert is_png(tmp_path / "g.png")
    lines = [l for l in run.stdout.splitlines() if l.startswith("delta_bar")]
    assert len(lines) == 3 and all(l.endswith("exit 0") for l in lines)
    gammas = [float(l.split("gamma =")[1].split()[0]) for l in lines]
    assert gammas == sorted(gammas)  # a larger uncertainty never gives a smaller certified bound here


def test_paper_navigation_draws_every_filter(tmp_path):
    run = run_example("paper_navigation.py", "--runs", "2", "--duration", "300", "-o", "nav.png", cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    assert is_png(tmp_path / "nav.png")
    for f in ("hinf", "published", "ekf", "ekf_no_control", "rekf"):
        assert "'%s'" % f in run.stdout, run.stdout

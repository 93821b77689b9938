"""What the plots show (issue "A tool people enjoy", item 3), read from the gnuplot scripts the
executables write: a stand-in `gnuplot` first on PATH keeps each script and draws a one-byte
file for every `set output`. The PNGs themselves were looked at (docs/experiments.md).
Needs only the executables."""
import os
import re
import stat
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SYNTH = os.environ.get("HINF_SYNTH", os.path.join(ROOT, "build", "bin", "hinf-synth"))
SIM = os.environ.get("HINF_SIM", os.path.join(ROOT, "build", "bin", "hinf-sim"))

FAKE = """#!/bin/bash
n=$(ls "$KEEP" | wc -l)
cp "$1" "$KEEP/script-$n.gp"
grep -o "^set output '[^']*'" "$1" | sed "s/^set output '//; s/'$//" | while read -r f; do printf x > "$f"; done
"""


def run_with_fake_gnuplot(tmp_path, argv):
    bin_dir, keep = tmp_path / "fakebin", tmp_path / "scripts"
    bin_dir.mkdir()
    keep.mkdir()
    fake = bin_dir / "gnuplot"
    fake.write_text(FAKE)
    fake.chmod(fake.stat().st_mode | stat.S_IEXEC)
    env = dict(os.environ, PATH=str(bin_dir) + os.pathsep + os.environ["PATH"], KEEP=str(keep))
    r = subprocess.run(argv, capture_output=True, text=True, env=env)
    assert r.returncode == 0, r.stderr
    return "\n".join(p.read_text() for p in sorted(keep.iterdir()))


def test_monte_carlo_errors_show_the_band_the_marks_and_the_seed(tmp_path):
    script = run_with_fake_gnuplot(tmp_path, [SIM, os.path.join(ROOT, "configs", "scenarios", "paper-control.yaml"),
                                              "-o", str(tmp_path / "run"), "--runs", "3", "--seed", "7",
                                              "--duration", "300", "-q"])
    assert script.count("with filledcurves") == 2 * 5  # each filter's 5-95 % band, both figures
    assert "median and 5–95 % of 3 runs, seed 7" in script and "moving RMS over 3 s" in script
    assert "convergence 1 m" in script and "'steady state' at first 150," in script
    (tmp_path / "one").mkdir()
    single = run_with_fake_gnuplot(tmp_path / "one", [SIM, os.path.join(ROOT, "configs", "scenarios", "paper-control.yaml"),
                                                      "-o", str(tmp_path / "run1"), "--duration", "300", "-q"])
    assert "filledcurves" not in single and "run 0 (raw norm lighter), seed 1" in single


def test_every_family_names_scenario_seed_and_runs(tmp_path):
    for name, extra in (("tumbling-hold-pwm", []), ("gyroless-attitude", ["--duration", "200"])):
        (tmp_path / name).mkdir()
        script = run_with_fake_gnuplot(tmp_path / name, [SIM, os.path.join(ROOT, "configs", "scenarios", name + ".yaml"),
                                                         "-o", str(tmp_path / name / "run"), "--runs", "2", "-q"] + extra)
        assert name + ", seed 1, 2 runs" in script, name


def test_hold_thrusters_are_duty_cycle_strips(tmp_path):
    script = run_with_fake_gnuplot(tmp_path, [SIM, os.path.join(ROOT, "configs", "scenarios", "tumbling-hold-pwm.yaml"),
                                              "-o", str(tmp_path / "run"), "-q"])
    assert "moving mean over 15 s (the pulses'' duty cycle) and the command U" in script  # '' : gnuplot's quote
    assert re.search(r"set multiplot layout 3,1", script)


def test_sigma_plot_draws_the_certified_gamma(tmp_path):
    script = run_with_fake_gnuplot(tmp_path, [SYNTH, "compare", os.path.join(ROOT, "configs", "paper-dbar0.05.yaml"),
                                              os.path.join(ROOT, "tests", "golden", "paper-dbar0.05.yaml"),
                                              "--plot", str(tmp_path / "s.png"), "-q"])
    assert "certified gamma = 0.3587237129" in script and "set arrow from graph 0, first 0.358723712" in script

"""The command-line convention (docs/cli.md): '-o -' puts the file alone on stdout (the report
on stderr), -q leaves stdout empty, '-o -' with --json is refused. Needs only the executable."""
import json
import os
import re
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SYNTH = os.environ.get("HINF_SYNTH", os.path.join(ROOT, "build", "bin", "hinf-synth"))
CONFIG = os.path.join(ROOT, "configs", "paper-dbar0.05.yaml")
GOLDEN = os.path.join(ROOT, "tests", "golden", "paper-dbar0.05.yaml")
TIMING = re.compile(r"solve_time_s|time_s")


def synth(*args):
    return subprocess.run([SYNTH, *args], capture_output=True, text=True)


def timing_apart(text):
    return "\n".join(l for l in text.splitlines() if not TIMING.search(l))


def test_dash_puts_the_file_alone_on_stdout(tmp_path):
    to_file = synth("solve", CONFIG, "-o", str(tmp_path / "g.yaml"))
    to_stdout = synth("solve", CONFIG, "-o", "-")
    assert to_file.returncode == 0 and to_stdout.returncode == 0
    assert timing_apart(to_stdout.stdout) == timing_apart((tmp_path / "g.yaml").read_text())
    assert "gains written to stdout" in to_stdout.stderr
    sdpa = synth("export-sdpa", CONFIG, "-o", "-")
    assert synth("export-sdpa", CONFIG, "-o", str(tmp_path / "p.dat-s")).returncode == 0
    assert sdpa.returncode == 0 and sdpa.stdout == (tmp_path / "p.dat-s").read_text()
    sweep = synth("sweep", CONFIG, "--param", "delta_bar=0:1:1", "-o", "-")
    assert sweep.returncode == 0 and sweep.stdout.startswith("parameter,value,outcome") and "delta_bar = 0" in sweep.stderr
    compare = synth("compare", CONFIG, GOLDEN, "--points", "10", "-o", "-")
    assert compare.returncode == 0 and compare.stdout.startswith("theta_rad_per_sample,")


def test_quiet_prints_nothing_on_success(tmp_path):
    for args in (["solve", CONFIG, "-o", str(tmp_path / "g.yaml")], ["verify", CONFIG, GOLDEN], ["analyze", CONFIG, GOLDEN],
                 ["export-sdpa", CONFIG, "-o", str(tmp_path / "p.dat-s")],
                 ["codegen", GOLDEN, "--prefix", "nav", "-o", str(tmp_path / "gen")]):
        run = synth(*args, "-q")
        assert run.returncode == 0 and run.stdout == "", args


def test_stdout_for_two_things_is_refused(tmp_path):
    run = synth("solve", CONFIG, "-o", "-", "--json")
    assert run.returncode == 2 and "-o - and --json both write to stdout" in run.stderr and run.stdout == ""


def test_sweep_json_to_stdout_and_check_verbose():
    sweep = synth("sweep", CONFIG, "--param", "delta_bar=0:1:1", "--json", "-")
    assert sweep.returncode == 0
    import json
    assert json.loads(sweep.stdout)["schema"] == "hinf-synth.sweep/1" and "delta_bar = 1" in sweep.stderr
    both = synth("sweep", CONFIG, "--param", "delta_bar=0:1:1", "--json", "-", "-o", "-")
    assert both.returncode == 2 and "both write to stdout" in both.stderr
    check = synth("check", CONFIG, "--golden", GOLDEN, "-v")
    assert check.returncode == 0 and "phase  step" in check.stderr and "same" in check.stdout


def test_a_run_replaces_the_earlier_run_in_its_directory(tmp_path):
    """hinf-sim into a directory that holds a run: that run's files this one does not write
    (its plots, when this one is --no-plots) are removed and the note says which; the user's own
    files stay; --json says the same."""
    sim = os.environ.get("HINF_SIM", os.path.join(ROOT, "build", "bin", "hinf-sim"))
    scenario = os.path.join(ROOT, "configs", "scenarios", "paper-no-control.yaml")
    out = tmp_path / "run"
    first = subprocess.run([sim, scenario, "-o", str(out), "--duration", "100", "-q"], capture_output=True, text=True)
    assert first.returncode == 0, first.stderr
    pngs = sorted(p.name for p in out.iterdir() if p.suffix == ".png")
    assert pngs and "position_error.png" in pngs
    (out / "notes.txt").write_text("mine")
    second = subprocess.run([sim, scenario, "-o", str(out), "--duration", "100", "--no-plots"],
                            capture_output=True, text=True)
    assert second.returncode == 0, second.stderr
    assert not [p for p in out.iterdir() if p.suffix == ".png"]
    assert (out / "notes.txt").read_text() == "mine"
    assert f"hinf-sim: note: {out} held an earlier run; replaced (removed its files this run did not write: " \
        in second.stderr
    assert all(name in second.stderr for name in pngs)
    third = subprocess.run([sim, scenario, "-o", str(out), "--duration", "100", "--no-plots", "--json"],
                           capture_output=True, text=True)
    j = json.loads(third.stdout)
    assert third.returncode == 0 and j["replaced_previous_run"] is True and j["removed_previous_files"] == []

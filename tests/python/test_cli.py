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


def test_sweep_by_a_named_parameter_in_its_units(tmp_path):
    """sweep --param k=… on a config with a named parameter k (issue 38 #5): the values are k's,
    the design point moves to each; at the config's own nominal the point is solve's γ, bit
    for bit; a misspelt name is named with the closest parameter."""
    config = os.path.join(ROOT, "configs", "example-parameters.yaml")
    swept = synth("sweep", config, "--param", "k=0.5:0.25:1", "--json", "-", "-q")
    assert swept.returncode == 0, swept.stderr
    points = json.loads(swept.stdout)["points"][::-1]  # k = 1 (the config's nominal) first
    assert [p["value"] for p in points] == [1, 0.75, 0.5]
    assert all(p["outcome"] == "certified" for p in points)
    solve = synth("solve", config, "--json", "-q", "-o", str(tmp_path / "g.yaml"))
    assert solve.returncode == 0, solve.stderr
    assert points[0]["gamma"] == json.loads(solve.stdout)["gamma"]
    assert len({p["gamma"] for p in points}) == 3  # a stiffer coupling is another plant
    typo = synth("sweep", config, "--param", "kk=1:1:2")
    assert typo.returncode == 2 and "did you mean 'k'?" in typo.stderr
    # analyze names the worst case found in k's units, inside k's range, below the certified γ
    analysis = synth("analyze", config, str(tmp_path / "g.yaml"), "--json")
    assert analysis.returncode == 0, analysis.stderr
    a = json.loads(analysis.stdout)
    assert list(a["worst_parameters"]) == ["k"] and 0.95 <= a["worst_parameters"]["k"] <= 1.05
    assert a["hinf_norm_nominal"] * (1 - 1e-7) <= a["worst_parameters_gain"] <= a["robust_bound"] <= points[0]["gamma"]
    text = synth("analyze", config, str(tmp_path / "g.yaml")).stdout
    assert re.search(r"worst case in the box +[0-9.]+ at k = [0-9.]+", text), text


def test_the_older_out_spelling_still_works_with_a_note(tmp_path):
    """--out (hinf-sim, codegen) is the older spelling of -o/--output: it still writes where it
    says, with a note on stderr; given beside -o it is refused; neither is 'required'."""
    sim = os.environ.get("HINF_SIM", os.path.join(ROOT, "build", "bin", "hinf-sim"))
    scenario = os.path.join(ROOT, "configs", "scenarios", "paper-no-control.yaml")
    old = subprocess.run([sim, scenario, "--out", str(tmp_path / "r"), "--duration", "50", "--no-plots", "-q"],
                         capture_output=True, text=True)
    assert old.returncode == 0 and (tmp_path / "r" / "summary.json").exists(), old.stderr
    assert "--out is the older spelling of -o/--output" in old.stderr
    both = subprocess.run([sim, scenario, "--out", str(tmp_path / "a"), "-o", str(tmp_path / "b")],
                          capture_output=True, text=True)
    assert both.returncode == 2 and "excludes" in both.stderr and not (tmp_path / "a").exists()
    none = subprocess.run([sim, scenario], capture_output=True, text=True)
    assert none.returncode == 2 and "hinf-sim: error: --output is required" in none.stderr
    gen = synth("codegen", GOLDEN, "--prefix", "nav", "--out", str(tmp_path / "c"))
    assert gen.returncode == 0 and (tmp_path / "c" / "nav.h").exists(), gen.stderr
    assert "--out is the older spelling of -o/--output" in gen.stderr
    gen_none = synth("codegen", GOLDEN, "--prefix", "nav")
    assert gen_none.returncode == 2 and "--output is required" in gen_none.stderr


def test_verbose_on_every_subcommand(tmp_path):
    """-v on the subcommands that run no synthesis: each stage on stderr with its wall time;
    sweep: each point as it ends; stdout unchanged by -v."""
    cases = {
        "analyze": ["analyze", CONFIG, GOLDEN],
        "verify": ["verify", CONFIG, GOLDEN],
        "export-sdpa": ["export-sdpa", CONFIG, "-o", str(tmp_path / "p.dat-s")],
        "kalman": ["kalman", CONFIG, "-o", str(tmp_path / "k.yaml")],
        "compare": ["compare", CONFIG, GOLDEN, "--points", "10"],
        "codegen": ["codegen", GOLDEN, "--prefix", "nav", "-o", str(tmp_path / "c")],
        "sweep": ["sweep", CONFIG, "--param", "delta_bar=0:1:1"],
    }
    for name, args in cases.items():
        quiet = synth(*args)
        loud = synth(*args, "-v")
        assert loud.returncode == 0 and quiet.returncode == 0, (name, loud.stderr)
        lines = [l for l in loud.stderr.splitlines() if l.startswith("hinf-synth: " + name + ": ")]
        assert lines and all(re.search(r"\(\d[\d.e+-]* s\)$", l) for l in lines), (name, loud.stderr)
        assert not [l for l in quiet.stderr.splitlines() if l.startswith("hinf-synth: " + name + ": ")], name
        assert timing_apart(loud.stdout) == timing_apart(quiet.stdout), name
    assert "delta_bar = 1: gamma = " in synth(*cases["sweep"], "-v").stderr


def test_each_further_campaign_is_labelled(tmp_path):
    """gps-ins-flyaround runs table 1's campaigns after the scenario's own: each is announced
    before its progress lines (issue 38 #2: three unlabelled bars); -q prints none of it."""
    sim = os.environ.get("HINF_SIM", os.path.join(ROOT, "build", "bin", "hinf-sim"))
    scenario = os.path.join(ROOT, "configs", "scenarios", "gps-ins-flyaround.yaml")
    run = subprocess.run([sim, scenario, "-o", str(tmp_path / "a"), "--runs", "2", "--duration", "30", "--no-plots"],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    lines = run.stderr.splitlines()
    labels = [l for l in lines if "campaign" in l]
    assert labels == ["hinf-sim: campaign 2 of 3: table 1 at inertia_products_fraction = 0.1",
                      "hinf-sim: campaign 3 of 3: table 1 at inertia_products_fraction = 0.3"], run.stderr
    assert lines.index(labels[0]) > 0 and "of the runs" in lines[lines.index(labels[0]) + 1]
    quiet = subprocess.run([sim, scenario, "-o", str(tmp_path / "b"), "--runs", "2", "--duration", "30", "--no-plots",
                            "-q"], capture_output=True, text=True)
    assert quiet.returncode == 0 and quiet.stderr == "", quiet.stderr

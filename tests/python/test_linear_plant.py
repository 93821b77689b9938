"""hinf-sim's linear_plant family (docs/experiments.md "The user's own plant"): the shipped
scenario end to end; each filter's measured error RMS beside its predicted one; a gains file
written by one run flown by the next gives the same estimates bit for bit; refusals exit 2.
Needs only the executable."""
import csv
import json
import os
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SIM = os.environ.get("HINF_SIM", os.path.join(ROOT, "build", "bin", "hinf-sim"))
SCENARIO = os.path.join(ROOT, "configs", "scenarios", "linear-plant-two-mass.yaml")


def sim(*args):
    return subprocess.run([SIM, *args], capture_output=True, text=True)


def test_shipped_scenario_measures_what_it_predicts(tmp_path):
    out = tmp_path / "run"
    run = sim(SCENARIO, "-o", str(out), "--runs", "8", "--jobs", "2", "--no-plots", "-q")
    assert run.returncode == 0, run.stderr
    assert sorted(os.listdir(out)) == ["hinf_gains.yaml", "kalman_gains.yaml", "manifest.txt", "runs.csv",
                                       "summary.json", "trajectory.csv"]
    summary = json.loads((out / "summary.json").read_text())
    assert summary["scenario_family"] == "linear_plant" and summary["uncertainty_delta"] == 1
    for name, f in summary["filters"].items():
        # 8 runs of 9 000 window samples: the mean RMS within 5 % of (229)
        assert abs(f["error_rms"]["mean"] / f["predicted_error_rms"]["mean"] - 1) < 0.05, name
        assert f["predicted_error_rms"]["min"] == f["predicted_error_rms"]["max"] and f["delta_1"]["min"] == f["delta_1"]["max"] == 1
        assert f["diverged_runs"] == 0
        assert f["gamma"] > 0
    with open(out / "runs.csv") as fh:
        rows = list(csv.DictReader(fh))
    assert len(rows) == 16 and {r["filter"] for r in rows} == {"hinf", "kalman"}
    assert list(rows[0])[:6] == ["run", "seed", "filter", "delta_1", "error_rms", "predicted_error_rms"]


def test_plots_of_one_run_and_of_a_campaign(tmp_path):
    # run 0's components (error.png) and the Monte-Carlo figure of |z - zhat| (error_norms.png),
    # with one run (raw norms under the moving RMS) and with several (median and band); the
    # same statistics as without plots
    for runs in ("1", "3"):
        out, bare = tmp_path / ("plots" + runs), tmp_path / ("bare" + runs)
        run = sim(SCENARIO, "-o", str(out), "--runs", runs, "--duration", "30", "-q")
        assert run.returncode == 0, run.stderr
        for png in ("error.png", "error_norms.png"):
            assert (out / png).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n", png
        assert not [f for f in os.listdir(out) if f.endswith((".dat", ".gp"))]
        assert sim(SCENARIO, "-o", str(bare), "--runs", runs, "--duration", "30", "-q", "--no-plots").returncode == 0
        assert (out / "runs.csv").read_text() == (bare / "runs.csv").read_text()


def test_a_written_gains_file_flies_the_same_filter(tmp_path):
    first = tmp_path / "first"
    assert sim(SCENARIO, "-o", str(first), "--duration", "20", "--no-plots", "-q").returncode == 0
    scenario = tmp_path / "again.yaml"
    scenario.write_text(f"scenario: linear_plant\nconfig: {ROOT}/configs/example-parameters.yaml\nduration: 20\n"
                        f"truth: {{uncertainty_delta: 1}}\nfilters:\n  hinf: {{}}\n"
                        f"  from_file: {{type: hinf, gains: {first}/hinf_gains.yaml}}\nplots: false\n")
    second = tmp_path / "second"
    run = sim(str(scenario), "-o", str(second), "-q")
    assert run.returncode == 0, run.stderr
    with open(second / "trajectory.csv") as fh:
        rows = list(csv.DictReader(fh))
    assert len(rows) == 401
    for row in rows:
        for i in (1, 2):
            assert row[f"hinf_err{i}"] == row[f"from_file_err{i}"]
    summary = json.loads((second / "summary.json").read_text())
    assert summary["filters"]["from_file"]["origin"] == f"gains file {first}/hinf_gains.yaml"
    assert summary["filters"]["from_file"]["gamma"] == summary["filters"]["hinf"]["gamma"]


def test_parameters_drawn_per_run(tmp_path):
    """uncertainty_delta: random: each run its own k in the range, the prediction for that k."""
    scenario = tmp_path / "random.yaml"
    scenario.write_text(f"scenario: linear_plant\nconfig: {ROOT}/configs/example-parameters.yaml\nduration: 2000\n"
                        f"truth: {{uncertainty_delta: random}}\nmetrics: {{steady_state_start: 20}}\n"
                        f"filters: {{kalman: {{}}}}\nplots: false\n")
    out = tmp_path / "out"
    run = sim(str(scenario), "-o", str(out), "--runs", "6", "-q")
    assert run.returncode == 0, run.stderr
    with open(out / "runs.csv") as fh:
        rows = list(csv.DictReader(fh))
    deltas = [float(r["delta_1"]) for r in rows]
    assert len(set(deltas)) == 6 and all(-1 <= d <= 1 for d in deltas)
    # 39 600 window samples a run, the error correlated over ~200 (the plant's damping time,
    # 10 s): each run's RMS is within ~5 % of its own prediction; their mean within 10 %
    ratios = [float(r["error_rms"]) / float(r["predicted_error_rms"]) for r in rows]
    assert abs(sum(ratios) / len(ratios) - 1) < 0.1, ratios
    assert json.loads((out / "summary.json").read_text())["uncertainty_delta"] == "random"


def test_refusals_exit_2_naming_the_key(tmp_path):
    scenario = tmp_path / "bad.yaml"
    for body, expected in [("duration: 20\nfilters: {hinf: {}}\nnoise: {process: 1}\n", "process"),
                           ("duration: 20\nfilters: {ekf: {}}\n", "needs type: hinf or kalman"),
                           ("filters: {hinf: {}}\n", "missing key 'duration'")]:
        scenario.write_text(f"scenario: linear_plant\nconfig: {ROOT}/configs/example-parameters.yaml\n" + body)
        run = sim(str(scenario), "-o", str(tmp_path / "out"), "-q")
        assert run.returncode == 2 and expected in run.stderr, run.stderr
        assert not (tmp_path / "out").exists()


def test_truth_parameters_in_their_units(tmp_path):
    """truth: {parameters: {k: random}}: each run's k drawn on the config's range, runs.csv and
    summary.json name it (issue 38 #4: parameters drawn per run from their ranges)."""
    scenario = tmp_path / "s.yaml"
    scenario.write_text("scenario: linear_plant\nconfig: " + os.path.join(ROOT, "configs", "example-parameters.yaml") +
                        "\nduration: 20\nfilters: {kalman: {}}\ntruth: {parameters: {k: random}}\n")
    out = tmp_path / "run"
    run = sim(str(scenario), "-o", str(out), "--runs", "6", "--no-plots", "-q")
    assert run.returncode == 0, run.stderr
    summary = json.loads((out / "summary.json").read_text())
    assert summary["truth_parameters"] == {"k": "random"} and "uncertainty_delta" not in summary
    with open(out / "runs.csv") as fh:
        rows = list(csv.DictReader(fh))
    assert list(rows[0])[:4] == ["run", "seed", "filter", "k"]
    ks = [float(r["k"]) for r in rows]
    assert all(0.95 <= k <= 1.05 for k in ks) and len(set(ks)) == 6

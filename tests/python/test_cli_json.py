"""`hinf-synth COMMAND --json` (docs/file-formats.md "JSON"): every number read back bit for bit
against the files the same commands write, read by an independent YAML parser (PyYAML), and
against the text and CSV outputs. Needs only the executable (HINF_SYNTH)."""
import csv
import io
import json
import math
import os
import subprocess

import pytest
import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SYNTH = os.environ.get("HINF_SYNTH", os.path.join(ROOT, "build", "bin", "hinf-synth"))


def path(*parts):
    return os.path.join(ROOT, *parts)


def synth_json(*args):
    run = subprocess.run([SYNTH, *args, "--json"], capture_output=True, text=True)
    lines = run.stdout.splitlines()
    assert len(lines) == 1, run.stdout + run.stderr  # one line of JSON, nothing else on stdout
    return run.returncode, json.loads(lines[0])


def same(from_json, from_yaml, where="file"):
    """The JSON's value is the YAML's, numbers bit for bit (== on floats), non-finite numbers
    null; PyYAML (YAML 1.1) reads a float without a dot, such as 1e+20, as a string."""
    if isinstance(from_yaml, dict):
        assert isinstance(from_json, dict) and list(from_json) == list(from_yaml), where
        for k in from_yaml:
            same(from_json[k], from_yaml[k], where + "." + k)
    elif isinstance(from_yaml, list):
        assert isinstance(from_json, list) and len(from_json) == len(from_yaml), where
        for i, (a, b) in enumerate(zip(from_json, from_yaml)):
            same(a, b, "%s[%d]" % (where, i))
    elif isinstance(from_yaml, float) and not math.isfinite(from_yaml):
        assert from_json is None, where
    elif isinstance(from_yaml, str) and isinstance(from_json, (int, float)) and not isinstance(from_json, bool):
        assert float(from_yaml) == from_json, where
    else:
        assert from_json == from_yaml and type(from_json) is type(from_yaml), where


@pytest.mark.parametrize("command, config", [("solve", "configs/paper-dbar0.05.yaml"),
                                             ("solve", "configs/paper-no-control-filtered.yaml"),
                                             ("solve", "tests/data/controllers/double-integrator.yaml"),
                                             ("kalman", "configs/example-matrices.yaml")])
def test_the_json_holds_the_written_file_bit_for_bit(command, config, tmp_path):
    out = tmp_path / "out.yaml"
    code, j = synth_json(command, path(config), "-o", str(out))
    assert code == 0
    data = yaml.safe_load(out.read_text())
    assert j["schema"] == "hinf-synth.%s/1" % command
    assert j["kind"] == ("controller" if "controller" in data else "filter")
    assert j["config"] == path(config)
    assert j["output"] == str(out)
    assert j["gamma"] == data["gamma"]
    same(j["file"], data)


def test_verify_check_and_analyze_give_the_files_numbers(tmp_path):
    config, golden = path("configs", "paper-dbar0.05.yaml"), path("tests", "golden", "paper-dbar0.05.yaml")
    data = yaml.safe_load(open(golden).read())
    code, v = synth_json("verify", config, golden)
    assert code == 0 and v["schema"] == "hinf-synth.verify/1" and v["holds"] is True
    assert v["claimed_gamma"] == data["gamma"] and v["achieved_bound"] is None
    # checks 2-4 re-derived: the certificate section's keys but check 1's and the conditioning
    assert not [k for k in v["certificate"] if k.startswith(("lmi_", "cond_"))] and v["certificate"]["passed"] is True
    assert v["certificate"]["hinf_norm_nominal"] == pytest.approx(data["certificate"]["hinf_norm_nominal"], rel=1e-9)
    code, c = synth_json("check", config, "--golden", golden)
    assert code == 0 and c["schema"] == "hinf-synth.check/1" and c["same"] is True
    assert c["gamma_golden"] == data["gamma"] and c["config_sha256"] == data["config_sha256"]
    code, a = synth_json("analyze", config, golden)
    assert code == 0 and a["schema"] == "hinf-synth.analyze/1" and a["claimed_gamma"] == data["gamma"]
    # full precision: the text prints ten digits of the same number
    text = subprocess.run([SYNTH, "analyze", config, golden], capture_output=True, text=True).stdout
    assert ("%.10g" % a["hinf_norm_nominal"]) in text
    assert a["hinf_norm_nominal"] != float("%.10g" % a["hinf_norm_nominal"])


def test_a_failed_verification_is_exit_one_with_holds_false(tmp_path):
    golden = yaml.safe_load(open(path("tests", "golden", "paper-dbar0.05.yaml")).read())
    golden["gamma"] = 0.9 * golden["gamma"]  # below the filter's nominal norm
    lowered = tmp_path / "lowered.yaml"
    lowered.write_text(yaml.safe_dump(golden))
    code, v = synth_json("verify", path("configs", "paper-dbar0.05.yaml"), str(lowered))
    assert code == 1 and v["holds"] is False and v["claimed_gamma"] == golden["gamma"]
    assert v["achieved_bound"] > v["claimed_gamma"]


def test_controller_verify_and_check(tmp_path):
    config, golden = path("configs", "tumbling-hold.yaml"), path("tests", "golden", "tumbling-hold.yaml")
    data = yaml.safe_load(open(golden).read())
    code, v = synth_json("verify", config, golden)
    assert code == 0 and v["kind"] == "controller" and v["holds"] is True and v["claimed_gamma"] == data["gamma"]
    assert v["certificate"]["closed_loop_stable"] is True and "cond_N" not in v["certificate"]
    code, c = synth_json("check", config, "--golden", golden)
    assert code == 0 and c["kind"] == "controller" and c["same"] is True


def test_export_codegen_and_compare_describe_what_they_wrote(tmp_path):
    config, golden = path("configs", "paper-dbar0.05.yaml"), path("tests", "golden", "paper-dbar0.05.yaml")
    out = tmp_path / "lmi.dat-s"
    code, e = synth_json("export-sdpa", config, "-o", str(out))
    assert code == 0 and e["schema"] == "hinf-synth.export-sdpa/1" and e["bytes"] == out.stat().st_size
    code, g = synth_json("codegen", golden, "--prefix", "nav", "-o", str(tmp_path / "gen"))
    assert code == 0 and g["schema"] == "hinf-synth.codegen/1"
    assert sorted(os.path.basename(f["path"]) for f in g["files"]) == sorted(os.listdir(tmp_path / "gen"))
    for f in g["files"]:
        assert os.path.getsize(f["path"]) == f["bytes"]
    sigma = tmp_path / "sigma.csv"
    code, c = synth_json("compare", config, golden, "--points", "50", "-o", str(sigma))
    assert code == 0 and c["schema"] == "hinf-synth.compare/1"
    rows = list(csv.DictReader(io.StringIO(sigma.read_text())))
    assert len(rows) == len(c["theta_rad_per_sample"]) == len(c["filter"]["sigma"]) == len(c["kalman"]["sigma"])
    for row, theta, s in zip(rows, c["theta_rad_per_sample"], c["filter"]["sigma"]):  # the CSV's ten digits
        assert float(row["theta_rad_per_sample"]) == pytest.approx(theta, rel=1e-9)
        assert float(row["sigma_filter"]) == pytest.approx(s, rel=1e-9)


def test_sweep_json_carries_its_schema(tmp_path):
    out = tmp_path / "s.json"
    run = subprocess.run([SYNTH, "sweep", path("configs", "paper-dbar0.05.yaml"), "--param", "delta_bar=0.05:0.05:0.1",
                          "--json", str(out)], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert json.loads(out.read_text())["schema"] == "hinf-synth.sweep/1"


def test_hinf_sim_json_is_the_run_directorys_summary(tmp_path):
    sim = os.environ.get("HINF_SIM", os.path.join(ROOT, "build", "bin", "hinf-sim"))
    out = tmp_path / "run"
    run = subprocess.run([sim, path("configs", "scenarios", "paper-no-control.yaml"), "-o", str(out), "--runs", "2",
                          "--seed", "7", "--no-plots", "--quiet", "--duration", "300", "--json"],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    lines = run.stdout.splitlines()
    assert len(lines) == 1
    j = json.loads(lines[0])
    assert j["schema"] == "hinf-sim.run/1" and j["out"] == str(out) and j["plots"] is False
    assert sorted(j["files"] + ["manifest.txt"]) == sorted(os.listdir(out))
    assert j["replaced_previous_run"] is False and j["removed_previous_files"] == []
    assert j["summary"] == json.loads((out / "summary.json").read_text())  # numbers bit for bit

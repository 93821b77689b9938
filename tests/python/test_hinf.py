"""The Python module against the executables (docs/python.md): the same files byte for byte
(timing apart), the same matrices, the same errors with the same exit codes and messages.
Run by CTest with PYTHONPATH=<build>/python, HINF_SYNTH and HINF_SIM the executables."""
import json
import os
import re
import signal
import subprocess
import sys
import time

import numpy as np
import pytest
import yaml

import hinf

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SYNTH = os.environ.get("HINF_SYNTH", os.path.join(ROOT, "build", "bin", "hinf-synth"))
SIM = os.environ.get("HINF_SIM", os.path.join(ROOT, "build", "bin", "hinf-sim"))
TIMING = re.compile(r"solve_time_s|wall_s|elapsed|_seconds")


def timing_apart(text):
    return "\n".join(line for line in text.splitlines() if not TIMING.search(line))


def path(*parts):
    return os.path.join(ROOT, *parts)


def solve_cli(config, out):
    run = subprocess.run([SYNTH, "solve", config, "-o", str(out)], capture_output=True, text=True)
    return run


@pytest.mark.parametrize("config", ["configs/paper-dbar0.05.yaml", "configs/paper-no-control-filtered.yaml",
                                    "tests/data/controllers/double-integrator.yaml"])
def test_synthesize_writes_the_executables_file(config, tmp_path):
    r = hinf.synthesize(path(config))
    run = solve_cli(path(config), tmp_path / "out.yaml")
    assert run.returncode == 0, run.stderr
    on_disk = (tmp_path / "out.yaml").read_text()
    assert timing_apart(r.text) == timing_apart(on_disk)
    data = yaml.safe_load(on_disk)
    assert r.gamma == data["gamma"]
    section = data["filter"] if r.kind == "filter" else data["controller"]
    for name, value in r.matrices.items():  # numpy arrays, every bit the file's
        assert isinstance(value, np.ndarray)
        np.testing.assert_array_equal(value, np.array(section[name], dtype=float))
    assert r.certificate["passed"] is True
    assert r.iterations and all(it["t"] > 0 for it in r.iterations)
    written = tmp_path / "again.yaml"
    r.write(written)
    assert written.read_text() == r.text


def test_a_dict_of_arrays_is_the_same_problem_as_its_yaml():
    cfg = yaml.safe_load(open(path("configs", "example-matrices.yaml")).read())
    as_arrays = {k: ({kk: np.array(vv) if isinstance(vv, list) else vv for kk, vv in v.items()} if isinstance(v, dict) else v)
                 for k, v in cfg.items()}
    assert hinf.synthesize(as_arrays).gamma == hinf.synthesize(path("configs", "example-matrices.yaml")).gamma


@pytest.mark.parametrize("config, code", [("tests/data/bad-configs/duplicate-key.yaml", 2),
                                          ("tests/data/ill-posed/unstable-plant.yaml", 3),
                                          ("tests/data/controllers/bad-unstabilisable.yaml", 3)])
def test_errors_carry_the_executables_exit_code_and_message(config, code, tmp_path):
    run = solve_cli(path(config), tmp_path / "out.yaml")
    assert run.returncode == code
    with pytest.raises(hinf.Error) as err:
        hinf.synthesize(path(config))
    assert err.value.exit_code == code
    assert type(err.value) is {2: hinf.InvalidInput, 3: hinf.Infeasible}[code]
    assert str(err.value) in run.stderr


def test_yaml_text_that_is_no_config_is_invalid_input():
    with pytest.raises(hinf.InvalidInput):
        hinf.synthesize("just: text\nnothing: here\n")


def test_analyze_verify_check_export(tmp_path):
    config = path("configs", "paper-dbar0.05.yaml")
    golden = path("tests", "golden", "paper-dbar0.05.yaml")
    figures = hinf.analyze(config, golden)
    cli = subprocess.run([SYNTH, "analyze", config, golden, "--json"], capture_output=True, text=True)
    assert cli.returncode == 0
    assert figures == yaml.safe_load(cli.stdout.strip().splitlines()[-1])
    holds, report = hinf.verify(config, golden)
    assert holds and "holds" in report
    same, gamma_now, _ = hinf.check(config, golden)
    assert same and abs(gamma_now - yaml.safe_load(open(golden))["gamma"]) <= 1e-6 * gamma_now
    out = tmp_path / "lmi.dat-s"
    assert subprocess.run([SYNTH, "export-sdpa", config, "-o", str(out)]).returncode == 0
    assert hinf.export_sdpa(config) == out.read_text()


def test_simulate_gives_the_executables_run_directory(tmp_path):
    scenario = path("configs", "scenarios", "paper-no-control.yaml")
    c = hinf.simulate(scenario, runs=2, seed=7, duration=300)
    out = tmp_path / "run"
    cli = subprocess.run([SIM, scenario, "-o", str(out), "--runs", "2", "--seed", "7", "--no-plots", "--quiet",
                          "--duration", "300"], capture_output=True, text=True)
    assert cli.returncode == 0, cli.stderr
    listing = sorted(p.name for p in out.iterdir())
    on_disk = [name for name in listing if name != "manifest.txt" and not name.endswith(".png")]
    assert sorted(c.files) == on_disk
    # the manifest lists what the run wrote (a later run into the directory removes the rest)
    assert sorted((out / "manifest.txt").read_text().splitlines()[1:]) == on_disk
    for name, data in c.files.items():
        assert timing_apart(data.decode()) == timing_apart((out / name).read_text()), name
    runs = c.table("runs.csv")
    assert len(runs) == 2
    assert c.summary
    # asked to, it writes the same run directory
    hinf.simulate(scenario, runs=2, seed=7, duration=300, out=tmp_path / "py")
    assert sorted(p.name for p in (tmp_path / "py").iterdir()) == listing
    for name in on_disk:
        assert timing_apart((tmp_path / "py" / name).read_text()) == timing_apart((out / name).read_text()), name


def numpy_filter(m, Y, U=None):
    """docs/maths.md (5)-(6) written out here: z(k) = C_F x(k) + D_F y(k), x(k+1) = A_F x + B_F y + G_F u."""
    x = np.zeros(m["A_F"].shape[0])
    D = m.get("D_F", np.zeros((m["C_F"].shape[0], m["B_F"].shape[1])))
    Z = []
    for k, y in enumerate(Y):
        Z.append(m["C_F"] @ x + D @ y)
        x = m["A_F"] @ x + m["B_F"] @ y + (m["G_F"] @ U[k] if U is not None else 0)
    return np.array(Z)


@pytest.mark.parametrize("config", ["configs/paper-dbar0.05.yaml", "configs/paper-no-control-filtered.yaml",
                                    "tests/data/plants/triple-integrator-known-input-filtered.yaml"])
def test_the_runtime_filter_steps_as_the_equations(config, tmp_path):
    r = hinf.synthesize(path(config))
    f = hinf.lti_filter(r)
    rng = np.random.default_rng(3)
    Y = rng.standard_normal((200, f.m))
    U = rng.standard_normal((200, f.r)) if f.r > 0 else None
    Z = f.run(Y, U)
    assert Z.shape == (200, f.l)
    reference = numpy_filter(r.matrices, Y, U)
    assert np.max(np.abs(Z - reference)) <= 1e-12 * max(1.0, np.max(np.abs(reference)))
    # step by step from a file gives the same, bit for bit
    r.write(tmp_path / "gains.yaml")
    g = hinf.lti_filter(tmp_path / "gains.yaml")
    for k in range(20):
        z = g.step(Y[k], U[k]) if U is not None else g.step(Y[k])
        np.testing.assert_array_equal(z, Z[k])
    with pytest.raises(ValueError):
        g.step(np.zeros(f.m + 1), *([U[0]] if U is not None else []))


def test_a_controller_is_no_filter():
    with pytest.raises(hinf.InvalidInput):
        hinf.lti_filter(hinf.synthesize(path("tests", "data", "controllers", "double-integrator.yaml")))


def test_kalman_writes_the_executables_file(tmp_path):
    config = path("configs", "paper-dbar0.05.yaml")
    r = hinf.kalman(config)
    run = subprocess.run([SYNTH, "kalman", config, "-o", str(tmp_path / "k.yaml")], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert timing_apart(r.text) == timing_apart((tmp_path / "k.yaml").read_text())
    assert r.certificate["passed"] is True and r.solver["method"].startswith("Kalman")
    controller = path("tests", "data", "controllers", "double-integrator.yaml")
    run = subprocess.run([SYNTH, "kalman", controller, "-o", str(tmp_path / "c.yaml")], capture_output=True, text=True)
    assert run.returncode == 2
    with pytest.raises(hinf.InvalidInput) as err:
        hinf.kalman(controller)
    assert str(err.value) in run.stderr


@pytest.mark.parametrize("gains, options", [("tests/golden/paper-dbar0.05.yaml", []),
                                            ("tests/golden/tumbling-hold.yaml", ["--tustin", "0.1", "--real", "float",
                                                                                 "--config", "configs/tumbling-hold.yaml"])])
def test_codegen_gives_the_executables_files(gains, options, tmp_path):
    run = subprocess.run([SYNTH, "codegen", path(gains), "--prefix", "nav", "-o", str(tmp_path / "cli")] +
                         [path(o) if o.endswith(".yaml") else o for o in options], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    kwargs = {"tustin": 0.1, "real": "float", "config": path("configs/tumbling-hold.yaml")} if options else {}
    files = hinf.codegen(path(gains), "nav", out=tmp_path / "py", **kwargs)
    assert sorted(files) == sorted(p.name for p in (tmp_path / "cli").iterdir())
    for name, text in files.items():
        assert text == (tmp_path / "cli" / name).read_text(), name
        assert (tmp_path / "py" / name).read_text() == text, name
    with pytest.raises(hinf.InvalidInput):
        hinf.codegen(path(gains), "int")  # a C keyword


@pytest.mark.parametrize("call", [lambda p: hinf.synthesize(p), lambda p: hinf.simulate(p),
                                  lambda p: hinf.codegen(p, "nav"), lambda p: hinf.lti_filter(p)])
def test_a_missing_file_is_invalid_input_naming_it(call, tmp_path):
    missing = str(tmp_path / "no-such-file.yaml")
    with pytest.raises(hinf.InvalidInput) as err:
        call(missing)
    assert err.value.exit_code == 2 and "no-such-file.yaml" in str(err.value)


def test_sweep_gives_the_executables_points(tmp_path):
    config = path("configs", "paper-dbar0.05.yaml")
    s = hinf.sweep(config, "delta_bar", [0.05, 0.1])
    run = subprocess.run([SYNTH, "sweep", config, "--param", "delta_bar=0.05:0.05:0.1", "--json",
                          str(tmp_path / "s.json")], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    cli = json.load(open(tmp_path / "s.json"))["points"]
    assert [{k: v for k, v in p.items() if k != "time_s"} for p in s["points"]] == \
           [{k: v for k, v in p.items() if k != "time_s"} for p in cli]
    np.testing.assert_array_equal(s["value"], [0.05, 0.1])
    np.testing.assert_array_equal(s["gamma"], [p["gamma"] for p in cli])
    np.testing.assert_array_equal(s["exit_code"], [0, 0])


def test_max_feasible_gives_the_executables_bracket(tmp_path):
    config = path("configs", "paper-dbar0.05.yaml")
    m = hinf.max_feasible(config, "delta_bar", 0.05, 0.1, tolerance=0.02)
    run = subprocess.run([SYNTH, "sweep", config, "--max-feasible", "delta_bar=0.05:0.1", "--tolerance", "0.02",
                          "--json", str(tmp_path / "m.json")], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    cli = json.load(open(tmp_path / "m.json"))
    strip = lambda p: None if p is None else {k: v for k, v in p.items() if k != "time_s"}
    for key in ("largest_certified", "smallest_not_certified", "smallest_infeasible"):
        assert strip(m[key]) == strip(cli[key])
    assert m["bracket_width"] == cli["bracket_width"]
    assert [strip(p) for p in m["evaluated"]] == [strip(p) for p in cli["evaluated"]]


def test_compare_gives_the_executables_curves(tmp_path):
    config = path("configs", "paper-dbar0.05.yaml")
    gains = tmp_path / "g.yaml"
    assert solve_cli(config, gains).returncode == 0
    c = hinf.compare(config, gains, points=50)
    run = subprocess.run([SYNTH, "compare", config, str(gains), "--points", "50", "-o", str(tmp_path / "s.csv")],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    table = np.genfromtxt(tmp_path / "s.csv", delimiter=",", names=True)
    # the CSV holds 10 significant digits (hinf-synth's number format)
    np.testing.assert_allclose(c["theta"], table["theta_rad_per_sample"], rtol=1e-9)
    np.testing.assert_allclose(c["frequency_hz"], table["frequency_hz"], rtol=1e-9)
    np.testing.assert_allclose(c["filter"]["sigma"], table["sigma_filter"], rtol=1e-9)
    np.testing.assert_allclose(c["kalman"]["sigma"], table["sigma_kalman"], rtol=1e-9)
    # the filter's worst-case gain is the largest of its sigma curve (both peaks are on the grid)
    assert c["filter"]["hinf_norm_nominal"] == pytest.approx(c["filter"]["sigma"].max(), rel=1e-9)
    assert c["filter"]["robust_bound"] is not None and c["filter"]["robust_bound"] >= c["filter"]["hinf_norm_nominal"]
    assert f"{c['filter']['hinf_norm_nominal']:.10g}" in run.stdout


@pytest.mark.parametrize("call, key", [
    (lambda: hinf.sweep(path("configs", "paper-dbar0.05.yaml"), "delta_barr", [0.1]), "delta_barr"),
    (lambda: hinf.compare(path("configs", "paper-dbar0.05.yaml"), path("configs", "paper-published-gains.yaml"),
                          points=1), "points"),
])
def test_sweep_and_compare_refuse_bad_input_naming_it(call, key):
    with pytest.raises(hinf.InvalidInput) as e:
        call()
    assert key in str(e.value)


def interrupted_inside(call, argument):
    """Runs `call` (Python text calling hinf with sys.argv[1] = argument) in a child, sends it
    SIGINT 0.5 s after it has started, and returns what it printed: "interrupted in FILE" with
    the KeyboardInterrupt's last frame, or "returned"."""
    script = ("import signal, sys, traceback, hinf\n"
              "signal.signal(signal.SIGINT, signal.default_int_handler)  # even if started with SIGINT ignored\n"
              "print('started', flush=True)\n"
              "try:\n"
              "    " + call + "\n"
              "    print('returned')\n"
              "except KeyboardInterrupt:\n"
              "    print('interrupted in', traceback.extract_tb(sys.exc_info()[2])[-1].filename)\n")
    child = subprocess.Popen([sys.executable, "-c", script, argument], stdout=subprocess.PIPE, text=True)
    assert child.stdout.readline().strip() == "started"
    time.sleep(0.5)
    child.send_signal(signal.SIGINT)
    return child.communicate(timeout=600)[0]


def raised_from_inside_the_call(out):
    return out.startswith("interrupted in") and out.strip().endswith(os.path.join("hinf", "__init__.py"))


def test_ctrl_c_interrupts_a_solve_from_inside_the_call():
    """SIGINT during hinf.synthesize raises KeyboardInterrupt out of the call itself (the
    solver polls Python's signal handlers), not after the solve has run to its end."""
    out = interrupted_inside("hinf.synthesize(sys.argv[1])",  # a solve of about 10 s on this machine
                             path("tests", "data", "random-n16-seed1.yaml"))
    assert raised_from_inside_the_call(out), out


def test_ctrl_c_interrupts_a_campaign_between_its_runs():
    """SIGINT during hinf.simulate: no further Monte-Carlo run starts and KeyboardInterrupt is
    raised out of the call once the run under way has ended."""
    out = interrupted_inside("hinf.simulate(sys.argv[1], runs=50, seed=1, jobs=1)",  # 50 runs of a few seconds each
                             path("configs", "scenarios", "paper-control.yaml"))
    assert raised_from_inside_the_call(out), out


def test_the_runtime_ekf_on_a_linear_model_is_the_kalman_recursion():
    """hinf.ekf: the flight code's predict/update against the Kalman recursion written here in
    numpy (P = F P F' + Q; K = P H' S^-1; Joseph form), 50 steps of a random 4-state plant."""
    rng = np.random.default_rng(7)
    n, r, m = 4, 2, 3
    F = rng.normal(size=(n, n))
    F *= 0.95 / np.max(np.abs(np.linalg.eigvals(F)))
    G, H = rng.normal(size=(n, r)), rng.normal(size=(m, n))
    Q, R = 0.01 * np.eye(n), 0.1 * np.eye(m)
    f = hinf.ekf(F, G, H, Q, R, x0=np.ones(n), P0=2 * np.eye(n))
    x, P = np.ones(n), 2 * np.eye(n)
    for k in range(50):
        u, y = rng.normal(size=r), rng.normal(size=m)
        assert f.predict(u) == "ok"
        x, P = F @ x + G @ u, F @ P @ F.T + Q
        assert f.update(y) == "ok"
        S = H @ P @ H.T + R
        K = np.linalg.solve(S, H @ P).T
        x = x + K @ (y - H @ x)
        IKH = np.eye(n) - K @ H
        P = IKH @ P @ IKH.T + K @ R @ K.T
        np.testing.assert_allclose(f.x, x, rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(f.P, P, rtol=1e-12, atol=1e-12)
    with pytest.raises(hinf.InvalidInput, match="H must be"):
        hinf.ekf(F, G, np.ones((m, n + 1)), Q, R)
    with pytest.raises(hinf.InvalidInput, match="R is not positive definite"):
        hinf.ekf(F, G, H, Q, -R)
    with pytest.raises(hinf.InvalidInput, match="y must have 3 entries"):
        f.update(np.ones(2))


def test_codegen_discretises_a_continuous_controller_only_with_its_sampled_loop_certified(tmp_path):
    config = path("tests/data/controllers/double-integrator.yaml")
    k = tmp_path / "k.yaml"
    hinf.synthesize(config).write(k)
    with pytest.raises(hinf.InvalidInput) as err:
        hinf.codegen(k, "hold", tustin=0.1)  # the sampled loop is certified on the config's plant
    assert err.value.key == "config"
    files = hinf.codegen(k, "hold", tustin=0.1, config=config)
    assert "of the sampled loop" in files["hold.h"]
    holds, report = hinf.verify(config, _written(tmp_path / "kd.yaml", files["hold_controller.yaml"]))
    assert holds, report
    with pytest.raises(hinf.CheckFailed) as err:
        hinf.codegen(k, "hold", zoh=2.0, config=config, out=tmp_path / "slow")
    assert "NOT certified: the sampled loop is unstable" in str(err.value)
    assert not (tmp_path / "slow").exists()


def _written(p, text):
    p.write_text(text)
    return p

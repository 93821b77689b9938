"""hinf: certified H-infinity filters and controllers, and their Monte-Carlo experiments,
from Python (docs/python.md).

The same library calls as the executables `hinf-synth` and `hinf-sim`, with results in
memory: numpy arrays for the matrices, dicts for the certificate, the bracket and the
campaign's summary. Nothing is written unless asked (`SynthesisResult.write`). A failure
raises a subclass of `hinf.Error` whose `exit_code` is the executables' for the same
failure (1 a check failed, 2 invalid input, 3 infeasible or ill-posed, 4 numerical
failure) and whose message is theirs.

    import hinf
    r = hinf.synthesize("configs/paper-dbar0.05.yaml")
    r.gamma, r.A_F, r.certificate["passed"]
"""
import csv
import io
import json
import os
import tempfile

import numpy as np
import yaml

from . import _hinf

__all__ = ["synthesize", "kalman", "analyze", "verify", "check", "export_sdpa", "codegen", "sweep", "max_feasible",
           "compare", "simulate", "lti_filter", "ekf", "Ekf",
           "Error", "CheckFailed",
           "InvalidInput", "Infeasible", "NumericalFailure", "SynthesisResult", "Campaign"]


class Error(Exception):
    """A failure of the library: `exit_code` as the executables', `key` the input it names."""

    exit_code = 0

    def __init__(self, message, key=""):
        super().__init__(message)
        self.key = key


class CheckFailed(Error):
    exit_code = 1


class InvalidInput(Error):
    exit_code = 2


class Infeasible(Error):
    exit_code = 3


class NumericalFailure(Error):
    exit_code = 4


_BY_CODE = {c.exit_code: c for c in (CheckFailed, InvalidInput, Infeasible, NumericalFailure)}


def _call(fn, *args, **kwargs):
    try:
        return fn(*args, **kwargs)
    except _hinf.NativeError as e:
        code, message, key = e.args[0] if len(e.args) == 1 else e.args
        raise _BY_CODE.get(code, Error)(message, key) from None


def _plain(value):
    """numpy arrays and scalars as lists and floats, for a config written as JSON (which is YAML)."""
    if isinstance(value, dict):
        return {str(k): _plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if isinstance(value, np.ndarray):
        return _plain(value.tolist())
    if isinstance(value, np.generic):
        return value.item()
    return value


def _config_source(config):
    """(text, name) of a config given as a path (text None: the library reads the file), as
    YAML text, or as a dict (numpy arrays allowed)."""
    if isinstance(config, dict):
        # JSON is YAML; json.dumps writes every float with the digits that read it back exactly
        return json.dumps(_plain(config), allow_nan=False), "<dict>"
    if isinstance(config, os.PathLike) or (isinstance(config, str) and "\n" not in config):
        return None, os.fspath(config)  # a one-line string is a path
    if isinstance(config, str):
        return config, "<text>"
    raise InvalidInput("config: expected a path, YAML text or a dict, got " + type(config).__name__)


def _problem(config):
    """A config given as a path, as YAML text, or as a dict (numpy arrays allowed)."""
    text, name = _config_source(config)
    if text is None:
        return _call(_hinf.load_problem, name)
    return _call(_hinf.parse_problem, text, name)


class SynthesisResult:
    """A certified design: `gamma`, the matrices as attributes (A_F, B_F, C_F[, D_F, G_F] for a
    filter; A_K, B_K, C_K, D_K for a controller), `certificate` and `solver` as dicts (the
    file's sections), `iterations` (one dict per centring), `report` (the executable's text)
    and `text` (the gains or controller file)."""

    def __init__(self, outcome):
        self.kind = outcome["kind"]
        self.gamma = outcome["gamma"]
        self.text = outcome["file"]
        self.report = outcome["report"]
        self.iterations = outcome["iterations"]
        self.matrices = dict(outcome["matrices"])
        self.form = self.matrices.pop("form", None)
        for name, value in self.matrices.items():
            setattr(self, name, value)
        data = yaml.safe_load(self.text)
        self.certificate = data.get("certificate", {})
        self.solver = data.get("solver", {})

    def write(self, path):
        """Writes the file `hinf-synth solve -o PATH` would write, atomically."""
        directory = os.path.dirname(os.path.abspath(path))
        fd, tmp = tempfile.mkstemp(prefix="." + os.path.basename(path) + ".tmp.", dir=directory)
        try:
            with os.fdopen(fd, "w") as f:
                f.write(self.text)
            os.replace(tmp, path)
        except BaseException:
            if os.path.exists(tmp):
                os.unlink(tmp)
            raise

    def __repr__(self):
        return f"<hinf.SynthesisResult {self.kind} gamma={self.gamma!r}>"


def synthesize(config):
    """`hinf-synth solve`: the certified filter or controller of a config (path, YAML text or dict)."""
    problem = _problem(config)
    return SynthesisResult(_call(problem.solve))


def kalman(config):
    """`hinf-synth kalman`: the Kalman predictor (or filter x_hat(k|k)) of a filter config's nominal
    plant, certified at the worst-case gain it achieves, as a SynthesisResult."""
    return SynthesisResult(_call(_problem(config).kalman))


def codegen(gains, prefix, real="double", vector_steps=50, tustin=None, zoh=None, config=None, out=None):
    """`hinf-synth codegen`: the C99 files (NAME.h, NAME.c, NAME_vectors.h, NAME_check.c) of a gains
    or controller file (a path, or a SynthesisResult) as {name: text}; also written into the
    directory `out` when given (atomically, never over an input). With `tustin` or `zoh` (a
    period, s) and `config` (the controller's config): a continuous-time controller file (a path)
    discretised and its sampled loop certified (CheckFailed with the report when it is not);
    NAME_controller.yaml, the discrete controller file, comes with the C files."""
    if isinstance(gains, SynthesisResult):
        text, source = gains.text, "<result>"
    else:
        text, source = None, os.fspath(gains)  # read by the library, as the executable reads it
    return _call(_hinf.codegen, text, source, prefix, real, vector_steps, tustin, zoh,
                 "" if config is None else os.fspath(config), None if out is None else os.fspath(out))


def analyze(config, file, delta_points=41):
    """`hinf-synth analyze --json`: the figures of a gains or controller file on the problem, as a dict."""
    report, text = _call(_problem(config).analyze, os.fspath(file), delta_points)
    return json.loads(text)


def verify(config, file):
    """`hinf-synth verify`: (holds, report) — whether the file's claimed gamma holds for the problem."""
    return _call(_problem(config).verify, os.fspath(file))


def check(config, golden, rtol=1e-6):
    """`hinf-synth check`: (same, gamma_now, report) against a golden file."""
    return _call(_problem(config).check, os.fspath(golden), rtol)


def export_sdpa(config):
    """`hinf-synth export-sdpa`: the synthesis LMI in SDPA sparse format."""
    return _call(_problem(config).export_sdpa)


def _sweep_arrays(points):
    """The points' values, certified gammas (NaN where not certified) and exit codes as arrays."""
    return (np.array([p["value"] for p in points], dtype=float),
            np.array([np.nan if p["gamma"] is None else p["gamma"] for p in points], dtype=float),
            np.array([p["exit_code"] for p in points], dtype=int))


def sweep(config, param, values):
    """`hinf-synth sweep --param`: a full certified synthesis of a filter config at each value of
    one of its numbers (`param`: delta_bar, uncertainty_scale, or a key path such as
    "hill.sample_time"). Returns {"parameter", "points": one dict per value as the executable's
    JSON (value, outcome, exit_code, gamma, gamma_lower, form, time_s, message), "value",
    "gamma" (NaN where not certified), "exit_code"} — a point that fails is recorded, not raised."""
    text, name = _config_source(config)
    points = _call(_hinf.sweep, text, name, param, [float(v) for v in values])
    value, gamma, code = _sweep_arrays(points)
    return {"parameter": param, "points": points, "value": value, "gamma": gamma, "exit_code": code}


def max_feasible(config, param, lo, hi, tolerance=1e-3):
    """`hinf-synth sweep --max-feasible`: the largest value of `param` in [lo, hi] with a certified
    filter, by bisection: {"largest_certified", "smallest_not_certified", "smallest_infeasible"
    (point dicts or None), "bracket_width" (None if hi is certified), "evaluated" (every point)}."""
    text, name = _config_source(config)
    return _call(_hinf.max_feasible, text, name, param, float(lo), float(hi), float(tolerance))


def compare(config, gains, points=400):
    """`hinf-synth compare`: a filter (gains file) beside the Kalman filter of the same plant (config
    file): {"theta" (rad/sample), "frequency_hz" (None without a sample time), "filter" and
    "kalman": {"hinf_norm_nominal", "hinf_peak_theta", "h2_norm_nominal", "robust_bound" (None for
    a certain plant), "sigma" (σ_max of the error system on theta)}}."""
    c = _call(_hinf.compare, os.fspath(config), os.fspath(gains), points)
    T = c.pop("sample_time")
    c["frequency_hz"] = None if T is None else c["theta"] / (2 * np.pi * T)
    return c


class Campaign:
    """A Monte-Carlo campaign's run directory in memory: `files` ({name: bytes}), `summary`
    (summary.json as a dict), and `table(name)` — a CSV file of it as a numpy structured array."""

    def __init__(self, files):
        self.files = files
        self.summary = json.loads(files["summary.json"]) if "summary.json" in files else {}

    def table(self, name):
        text = self.files[name].decode()
        rows = list(csv.reader(io.StringIO(text)))
        names = rows[0]
        columns = list(zip(*rows[1:])) if len(rows) > 1 else [[] for _ in names]
        dtype = []
        for n, col in zip(names, columns):
            try:
                np.asarray(col, dtype=float)
                dtype.append((n, float))
            except ValueError:
                dtype.append((n, object))
        out = np.empty(len(rows) - 1, dtype=dtype)
        for (n, t), col in zip(dtype, columns):
            out[n] = np.asarray(col, dtype=t)
        return out

    def __repr__(self):
        return f"<hinf.Campaign {sorted(self.files)}>"


def simulate(scenario, runs=1, seed=1, jobs=1, duration=None, out=None, plots=False):
    """`hinf-sim SCENARIO --runs N --seed S --jobs J [--duration T]` in memory: nothing is written
    unless `out` names a run directory, which is then written as hinf-sim writes it (all files
    or none, never over a file the run reads; the PNGs too with plots=True)."""
    return Campaign(_call(_hinf.simulate, os.fspath(scenario), runs, seed, jobs, duration,
                          None if out is None else os.fspath(out), plots))


def lti_filter(gains):
    """The runtime's fixed-gain filter (runtime/lti_filter.hpp), loaded as flight code loads it,
    from a gains file's path, a filter's SynthesisResult, or gains YAML text:
    `step(y)` (or `step(y, u)` with a known input) → z_F(k); `run(Y[, U])` → Z over a record
    (rows are samples); `init(z0)`, `set_state(x_F)`, `state`, and the sizes n, m, l, r."""
    if isinstance(gains, SynthesisResult):
        if gains.kind != "filter":
            raise InvalidInput("lti_filter: a controller is not a filter (its file is hinf-controller/1)")
        return _call(_hinf.LtiFilter.from_text, gains.text, "<result>")
    if isinstance(gains, os.PathLike) or (isinstance(gains, str) and "\n" not in gains):
        return _call(_hinf.LtiFilter.from_file, os.fspath(gains))
    return _call(_hinf.LtiFilter.from_text, gains, "<text>")


class Ekf:
    """The runtime's extended Kalman filter (runtime/ekf.hpp, docs/maths.md §12) on the linear
    model x(k+1) = F x(k) + G u(k) + w, y(k) = H x(k) + v, cov(w) = Q, cov(v) = R: the same
    predict/update code as flies (Joseph update, Cholesky solves). `predict(u)` and `update(y)`
    return the step's status ("ok", or why it was skipped: the state is then unchanged); `x`,
    `P`, `K` (the last update's gain), `innovation`, `nis`. Made by `hinf.ekf`."""

    def __init__(self, native, n):
        self._f = native
        self.n = n

    def init(self, x0, P0):
        _call(self._f.init, np.asarray(x0, dtype=float).ravel(), np.atleast_2d(np.asarray(P0, dtype=float)))

    def predict(self, u):
        return _call(self._f.predict, np.asarray(u, dtype=float).ravel())

    def update(self, y):
        return _call(self._f.update, np.asarray(y, dtype=float).ravel())

    def set_innovation_gate(self, nis_threshold):
        """Skip updates whose normalised innovation squared exceeds this (default: none)."""
        self._f.set_innovation_gate(float(nis_threshold))

    x = property(lambda self: self._f.x)
    P = property(lambda self: self._f.P)
    K = property(lambda self: self._f.K)
    innovation = property(lambda self: self._f.innovation)
    nis = property(lambda self: self._f.nis)

    def __repr__(self):
        return f"<hinf.Ekf n={self.n}>"


def ekf(F, G, H, Q, R, x0=None, P0=None):
    """The runtime's EKF on the linear model (see `Ekf`), sizes from the matrices; x(0) = x0
    (default 0) and P(0) = P0 (default I). Bad shapes, or a Q, R, P0 that is not positive
    (semi)definite, raise InvalidInput naming the matrix."""
    as_matrix = lambda M: np.atleast_2d(np.asarray(M, dtype=float))
    f = Ekf(_call(_hinf.LinearEkf, as_matrix(F), as_matrix(G), as_matrix(H), as_matrix(Q), as_matrix(R)),
            as_matrix(F).shape[0])
    f.init(np.zeros(f.n) if x0 is None else x0, np.eye(f.n) if P0 is None else P0)
    return f

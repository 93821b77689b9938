// The Python module's compiled core, `hinf._hinf` (docs/python.md): pybind11 over the
// synthesis API (synth/api.hpp) and the simulation API (sim/family.hpp), nothing else —
// every number comes from the same library calls as the executables'. Matrices cross as
// numpy arrays (pybind11/eigen.h copies them); errors as hinf.Error subclasses carrying the
// executables' exit code (python/hinf/__init__.py maps them). Long jobs release the GIL.
#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <variant>

#include "hinf/codegen/codegen.hpp"
#include "hinf/common/error.hpp"
#include "hinf/common/input_file.hpp"
#include "hinf/models/linear.hpp"
#include "hinf/runtime/ekf.hpp"
#include "hinf/runtime/lti_filter.hpp"
#include "hinf/runtime_yaml/gains_file.hpp"
#include "hinf/runtime_yaml/lti_filter_from_gains.hpp"
#include "hinf/sim/family.hpp"
#include "hinf/sim/plots.hpp"
#include "hinf/synth/api.hpp"
#include "hinf/synth/comparison.hpp"
#include "hinf/synth/filter_file.hpp"
#include "hinf/synth/gains_output.hpp"
#include "hinf/synth/sweep.hpp"

namespace py = pybind11;
using hinf::synth::Problem;

namespace {

// A filter's matrices by the names of the gains file (the optional ones only when present).
py::dict filter_dict(const hinf::Filter& f) {
  py::dict d;
  d["A_F"] = f.A_F;
  d["B_F"] = f.B_F;
  d["C_F"] = f.C_F;
  if (f.D_F.size() > 0) d["D_F"] = f.D_F;
  if (f.G_F.size() > 0) d["G_F"] = f.G_F;
  d["form"] = f.form == hinf::FilterForm::Observer ? "observer" : "augmented";
  return d;
}

py::dict controller_dict(const hinf::Controller& k) {
  py::dict d;
  d["A_K"] = k.A_K;
  d["B_K"] = k.B_K;
  d["C_K"] = k.C_K;
  d["D_K"] = k.D_K;
  return d;
}

// solve's outcome: γ, the matrices, the file's text and the report (the certificate and the
// bracket are in the file's text, which hinf/__init__.py parses into dicts).
py::dict solve_dict(const hinf::synth::SolveOutcome& o) {
  py::dict d;
  d["gamma"] = o.gamma;
  d["file"] = o.file;
  d["file_contents"] = o.file_contents;
  d["report"] = o.report;
  if (const auto* f = std::get_if<hinf::synth::SynthesisResult>(&o.result)) {
    d["kind"] = "filter";
    d["matrices"] = filter_dict(f->filter);
  } else {
    d["kind"] = "controller";
    d["matrices"] = controller_dict(std::get<hinf::synth::ControllerSynthesisResult>(o.result).controller);
  }
  return d;
}

// One point of a sweep as the CSV and JSON of `hinf-synth sweep` give it (None where they
// leave the field empty or null).
py::dict sweep_point_dict(const hinf::synth::SweepPoint& p) {
  const bool ok = p.outcome == hinf::ErrorCode::Ok;
  py::dict d;
  d["value"] = p.value;
  d["outcome"] = hinf::synth::sweep_outcome_word(p.outcome);
  d["exit_code"] = hinf::exit_code(p.outcome);
  d["gamma"] = ok ? py::object(py::float_(p.gamma)) : py::none();
  d["gamma_lower"] = ok && p.gap_certified ? py::object(py::float_(p.gamma_lower)) : py::none();
  d["form"] = ok ? py::object(py::str(p.form)) : py::none();
  d["time_s"] = p.time_s;
  d["message"] = p.message;
  return d;
}

py::list sweep_points(const std::vector<hinf::synth::SweepPoint>& points) {
  py::list l;
  for (const auto& p : points) l.append(sweep_point_dict(p));
  return l;
}

py::dict figures_dict(const hinf::synth::FilterFigures& f) {
  py::dict d;
  d["hinf_norm_nominal"] = f.hinf_norm_nominal;
  d["hinf_peak_theta"] = f.hinf_peak_theta;
  d["h2_norm_nominal"] = f.h2_norm_nominal;
  d["robust_bound"] = std::isnan(f.robust_bound) ? py::object(py::none()) : py::object(py::float_(f.robust_bound));
  d["sigma"] = Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(f.sigma.data(), static_cast<Eigen::Index>(f.sigma.size())));
  return d;
}

// A config's text (read from `path` as the executables read it when `text` is None).
std::string config_text(const std::optional<std::string>& text, const std::string& path) {
  return text ? *text : hinf::read_input_file(path, "config", hinf::kMaxConfigBytes);
}

using hinf::runtime::LtiFilter;

// The runtime's EKF on the linear model x(k+1) = F x + G u, y = H x (docs/maths.md §12),
// its sizes taken from the matrices (Eigen::Dynamic): the same predict/update code as flies.
using LinearModel = hinf::models::LinearModel<Eigen::Dynamic, Eigen::Dynamic>;
using LinearMeasurement = hinf::models::LinearMeasurement<Eigen::Dynamic, Eigen::Dynamic>;
using LinearEkf = hinf::runtime::Ekf<LinearModel, LinearMeasurement>;

// A runtime filter's refusal (std::invalid_argument) as the library's InvalidInput.
template <class Call>
auto refused_as_invalid_input(Call&& call) {
  try {
    return call();
  } catch (const std::invalid_argument& e) {
    throw hinf::Error(hinf::ErrorCode::InvalidInput, e.what());
  }
}

void require_length(const Eigen::VectorXd& v, Eigen::Index n, const char* what) {
  if (v.size() != n)
    throw hinf::Error(hinf::ErrorCode::InvalidInput,
                      std::string(what) + " must have " + std::to_string(n) + " entries; got " + std::to_string(v.size()),
                      what);
}

LinearEkf make_linear_ekf(const Eigen::MatrixXd& F, const Eigen::MatrixXd& G, const Eigen::MatrixXd& H,
                          const Eigen::MatrixXd& Q, const Eigen::MatrixXd& R) {
  const Eigen::Index n = F.rows();
  const auto shape = [](const Eigen::MatrixXd& M, Eigen::Index rows, Eigen::Index cols, const char* name) {
    if (M.rows() != rows || M.cols() != cols || rows == 0 || cols == 0)
      throw hinf::Error(hinf::ErrorCode::InvalidInput,
                        std::string(name) + " must be " + std::to_string(rows) + "x" + std::to_string(cols) +
                            " (nonempty); got " + std::to_string(M.rows()) + "x" + std::to_string(M.cols()),
                        name);
  };
  shape(F, n, n, "F");
  shape(G, n, G.cols(), "G");
  shape(H, H.rows(), n, "H");
  shape(Q, n, n, "Q");
  shape(R, H.rows(), H.rows(), "R");
  return refused_as_invalid_input([&] { return LinearEkf(LinearModel(F, G), LinearMeasurement(H), Q, R); });
}

// The filter driven over a whole record (rows are samples: Y is N×m, U N×r), z_F(k) as the
// rows of the result — the loop in C++, without the GIL.
Eigen::MatrixXd run_filter(LtiFilter& f, const Eigen::MatrixXd& Y, const std::optional<Eigen::MatrixXd>& U) {
  if (Y.cols() != f.m())
    throw std::invalid_argument("Y must have m = " + std::to_string(f.m()) + " columns (one row per sample); got " +
                                std::to_string(Y.cols()));
  if (U && (U->rows() != Y.rows() || U->cols() != f.r()))
    throw std::invalid_argument("U must be " + std::to_string(Y.rows()) + "x" + std::to_string(f.r()) +
                                " (one row per sample of Y); got " + std::to_string(U->rows()) + "x" +
                                std::to_string(U->cols()));
  Eigen::MatrixXd Z(Y.rows(), f.l());
  py::gil_scoped_release release;
  for (Eigen::Index k = 0; k < Y.rows(); ++k) {
    const Eigen::VectorXd y = Y.row(k).transpose();
    Z.row(k) = U ? f.step(y, U->row(k).transpose()).transpose() : f.step(y).transpose();
  }
  return Z;
}

// Runs `job` without the GIL (other Python threads go on meanwhile).
template <class Job>
auto without_gil(Job&& job) {
  py::gil_scoped_release release;
  return job();
}

// Ctrl-C during a long job. The solver polls `poll()` (sdp::Options::interrupted, through
// synth's JobObservers) while the GIL is released; at most every kPollSeconds it takes the
// GIL and runs Python's signal handlers (PyErr_CheckSignals, main thread only). The
// exception a handler raised (KeyboardInterrupt for SIGINT) is kept, the solver told to
// stop, and the exception raised again once the job has returned or thrown.
class Interruption {
 public:
  std::function<bool()> poll() {
    return [state = state_] {
      if (state->raised) return true;
      const auto now = std::chrono::steady_clock::now();
      if (now - state->last < std::chrono::duration<double>(kPollSeconds)) return false;
      state->last = now;
      py::gil_scoped_acquire gil;
      if (PyErr_CheckSignals() == 0) return false;
      PyErr_Fetch(&state->type, &state->value, &state->traceback);
      state->raised = true;
      return true;
    };
  }
  // Raises the kept exception (with the GIL held), if a handler raised one.
  void raise_if_interrupted() {
    if (!state_->raised) return;
    PyErr_Restore(state_->type, state_->value, state_->traceback);
    state_->type = state_->value = state_->traceback = nullptr;
    throw py::error_already_set();
  }
  // Runs `job` without the GIL, interruptible through poll(): its result, or the kept
  // exception raised in place of the job's own (which only says "interrupted").
  template <class Job>
  auto run(Job&& job) {
    try {
      auto result = without_gil(std::forward<Job>(job));
      raise_if_interrupted();
      return result;
    } catch (const py::error_already_set&) {
      throw;
    } catch (...) {
      raise_if_interrupted();
      throw;
    }
  }

 private:
  static constexpr double kPollSeconds = 0.05;  // a Ctrl-C is seen within this, plus one LMI term's work
  struct State {
    std::atomic<bool> raised{false};
    std::chrono::steady_clock::time_point last{};
    PyObject* type = nullptr;
    PyObject* value = nullptr;
    PyObject* traceback = nullptr;
  };
  std::shared_ptr<State> state_ = std::make_shared<State>();
};

}  // namespace

PYBIND11_MODULE(_hinf, m) {
  m.doc() = "compiled core of the hinf module (use `import hinf`)";

  // hinf::Error crosses as (exit code, message, key); __init__.py raises the subclass.
  static py::exception<hinf::Error> error_base(m, "NativeError");
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const hinf::Error& e) {
      py::tuple args = py::make_tuple(hinf::exit_code(e.code()), std::string(e.what()), e.key());
      PyErr_SetObject(error_base.ptr(), args.ptr());
    }
  });

  py::class_<Problem, std::shared_ptr<Problem>>(m, "Problem")
      .def_property_readonly("kind", [](const Problem& p) { return std::string(p.kind()); })
      .def_property_readonly("source", &Problem::source)
      .def_property_readonly("sha256", &Problem::sha256)
      .def("solve",
           [](const Problem& p) {
             // the centrings' ends (not every Newton step), as the iteration table shows them
             std::vector<hinf::synth::IterationReport> log;
             hinf::synth::JobObservers obs;
             obs.on_iteration = [&log](const hinf::synth::IterationReport& r) {
               if (!r.progress.newton_step && !r.progress.assembling) log.push_back(r);
             };
             Interruption interruption;
             obs.interrupted = interruption.poll();
             const auto outcome = interruption.run([&] { return p.solve(obs); });
             py::dict d = solve_dict(outcome);
             py::list iterations;
             for (const auto& r : log) {
               py::dict it;
               it["stage"] = r.stage == hinf::synth::SolveStage::Backoff      ? "backoff"
                             : r.stage == hinf::synth::SolveStage::Controller ? "controller"
                                                                              : "synthesis";
               it["phase"] = r.progress.phase;
               it["centering"] = r.progress.centering;
               it["t"] = r.progress.t;
               it["objective"] = r.progress.objective;
               it["gap"] = r.progress.gap;
               it["newton"] = r.progress.newton;
               it["elapsed_s"] = r.progress.elapsed_s;
               iterations.append(it);
             }
             d["iterations"] = iterations;
             return d;
           })
      .def("analyze",
           [](const Problem& p, const std::string& file, int delta_points) {
             const auto o = without_gil([&] { return p.analyze(file, {delta_points}); });
             return py::make_tuple(o.report, o.json);
           },
           py::arg("file"), py::arg("delta_points") = 41)
      .def("verify",
           [](const Problem& p, const std::string& file) {
             const auto o = without_gil([&] { return p.verify(file); });
             return py::make_tuple(o.holds, o.report);
           })
      .def("check",
           [](const Problem& p, const std::string& golden, double rtol) {
             Interruption interruption;
             hinf::synth::JobObservers obs;
             obs.interrupted = interruption.poll();
             const auto o = interruption.run([&] { return p.check(golden, rtol, obs); });
             return py::make_tuple(o.same, o.gamma_now, o.report);
           })
      .def("export_sdpa", [](const Problem& p) { return without_gil([&] { return p.export_sdpa(); }); })
      .def("kalman", [](const Problem& p) {
        py::dict d = solve_dict(without_gil([&] { return p.kalman(); }));
        d["iterations"] = py::list();
        return d;
      });

  // The runtime's fixed-gain filter (runtime/lti_filter.hpp), loaded as flight code loads it
  // (runtime_yaml::make_lti_filter: D_F and G_F included).
  py::class_<LtiFilter>(m, "LtiFilter")
      .def_static("from_text",
                  [](const std::string& text, const std::string& name) {
                    return hinf::runtime_yaml::make_lti_filter(hinf::runtime_yaml::parse_gains_yaml(text, name), name);
                  })
      .def_static("from_file",
                  [](const std::string& path) {
                    return hinf::runtime_yaml::make_lti_filter(hinf::runtime_yaml::load_gains_file(path), path);
                  })
      .def_property_readonly("n", &LtiFilter::n)
      .def_property_readonly("m", &LtiFilter::m)
      .def_property_readonly("l", &LtiFilter::l)
      .def_property_readonly("r", &LtiFilter::r)
      .def_property_readonly("state", [](const LtiFilter& f) { return Eigen::VectorXd(f.x_F()); })
      .def("init", [](LtiFilter& f, const Eigen::VectorXd& z0) { f.init(z0); }, py::arg("z0"))
      .def("set_state", [](LtiFilter& f, const Eigen::VectorXd& x) { f.set_state(x); }, py::arg("x_F"))
      .def("step", [](LtiFilter& f, const Eigen::VectorXd& y) { return Eigen::VectorXd(f.step(y)); }, py::arg("y"))
      .def("step", [](LtiFilter& f, const Eigen::VectorXd& y, const Eigen::VectorXd& u) { return Eigen::VectorXd(f.step(y, u)); },
           py::arg("y"), py::arg("u"))
      .def("run", &run_filter, py::arg("Y"), py::arg("U") = py::none());

  py::class_<LinearEkf>(m, "LinearEkf")
      .def(py::init(&make_linear_ekf), py::arg("F"), py::arg("G"), py::arg("H"), py::arg("Q"), py::arg("R"))
      .def("init",
           [](LinearEkf& f, const Eigen::VectorXd& x0, const Eigen::MatrixXd& P0) {
             refused_as_invalid_input([&] { f.init(x0, P0); return 0; });
           },
           py::arg("x0"), py::arg("P0"))
      .def("predict",
           [](LinearEkf& f, const Eigen::VectorXd& u) {
             require_length(u, f.model().G().cols(), "u");
             return std::string(hinf::runtime::to_string(f.predict(u)));
           },
           py::arg("u"))
      .def("update",
           [](LinearEkf& f, const Eigen::VectorXd& y) {
             require_length(y, f.R().rows(), "y");
             return std::string(hinf::runtime::to_string(f.update(y)));
           },
           py::arg("y"))
      .def("set_innovation_gate", &LinearEkf::set_innovation_gate, py::arg("nis_threshold"))
      .def_property_readonly("x", [](const LinearEkf& f) { return Eigen::VectorXd(f.x()); })
      .def_property_readonly("P", [](const LinearEkf& f) { return Eigen::MatrixXd(f.P()); })
      .def_property_readonly("K", [](const LinearEkf& f) { return Eigen::MatrixXd(f.K()); })
      .def_property_readonly("innovation", [](const LinearEkf& f) { return Eigen::VectorXd(f.innovation()); })
      .def_property_readonly("nis", &LinearEkf::nis);

  // `hinf-synth codegen`: the four C99 files of a gains or controller file (its text, or read
  // from `path` as the executable reads it when `text` is None), in memory ({name: text});
  // written into `out` (atomically, never over an input) when given. With `tustin` or `zoh` (a
  // period, s) and `config`: the continuous-time controller file at `path` discretised, its
  // sampled loop certified (CheckFailed with the report when it is not), and NAME_controller.yaml
  // (the discrete controller file) beside the C files.
  m.def(
      "codegen",
      [](std::optional<std::string> text, const std::string& path, const std::string& prefix, const std::string& real,
         int vector_steps, std::optional<double> tustin, std::optional<double> zoh, const std::string& config,
         std::optional<std::string> out) {
        hinf::codegen::CodegenOptions options;
        options.prefix = prefix;
        if (real != "double" && real != "float")
          throw hinf::Error(hinf::ErrorCode::InvalidInput, "real = '" + real + "': must be 'double' or 'float'", "real");
        options.real = real == "float" ? hinf::codegen::CodegenOptions::Real::Float : hinf::codegen::CodegenOptions::Real::Double;
        options.generator = std::string("hinf-synth ") + hinf::synth::tool_version();
        options.vector_steps = vector_steps;
        const hinf::codegen::GeneratedFiles files = without_gil([&] {
          hinf::codegen::validate_codegen_prefix(options.prefix);  // before touching any file
          if ((tustin || zoh) && text)
            throw hinf::Error(hinf::ErrorCode::InvalidInput, "tustin/zoh: give the controller file's path", "tustin");
          const auto sampled = hinf::synth::discretise_for_codegen(path, config, tustin, zoh);
          if (sampled && !sampled->holds) throw hinf::Error(hinf::ErrorCode::CheckFailed, sampled->report);
          if (sampled) text = sampled->file;
          if (!text) text = hinf::read_input_file(path, "gains or controller file", hinf::kMaxGainsBytes);
          hinf::codegen::GeneratedFiles g = hinf::codegen::generate_c_for_file(*text, path, options);
          if (sampled) g.files.push_back({prefix + "_controller.yaml", sampled->file});
          std::vector<std::string> inputs{path};
          if (!config.empty()) inputs.push_back(config);
          if (out) hinf::codegen::write_generated_files(g, *out, inputs);
          return g;
        });
        py::dict d;
        for (const auto& f : files.files) d[py::str(f.name)] = f.contents;
        return d;
      },
      py::arg("text"), py::arg("path"), py::arg("prefix"), py::arg("real") = "double", py::arg("vector_steps") = 50,
      py::arg("tustin") = py::none(), py::arg("zoh") = py::none(), py::arg("config") = "",
      py::arg("out") = py::none());

  m.def("parse_problem", [](const std::string& text, const std::string& name) {
    return std::shared_ptr<Problem>(hinf::synth::parse_problem(text, name));
  });
  m.def("load_problem", [](const std::string& path) { return std::shared_ptr<Problem>(hinf::synth::load_problem(path)); });

  // `hinf-synth sweep --param NAME=…`: a full certified synthesis at each value, a point's
  // failure recorded (never raised), as a list of dicts.
  m.def(
      "sweep",
      [](std::optional<std::string> text, const std::string& path, const std::string& name,
         const std::vector<double>& values) {
        const std::string yaml = config_text(text, path);
        Interruption interruption;
        const auto points = interruption.run([&, poll = interruption.poll()] {
          const hinf::synth::SweepParameter parameter = hinf::synth::resolve_sweep_parameter(name, yaml, path);
          return hinf::synth::sweep(parameter, values, yaml, path, poll);
        });
        return sweep_points(points);
      },
      py::arg("text"), py::arg("path"), py::arg("name"), py::arg("values"));

  // `hinf-synth sweep --max-feasible NAME=LO:HI`: the largest certified value, by bisection.
  m.def(
      "max_feasible",
      [](std::optional<std::string> text, const std::string& path, const std::string& name, double lo, double hi,
         double tolerance) {
        const std::string yaml = config_text(text, path);
        Interruption interruption;
        const hinf::synth::FeasibilitySearch s = interruption.run([&, poll = interruption.poll()] {
          const hinf::synth::SweepParameter parameter = hinf::synth::resolve_sweep_parameter(name, yaml, path);
          return hinf::synth::max_feasible(parameter, lo, hi, tolerance, yaml, path, poll);
        });
        py::dict d;
        d["largest_certified"] = sweep_point_dict(s.largest_certified);
        d["smallest_not_certified"] =
            s.smallest_not_certified ? py::object(sweep_point_dict(*s.smallest_not_certified)) : py::none();
        d["smallest_infeasible"] = s.smallest_infeasible ? py::object(sweep_point_dict(*s.smallest_infeasible)) : py::none();
        d["bracket_width"] = s.bracketed ? py::object(py::float_(s.width)) : py::none();
        d["evaluated"] = sweep_points(s.evaluated);
        return d;
      },
      py::arg("text"), py::arg("path"), py::arg("name"), py::arg("lo"), py::arg("hi"), py::arg("tolerance"));

  // `hinf-synth compare CONFIG GAINS`: the filter beside the Kalman filter of the same plant.
  m.def(
      "compare",
      [](const std::string& config_path, const std::string& gains_path, int points) {
        const auto [c, sample_time] = without_gil([&] {
          const hinf::synth::ConfigAndFilter in = hinf::synth::load_config_and_filter(config_path, gains_path);
          return std::make_pair(hinf::synth::compare_with_kalman(in.config.plant, in.filter, in.config.settings, points,
                                                                 in.config.kalman_noise),
                                in.config.sample_time());
        });
        py::dict d;
        d["theta"] = Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(c.theta.data(), static_cast<Eigen::Index>(c.theta.size())));
        d["sample_time"] = sample_time ? py::object(py::float_(*sample_time)) : py::none();
        d["filter"] = figures_dict(c.filter);
        d["kalman"] = figures_dict(c.kalman);
        return d;
      },
      py::arg("config"), py::arg("gains"), py::arg("points") = 400);

  // One Monte-Carlo campaign in memory (the scenario read as hinf-sim reads it): the run
  // directory's files as {name: bytes}.
  m.def(
      "simulate",
      [](const std::string& path, long runs, std::uint64_t seed, int jobs, std::optional<double> duration,
         std::optional<std::string> out, bool plots) {
        hinf::sim::CampaignRequest request;
        request.scenario_text = hinf::read_input_file(path, "scenario", hinf::kMaxScenarioBytes);
        request.scenario_path = path;
        request.runs = runs;
        request.seed = seed;
        request.jobs = jobs;
        request.duration = duration;
        Interruption interruption;
        request.interrupted = interruption.poll();
        const hinf::sim::CampaignResult result = interruption.run([&] { return hinf::sim::simulate(request); });
        if (out)  // the run directory as hinf-sim writes it: all or nothing, never over an input
          without_gil([&] {
            try {
              hinf::sim::write_campaign(result, *out, path, plots);
            } catch (const hinf::sim::PlotError& e) {  // gnuplot could not draw: as hinf-sim says it
              throw hinf::Error(hinf::ErrorCode::InvalidInput, std::string("plots: ") + e.what());
            }
            return 0;
          });
        py::dict files;
        for (const auto& [name, bytes] : result.files) files[py::str(name)] = py::bytes(bytes);
        return files;
      },
      py::arg("path"), py::arg("runs") = 1, py::arg("seed") = 1, py::arg("jobs") = 1,
      py::arg("duration") = py::none(), py::arg("out") = py::none(), py::arg("plots") = false);
}

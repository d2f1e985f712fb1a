// rupture/cli/main.cpp
// The `rupture` command line:
//   rupture check CASE.toml [--set key=value ...]   validate and print derived quantities
//   rupture check --explain [KEY]   the description of an input key or table (no case file)
//   rupture docs --input            the input reference as Markdown (docs/input.md)
//   rupture run   CASE.toml -o DIR [--set key=value ...] [--quiet] [--checkpoint-interval T]
//                 [--overwrite] [--no-rebalance]
//   rupture resume DIR [--quiet] [--checkpoint-interval T]   continue from DIR's last checkpoint
//   rupture sweep CASE.toml -o DIR --vary KEY=V1,V2,... [--vary ...] [--set ...] [-j K]
//                 [--threads N] [--checkpoint-interval T] [--quiet]   parameter study
//                 (run/sweep.hpp): DIR/<run>/ and DIR/summary.csv; resumable
//   rupture plot  DIR [--compare DIR2 ...] [--labels A B ...]   figures into DIR/figures/
//                 (python/rupture_plot.py with Debian's /usr/bin/python3: numpy, matplotlib,
//                 h5py; RUPTURE_PYTHON overrides the interpreter)
// Exit codes: 0 success, 1 bad input (also: an output directory holding another run without
// --overwrite, no usable checkpoint to resume), 2 the run went unstable, 3 I/O failure (the
// message names the file and the operating system's reason) or other failure, 4 interrupted by
// SIGINT/SIGTERM after writing a checkpoint (the message says how to resume).
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

#include "cli/print_check.hpp"
#include "cli/print_result.hpp"
#include "core/build_info.hpp"
#include "core/errors.hpp"
#include "core/fp_mode.hpp"
#include "input/case_toml.hpp"
#include "run/checkpoint.hpp"
#include "core/fault_injection.hpp"
#include "parallel/agreement.hpp"
#include "parallel/comm.hpp"
#include "input/input_schema.hpp"
#include "input/text_limits.hpp"
#include "run/driver.hpp"
#include "run/sweep.hpp"

using namespace rupture;

namespace {

// A helper script (python/NAME): next to the executable, in ../share/rupture, or the source's.
std::string helper_script(const char* argv0, const char* name, const char* source) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path exe = fs::canonical("/proc/self/exe", ec);
  const fs::path dir = ec ? fs::path(argv0).parent_path() : exe.parent_path();
  for (const fs::path& p : {dir / name, dir / "../share/rupture" / name, fs::path(source)})
    if (fs::exists(p)) return p.string();
  return {};
}

// Replaces this process by `python script args...`; returns only on failure.
int exec_python(const std::string& script, std::vector<std::string> args) {
  const char* env = std::getenv("RUPTURE_PYTHON");
  const std::string python = env && *env ? env
                             : std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3"
                                                                           : "python3";
  args.insert(args.begin(), {python, script});
  std::vector<char*> cargs;
  for (std::string& a : args) cargs.push_back(a.data());
  cargs.push_back(nullptr);
  execvp(cargs[0], cargs.data());
  fmt::print(stderr, "error: cannot start '{}': {}\n", python, std::strerror(errno));
  return 3;
}

// `rupture export DIR --format scec` (python/rupture_export.py).
int run_export(const char* argv0, const std::vector<std::string>& args) {
  const std::string script = helper_script(argv0, "rupture_export.py", RUPTURE_EXPORT_SCRIPT_SOURCE);
  if (script.empty()) {
    fmt::print(stderr, "error: rupture_export.py not found next to the executable nor at {}\n",
               RUPTURE_EXPORT_SCRIPT_SOURCE);
    return 3;
  }
  return exec_python(script, args);
}

// Replaces this process by the plotting script; returns only on failure.
int run_plot(const char* argv0, const std::string& dir, const std::vector<std::string>& compare,
             const std::vector<std::string>& labels) {
  const std::string script = helper_script(argv0, "rupture_plot.py", RUPTURE_PLOT_SCRIPT_SOURCE);
  if (script.empty()) {
    fmt::print(stderr, "error: rupture_plot.py not found next to the executable nor at {}\n",
               RUPTURE_PLOT_SCRIPT_SOURCE);
    return 3;
  }
  std::vector<std::string> args{dir};
  if (!compare.empty()) {
    args.push_back("--compare");
    args.insert(args.end(), compare.begin(), compare.end());
  }
  if (!labels.empty()) {
    args.push_back("--labels");
    args.insert(args.end(), labels.begin(), labels.end());
  }
  return exec_python(script, args);
}

// The case file as read, or (a resume) the input its checkpoint stores. The fault site
// case_read fails it as a missing file does (core/fault_injection.hpp).
CaseSource read_source(bool resume, const std::string& path, const std::vector<std::string>& overrides) {
  if (fault_due(FaultSite::case_read, 0))
    throw InputError(fmt::format("cannot read {} '{}': No such file or directory (injected)",
                                 resume ? "checkpoint" : "case file", path));
  if (resume) return read_checkpoint_source(path);
  return CaseSource{read_bounded_file(path, kMaxCaseBytes, "case file"), path, overrides};
}

// The case every rank runs, read once. Under mpirun rank 0 alone reads the files (the case and
// its table files, or the checkpoint's input) and parses them; the others parse what it sends
// (the merged input with the tables inline when it read table files, which reads back to the
// same case). A file that some node lacks or cannot read then stops every rank with rank 0's
// message, where ranks that read their own copies could fail alone and leave the others
// waiting in a collective call; any rank's failure is agreed (parallel/agreement.hpp).
Case load_shared_case(const Comm& world, bool resume, const std::string& path,
                      const std::vector<std::string>& overrides, CaseSource& source) {
  Case c;
  agree_on_failure(world, [&] {
    if (world.rank() != 0) return;
    source = read_source(resume, path, overrides);
    c = parse_case(source.text, source.overrides, source.origin);
  });
  if (!world.distributed()) return c;
  CaseSource sent;
  if (world.rank() == 0) sent = c.read_table_files ? CaseSource{c.input_toml, source.origin, {}} : source;
  sent.origin = world.broadcast(sent.origin, 0);
  sent.text = world.broadcast(sent.text, 0);
  // The overrides (a resume's are the checkpoint's), each as its length, ':' and its text.
  std::string packed;
  for (const std::string& o : sent.overrides) packed += fmt::format("{}:{}", o.size(), o);
  packed = world.broadcast(packed, 0);
  agree_on_failure(world, [&] {
    if (world.rank() == 0) return;
    sent.overrides.clear();
    for (std::size_t at = 0; at < packed.size();) {
      const std::size_t colon = packed.find(':', at);
      const std::size_t n = std::stoul(packed.substr(at, colon - at));
      sent.overrides.push_back(packed.substr(colon + 1, n));
      at = colon + 1 + n;
    }
    source = sent;
    c = parse_case(source.text, source.overrides, source.origin);
  });
  return c;
}

// rupture check --explain KEY: the schema entry (input/input_schema.hpp), or exit code 1 with the
// documented keys that come close.
int explain(const std::string& key) {
  if (const KeyDoc* e = find_key(key)) {
    fmt::print("{}", explain_key(*e));
    return 0;
  }
  std::string hint;
  for (const std::string& k : similar_keys(key)) hint += "\n  " + k;
  fmt::print(stderr, "error: '{}' is not an input key or table{}\n", key,
             hint.empty() ? "; rupture check --explain lists the tables"
                          : "; did you mean:" + hint);
  return 1;
}

int exit_code(Outcome o) {
  switch (o) {
    case Outcome::completed: return 0;
    case Outcome::unstable: return 2;
    case Outcome::interrupted: return 4;
    case Outcome::io_error:
    case Outcome::error: return 3;
  }
  return 3;
}

}  // namespace

int main(int argc, char** argv) {
  rupture::flush_subnormals_to_zero();  // core/fp_mode.hpp: before any other thread exists
  // Under mpirun every process runs this; `rupture run` then steps one case together
  // (parallel/halo.hpp) and rank 0 alone prints and writes (the others' stdout is discarded;
  // the diagnoses every rank shares are printed by rank 0 only).
  const MpiSession mpi(launched_by_mpi());
  const Comm world = Comm::world();
  if (world.rank() > 0 && !std::freopen("/dev/null", "w", stdout)) return 3;
  const bool quiet_errors = world.rank() > 0;
  try {
    arm_fault_from_environment(world.rank());  // tests of failure paths (core/fault_injection.hpp)
  } catch (const InputError& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 1;
  }
  CLI::App app{"rupture: dynamic fracture with GIMP and cohesive zones"};
  app.set_version_flag("--version", version_line(), "print the version, the commit it was built from, the compiler");
  app.require_subcommand(1);
  std::string case_path, out_dir;
  std::vector<std::string> overrides;
  bool quiet = false;

  auto* check = app.add_subcommand("check", "validate a case and print derived quantities");
  // CASE is required unless --explain is given (checked after parsing).
  auto* check_case = check->add_option("case", case_path, "case file (TOML)");
  check->add_option("--set", overrides, "override an input key: dotted.key=value");
  int check_ranks = 0;
  check->add_option("--ranks", check_ranks,
                    "print how N processes would split the case: blocks, particles and shared "
                    "nodes per rank, predicted imbalance")
      ->check(CLI::Range(1, 1 << 20));
  bool no_timing = false;
  check->add_flag("--no-timing", no_timing,
                  "skip the few timed steps behind measured_step_seconds= and predicted_wall_seconds=");
  std::string explain_path;
  auto* explain_opt =
      check->add_option("--explain", explain_path,
                        "describe an input key or table (unit, default, range, example), e.g. "
                        "time.cfl or interface.weak_plane.sigma_max; no KEY: the top level")
          ->expected(0, 1);

  auto* docs = app.add_subcommand("docs", "print reference documentation");
  bool docs_input = false;
  docs->add_flag("--input", docs_input, "every input table and key as Markdown (docs/input.md)")
      ->required();

  auto* run = app.add_subcommand("run", "run a case");
  run->add_option("case", case_path, "case file (TOML)")->required();
  run->add_option("-o,--output", out_dir, "output directory")->required();
  run->add_option("--set", overrides, "override an input key: dotted.key=value");
  run->add_flag("-q,--quiet", quiet, "no progress line");
  double checkpoint_interval = 0.0;
  long stop_after_steps = 0;
  bool overwrite = false;
  run->add_option("--checkpoint-interval", checkpoint_interval,
                  "write a checkpoint every T seconds of simulated time (rupture resume DIR)")
      ->check(CLI::NonNegativeNumber);
  run->add_flag("--overwrite", overwrite, "delete another run's files in the output directory");
  bool no_rebalance = false;
  run->add_flag("--no-rebalance", no_rebalance,
                "under mpirun: keep the split of t = 0 (no re-split when the measured load drifts)");
  // Tests: stop after N steps as if interrupted (checkpoint written, exit code 4).
  run->add_option("--stop-after-steps", stop_after_steps)->group("");

  std::string resume_dir;
  auto* resume = app.add_subcommand("resume", "continue a run from its last checkpoint");
  resume->add_option("dir", resume_dir, "run directory")->required()->check(CLI::ExistingDirectory);
  resume->add_flag("-q,--quiet", quiet, "no progress line");
  resume->add_option("--checkpoint-interval", checkpoint_interval,
                     "change the checkpoint interval (default: the run's)")
      ->check(CLI::NonNegativeNumber);
  resume->add_option("--stop-after-steps", stop_after_steps)->group("");
  resume->add_flag("--no-rebalance", no_rebalance, "under mpirun: keep the split made at the resume");

  SweepOptions sweep_opt;
  std::vector<std::string> vary;
  auto* sweep = app.add_subcommand("sweep", "run a case for every combination of --vary values");
  sweep->add_option("case", sweep_opt.case_path, "case file (TOML)")->required()->check(CLI::ExistingFile);
  sweep->add_option("-o,--output", sweep_opt.dir, "sweep directory")->required();
  sweep->add_option("--vary", vary, "KEY=V1,V2,...: values of an input key (repeat for more keys)")
      ->required();
  sweep->add_option("--set", sweep_opt.sets, "override an input key in every run: dotted.key=value");
  sweep->add_option("-j,--jobs", sweep_opt.jobs, "runs at a time (default 1)")->check(CLI::PositiveNumber);
  sweep->add_option("--threads", sweep_opt.threads,
                    "threads in all, split between the runs (default: the machine's)")
      ->check(CLI::PositiveNumber);
  sweep->add_option("--checkpoint-interval", sweep_opt.checkpoint_interval,
                    "checkpoint every T seconds of simulated time in each run")
      ->check(CLI::NonNegativeNumber);
  sweep->add_flag("-q,--quiet", sweep_opt.quiet, "no line per run");

  std::string plot_dir;
  std::vector<std::string> compare, labels;
  auto* plot = app.add_subcommand("plot", "write the figures of a finished run into DIR/figures/");
  plot->add_option("dir", plot_dir, "run directory")->required()->check(CLI::ExistingDirectory);
  plot->add_option("--compare", compare, "more run directories to overlay on crack_tip.png (on a sweep: more sweeps, one map)")
      ->check(CLI::ExistingDirectory);
  plot->add_option("--labels", labels, "legend labels, one per run");

  std::string export_dir, export_format, export_problem, export_author;
  auto* exp = app.add_subcommand(
      "export", "write a finished run's results in a community format into DIR/FORMAT/ (docs/faults.md)");
  exp->add_option("dir", export_dir, "run directory")->required()->check(CLI::ExistingDirectory);
  exp->add_option("--format", export_format, "the format: scec (the SCEC code-verification uploads)")
      ->required()
      ->check(CLI::IsMember({"scec"}));
  exp->add_option("--problem", export_problem, "the benchmark's name for the files' # problem= line "
                                               "(default: the case's title)");
  exp->add_option("--author", export_author, "the files' # author= line");

  CLI11_PARSE(app, argc, argv);
  if (exp->parsed()) {
    std::vector<std::string> args{export_dir, "--format", export_format};
    if (!export_problem.empty()) args.insert(args.end(), {"--problem", export_problem});
    if (!export_author.empty()) args.insert(args.end(), {"--author", export_author});
    return run_export(argv[0], args);
  }
  if (docs->parsed()) {
    fmt::print("{}", input_reference_markdown());
    return 0;
  }
  if (check->parsed() && explain_opt->count() > 0) return explain(explain_path);
  if (check->parsed() && check_case->count() == 0)
    return app.exit(CLI::RequiredError(check_case->get_name()));
  if (plot->parsed()) return run_plot(argv[0], plot_dir, compare, labels);
  if (sweep->parsed()) {
    try {
      for (const std::string& v : vary) sweep_opt.axes.push_back(parse_vary(v));
      std::error_code ec;
      const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
      sweep_opt.exe = ec ? std::string(argv[0]) : self.string();
      return run_sweep(sweep_opt);
    } catch (const InputError& e) {
      fmt::print(stderr, "error: {}\n", e.what());
      return 1;
    } catch (const std::exception& e) {
      fmt::print(stderr, "error: {}\n", e.what());
      return 3;
    }
  }

  try {
    auto warn = [&](const Case& c) {
      if (quiet_errors) return;
      for (const std::string& w : c.warnings) fmt::print(stderr, "warning: {}\n", w);
    };
    if (check->parsed()) {
      const Case c = load_case(case_path, overrides);
      warn(c);
      print_check(case_path, c);
      if (check_ranks > 0) print_rank_plan(c, check_ranks);
      if (!no_timing) print_predicted_time(c);
      return 0;
    }
    RunOptions options;
    options.progress = !quiet;
    options.checkpoint_interval = checkpoint_interval;
    options.stop_after_steps = stop_after_steps;
    options.rebalance = !no_rebalance;
    if (resume->parsed()) {
      out_dir = resume_dir;
      options.resume = true;
      fmt::print("resuming run in {}\n", resume_dir);
    } else {
      options.overwrite = overwrite;
    }
    options.output_dir = out_dir;
    options.comm = world;
    const Case c = load_shared_case(world, options.resume, options.resume ? checkpoint_path(resume_dir) : case_path,
                                    overrides, options.source);
    // A checkpoint must not depend on files that can change or vanish before `rupture resume`:
    // with table_file tables it stores the merged input with the tables inline (exact: the
    // echo writes every number so that it reads back to the same double).
    if (!resume->parsed() && c.read_table_files)
      options.source = CaseSource{c.input_toml, options.source.origin, {}};
    warn(c);
    print_check(options.source.origin, c);
    const RunResult r = run_case(c, options);
    print_run_result(c, r, out_dir);
    if (quiet_errors) {
    } else if (r.outcome == Outcome::interrupted) {
      fmt::print(stderr, "{}\n", r.message);
    } else if (!r.ok) {
      fmt::print(stderr, "error: {}\n", r.message);
    }
    return exit_code(r.outcome);
  } catch (const InputError& e) {  // the same on every rank of a distributed run
    if (!quiet_errors) fmt::print(stderr, "error: {}\n", e.what());
    return 1;
  } catch (const AgreedFailure& e) {  // every rank holds it (parallel/agreement.hpp)
    if (!quiet_errors) fmt::print(stderr, "error: {}\n", e.what());
    return e.exit_code();
  } catch (const std::exception& e) {
    if (world.distributed()) {  // one rank's own failure: say which, and stop the others
      fmt::print(stderr, "error: rank {}: {}\n", world.rank(), e.what());
      world.abort(3);
    }
    fmt::print(stderr, "error: {}\n", e.what());
    return 3;
  }
}

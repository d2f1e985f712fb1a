// rupture/run/sweep.cpp
#include "run/sweep.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include "core/errors.hpp"
#include "core/atomic_file.hpp"
#include "input/case_toml.hpp"

namespace rupture {
namespace fs = std::filesystem;
namespace {

volatile std::sig_atomic_t g_stop = 0;
extern "C" void on_stop_signal(int) { g_stop = 1; }

// One combination of the sweep.
struct Run {
  std::vector<std::size_t> pick;  // index into each axis' values
  std::string name, dir;
  std::string status = "pending";  // pending | completed | failed | invalid | interrupted
  std::string message;             // why it failed, or was invalid
  std::map<std::string, std::string> keys;  // key=value lines the run printed
  pid_t pid = -1;
};

// The key=value lines of a run's standard output.
std::map<std::string, std::string> read_keys(const std::string& path) {
  std::map<std::string, std::string> keys;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    const std::size_t eq = line.find('=');
    if (eq == std::string::npos || eq == 0 || line.find(' ') < eq) continue;
    keys[line.substr(0, eq)] = line.substr(eq + 1);
  }
  return keys;
}

// The last non-empty line of a file (a failed run's reason is the last line it wrote).
std::string last_line(const std::string& path) {
  std::ifstream in(path);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last;
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

// Summary columns: (column name, key printed by `rupture run`).
const std::vector<std::pair<const char*, const char*>> kColumns = {
    {"initiation_time_s", "crack.initiation_time"},
    {"intersonic_time_s", "crack.intersonic_time"},
    {"daughter_crack_time_s", "crack.daughter_crack_time"},
    {"sustained_speed_m_per_s", "crack.sustained_speed"},
    {"sustained_over_cR", "crack.sustained_speed_over_cR"},
    {"sustained_over_cS", "crack.sustained_speed_over_cS"},
    {"steady_begin_s", "crack.steady_begin"},
    {"steady_end_s", "crack.steady_end"},
    {"regime", "crack.regime"},
    {"arrested", "crack.arrested"},
    {"arrest_s_m", "crack.arrest_s"},
    {"last_window_speed_m_per_s", "crack.last_window_speed"},
    {"mach_angle_deg", "crack.mach_angle"},
    {"mach_speed_m_per_s", "crack.mach_speed"},
    {"energy_balance_error", "energy_balance_error"},
    {"energy_balance_error_final", "energy_balance_error_final"},
    {"wall_seconds", "wall_seconds"},
    {"steps", "steps"},
};

void write_summary(const SweepOptions& o, const std::vector<Run>& runs) {
  // Appended piece by piece ("," + string trips GCC 12's -Wrestrict false positive).
  std::string csv = "run";
  auto field = [&csv](const std::string& s) {
    csv += ',';
    csv += csv_field(s);
  };
  for (const SweepAxis& a : o.axes) field(a.key);
  field("status");
  for (const auto& [column, key] : kColumns) field(column);
  field("message");
  csv += '\n';
  for (const Run& r : runs) {
    csv += csv_field(r.name);
    for (std::size_t k = 0; k < o.axes.size(); ++k) field(o.axes[k].values[r.pick[k]]);
    field(r.status);
    for (const auto& [column, key] : kColumns) {
      const auto it = r.keys.find(key);
      field(it == r.keys.end() ? std::string() : it->second);
    }
    field(r.message);
    csv += '\n';
  }
  write_file_atomic(o.dir + "/summary.csv", csv);
}

// Starts one run as a child process with its output in DIR/<name>/rupture.out and .err.
pid_t start(const SweepOptions& o, Run& r, int threads) {
  std::vector<std::string> args{o.exe};
  const bool resume = fs::exists(r.dir + "/checkpoint");
  if (resume) {
    args.insert(args.end(), {"resume", r.dir});
  } else {
    args.insert(args.end(), {"run", o.case_path, "-o", r.dir, "--overwrite"});
    for (const std::string& s : o.sets) args.insert(args.end(), {"--set", s});
    for (std::size_t k = 0; k < o.axes.size(); ++k)
      args.insert(args.end(), {"--set", o.axes[k].key + "=" + o.axes[k].values[r.pick[k]]});
    args.insert(args.end(), {"--set", fmt::format("solver.threads={}", threads)});
  }
  args.emplace_back("--quiet");
  if (o.checkpoint_interval > 0)
    args.insert(args.end(), {"--checkpoint-interval", fmt::format("{:g}", o.checkpoint_interval)});
  fs::create_directories(r.dir);
  const std::string out = r.dir + "/rupture.out", err = r.dir + "/rupture.err";
  const pid_t pid = fork();
  if (pid < 0) throw_io_error("cannot start a run (fork) for", r.dir);
  if (pid == 0) {
    const int fo = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int fe = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fo < 0 || fe < 0 || dup2(fo, 1) < 0 || dup2(fe, 2) < 0) _exit(127);
    std::vector<char*> cargs;
    for (std::string& a : args) cargs.push_back(a.data());
    cargs.push_back(nullptr);
    execv(cargs[0], cargs.data());
    _exit(127);
  }
  return pid;
}

// Status of a finished child from its exit and its output.
void finish(Run& r, int wstatus) {
  r.pid = -1;
  r.keys = read_keys(r.dir + "/rupture.out");
  if (WIFEXITED(wstatus) && WEXITSTATUS(wstatus) == 0 && r.keys["status"] == "completed") {
    r.status = "completed";
    r.message.clear();
    return;
  }
  if (WIFEXITED(wstatus) && WEXITSTATUS(wstatus) == 4) {
    r.status = "interrupted";
    r.message = "interrupted: `rupture sweep` again resumes it";
    return;
  }
  r.status = "failed";
  const std::string reason = last_line(r.dir + "/rupture.err");
  if (WIFSIGNALED(wstatus))
    r.message = fmt::format("killed by signal {} ({}); {}", WTERMSIG(wstatus), strsignal(WTERMSIG(wstatus)), reason);
  else
    r.message = fmt::format("exit code {}: {}", WEXITSTATUS(wstatus), reason);
}

}  // namespace

SweepAxis parse_vary(const std::string& arg) {
  const std::size_t eq = arg.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == arg.size())
    throw InputError(fmt::format("--vary '{}': expected KEY=V1,V2,... (e.g. "
                                 "boundary.impact.velocity=10,20,30)", arg));
  SweepAxis a{arg.substr(0, eq), {}};
  std::string cur;
  int depth = 0;
  bool quoted = false;
  for (char c : arg.substr(eq + 1)) {
    if (c == '"') quoted = !quoted;
    if (!quoted && c == '[') ++depth;
    if (!quoted && c == ']') --depth;
    if (c == ',' && depth == 0 && !quoted) {
      a.values.push_back(cur), cur.clear();
      continue;
    }
    cur += c;
  }
  a.values.push_back(cur);
  for (const std::string& v : a.values)
    if (v.empty())
      throw InputError(fmt::format("--vary '{}': an empty value (two commas in a row, or a comma at "
                                   "an end)", arg));
  return a;
}

std::string sweep_run_name(const std::vector<SweepAxis>& axes, const std::vector<std::size_t>& pick) {
  std::string name;
  for (std::size_t k = 0; k < axes.size(); ++k) {
    const std::string& key = axes[k].key;
    const std::size_t dot = key.rfind('.');
    std::string part = dot == std::string::npos ? key : key.substr(dot + 1);
    part += '_';
    part += axes[k].values[pick[k]];
    for (char& c : part)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '+') c = '_';
    if (k > 0) name += "__";
    name += part;
  }
  return name;
}

int run_sweep(const SweepOptions& o) {
  if (o.axes.empty()) throw InputError("rupture sweep: give at least one --vary KEY=V1,V2,...");
  if (o.jobs < 1) throw InputError(fmt::format("-j {}: must be >= 1", o.jobs));
  for (const std::string& s : o.sets)
    if (s.rfind("solver.threads=", 0) == 0)
      throw InputError("--set solver.threads: the sweep splits the threads between its runs (-j, --threads)");
  // Every combination, first axis slowest; each validated before any run starts.
  std::vector<Run> runs;
  std::vector<std::size_t> pick(o.axes.size(), 0);
  std::map<std::string, std::size_t> names;
  while (true) {
    Run r;
    r.pick = pick;
    r.name = sweep_run_name(o.axes, pick);
    r.dir = o.dir + "/" + r.name;
    if (names.count(r.name))
      throw InputError(fmt::format("--vary: two combinations would share the directory '{}'; make the "
                                   "values distinct", r.name));
    names[r.name] = runs.size();
    std::vector<std::string> sets = o.sets;
    for (std::size_t k = 0; k < o.axes.size(); ++k) sets.push_back(o.axes[k].key + "=" + o.axes[k].values[pick[k]]);
    try {
      (void)load_case(o.case_path, sets);
    } catch (const InputError& e) {
      r.status = "invalid";
      r.message = e.what();
    }
    runs.push_back(std::move(r));
    std::size_t k = o.axes.size();
    while (k > 0 && ++pick[k - 1] == o.axes[k - 1].values.size()) pick[--k] = 0;
    if (k == 0) break;
  }
  fs::create_directories(o.dir);
  // Finished runs are not run again.
  for (Run& r : runs) {
    if (r.status != "pending") continue;
    std::map<std::string, std::string> keys = read_keys(r.dir + "/rupture.out");
    if (keys["status"] == "completed" && fs::exists(r.dir + "/run.json")) {
      r.status = "completed";
      r.keys = std::move(keys);
    }
  }
  const int hardware = int(std::max(1u, std::thread::hardware_concurrency()));
  const int threads = std::max(1, (o.threads > 0 ? o.threads : hardware) / o.jobs);
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  struct sigaction old_int {}, old_term {};
  sigaction(SIGINT, &sa, &old_int);
  sigaction(SIGTERM, &sa, &old_term);
  g_stop = 0;
  std::size_t next = 0, running = 0, done = 0;
  const std::size_t todo = std::size_t(std::count_if(runs.begin(), runs.end(),
                                                      [](const Run& r) { return r.status == "pending"; }));
  write_summary(o, runs);
  bool forwarded = false;
  while (true) {
    if (g_stop && !forwarded) {  // the runs write a checkpoint and stop (exit code 4)
      for (const Run& r : runs)
        if (r.pid > 0) kill(r.pid, SIGTERM);
      forwarded = true;
    }
    while (!g_stop && running < std::size_t(o.jobs) && next < runs.size()) {
      Run& r = runs[next++];
      if (r.status != "pending") continue;
      try {
        r.pid = start(o, r, threads);
      } catch (const std::exception& e) {  // e.g. its directory cannot be made: this run only
        r.status = "failed";
        r.message = e.what();
        write_summary(o, runs);
        continue;
      }
      r.status = "running";
      ++running;
      if (!o.quiet) fmt::print("started {} ({} of {})\n", r.name, done + running, todo);
    }
    if (running == 0) break;
    int wstatus = 0;
    const pid_t pid = waitpid(-1, &wstatus, 0);
    if (pid < 0) {
      if (errno != EINTR) break;
      continue;
    }
    for (Run& r : runs) {
      if (r.pid != pid) continue;
      finish(r, wstatus);
      --running, ++done;
      if (!o.quiet)
        fmt::print("{} {}{}\n", r.status, r.name, r.message.empty() ? "" : ": " + r.message);
      write_summary(o, runs);
    }
  }
  sigaction(SIGINT, &old_int, nullptr);
  sigaction(SIGTERM, &old_term, nullptr);
  for (Run& r : runs)
    if (r.status == "pending" && g_stop) r.status = "interrupted", r.message = "not started";
  write_summary(o, runs);
  const auto count = [&](const char* s) {
    return std::count_if(runs.begin(), runs.end(), [&](const Run& r) { return r.status == s; });
  };
  fmt::print("sweep={}\nruns={}\ncompleted={}\nfailed={}\ninvalid={}\ninterrupted={}\nsummary={}/summary.csv\n",
             o.dir, runs.size(), count("completed"), count("failed"), count("invalid"),
             count("interrupted"), o.dir);
  if (g_stop || count("interrupted") > 0) return 4;
  return count("completed") == std::ptrdiff_t(runs.size()) ? 0 : 1;
}

}  // namespace rupture

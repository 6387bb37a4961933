#include "runner/regress.h"

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstring>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <regex>
#include <unordered_map>
#include <sstream>

#include "regression/state_file.h"
#include "regression/topology_file.h"
#include "runner/probes.h"
#include "runner/session.h"

namespace sinew::runner {

namespace {

bool is_regular_file(const std::string& p) {
  struct stat st;
  return ::stat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

// The reference file for `suffix` ("..._mstate.txt"): gzipped or plain.
std::string find_reference(const std::string& base, const std::string& suffix) {
  if (is_regular_file(base + suffix + ".gz")) return base + suffix + ".gz";
  if (is_regular_file(base + suffix)) return base + suffix;
  return {};
}

std::string first_error(const Diagnostics& d) {
  for (const auto& m : d.messages())
    if (m.severity == Severity::error) return Diagnostics::format(m);
  return {};
}

// Scene value (§6): every node takes the comparer found in itself or its
// nearest ancestor; value = Σ E / count over those nodes.
template <class Probe, class ErrorOf>
double aggregate(Node& root, ErrorOf error_of) {
  double sum = 0;
  int count = 0;
  // In a DAG a node takes the comparer of its first parent that has one.
  std::unordered_map<const Node*, Probe*> taken;
  traverse(root, [&](Node& n, bool) {
    if (!n.activated.value()) return Visit::skip;
    Probe* mine = n.find_local<Probe>();
    for (const Node* p : n.parents())
      if (auto it = taken.find(p); !mine && it != taken.end()) mine = it->second;
    taken[&n] = mine;
    if (mine) {
      sum += error_of(*mine);
      ++count;
    }
    return Visit::descend;
  });
  return count == 0 ? std::numeric_limits<double>::quiet_NaN() : sum / count;
}

}  // namespace

RegressResult regress_scene(const regression::SceneList& list, const regression::SceneEntry& entry, TestKind kind,
                            const RegressOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  RegressResult r;
  r.scene = entry.scene;
  r.epsilon = entry.epsilon;
  const std::string scene = regression::scene_path(list, entry);
  const std::string base = regression::reference_base(list, entry);
  auto finish = [&](RegressResult& res) -> RegressResult& {
    res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return res;
  };
  if (!is_regular_file(base)) {
    r.reason = "no reference for this scene (" + base + " does not exist)";
    return finish(r);
  }
  SessionOptions so;
  so.data_paths = sofa_data_paths(options.data_root);
  so.data_paths.insert(so.data_paths.end(), options.extra_paths.begin(), options.extra_paths.end());
  Session session(scene, so);
  if (!session.ok()) {
    r.reason = first_error(session.diagnostics());
    if (r.reason.empty()) r.reason = "the scene could not be loaded";
    return finish(r);
  }
  Node& root = session.root();
  const double dt = root.dt.value();
  if (kind == TestKind::state) {
    for (const StateTarget& t : select_states(root, entry.mapped)) {
      const std::string file = find_reference(base, state_file_suffix(t));
      if (file.empty()) {
        r.reason = "missing reference file " + base + state_file_suffix(t) + ".gz";
        return finish(r);
      }
      std::string err;
      auto blocks = regression::read_state_file(file, &err);
      if (!blocks) {
        r.reason = "cannot read " + file + ": " + err;
        return finish(r);
      }
      t.node->add_object(std::make_unique<StateCompareProbe>(t.state, std::move(*blocks), dt));
      ++r.files;
    }
  } else {
    for (const TopologyTarget& t : select_topologies(root, entry.mapped)) {
      const std::string file = find_reference(base, topology_file_suffix(t));
      if (file.empty()) {
        r.reason = "missing reference file " + base + topology_file_suffix(t) + ".gz";
        return finish(r);
      }
      std::string err;
      auto blocks = regression::read_topology_file(file, &err);
      if (!blocks) {
        r.reason = "cannot read " + file + ": " + err;
        return finish(r);
      }
      t.node->add_object(std::make_unique<TopologyCompareProbe>(t.topology, std::move(*blocks)));
      ++r.files;
    }
  }
  for (int i = 0; i < entry.steps; ++i) {
    if (!session.step()) {
      r.reason = "step " + std::to_string(i) + ": " + first_error(session.diagnostics());
      return finish(r);
    }
  }
  if (kind == TestKind::state) {
    r.value = aggregate<StateCompareProbe>(root, [](StateCompareProbe& p) { return p.comparer().error(); });
    r.passed = regression::scene_passes(r.value, entry.epsilon);
    if (!r.passed) {
      std::ostringstream s;
      s << "error " << r.value << " > epsilon " << entry.epsilon;
      r.reason = s.str();
    }
  } else {
    r.value = aggregate<TopologyCompareProbe>(
        root, [](TopologyCompareProbe& p) { return static_cast<double>(p.comparer().total_error()); });
    r.passed = r.files == 0 || r.value == 0;
    if (!r.passed) r.reason = "topology differs (" + std::to_string(static_cast<long long>(r.value)) + ")";
  }
  return finish(r);
}

RegressResult regress_scene_isolated(const regression::SceneList& list, const regression::SceneEntry& entry,
                                     TestKind kind, const RegressOptions& options) {
  if (!options.isolate) return regress_scene(list, entry, kind, options);
  int fds[2];
  if (::pipe(fds) != 0) return regress_scene(list, entry, kind, options);
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    return regress_scene(list, entry, kind, options);
  }
  if (pid == 0) {
    ::close(fds[0]);
    ::alarm(static_cast<unsigned>(options.time_limit));
    RegressResult r = regress_scene(list, entry, kind, options);
    std::ostringstream s;
    s.precision(17);
    s << r.passed << '\n' << r.value << '\n' << r.files << '\n' << r.seconds << '\n' << r.reason;
    const std::string text = s.str();
    std::size_t off = 0;
    while (off < text.size()) {
      const ssize_t n = ::write(fds[1], text.data() + off, text.size() - off);
      if (n <= 0) break;
      off += static_cast<std::size_t>(n);
    }
    ::close(fds[1]);
    ::_exit(0);
  }
  ::close(fds[1]);
  std::string text;
  char buf[4096];
  for (;;) {
    const ssize_t n = ::read(fds[0], buf, sizeof buf);
    if (n <= 0) break;
    text.append(buf, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  RegressResult r;
  r.scene = entry.scene;
  r.epsilon = entry.epsilon;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    r.reason = sig == SIGALRM ? "time limit exceeded" : std::string("crashed: ") + strsignal(sig);
    return r;
  }
  if (text.empty()) {
    r.reason = "no result from the child process";
    return r;
  }
  // Lines: passed, value (strtod reads "nan"), files, seconds, then the reason.
  std::vector<std::string> lines;
  std::size_t start = 0;
  for (int i = 0; i < 4; ++i) {
    const std::size_t nl = text.find('\n', start);
    lines.push_back(text.substr(start, nl - start));
    start = nl == std::string::npos ? text.size() : nl + 1;
  }
  r.passed = lines[0] == "1";
  r.value = std::strtod(lines[1].c_str(), nullptr);
  r.files = std::atoi(lines[2].c_str());
  r.seconds = std::strtod(lines[3].c_str(), nullptr);
  r.reason = text.substr(start);
  return r;
}

}  // namespace sinew::runner

namespace sinew::runner {

int regress_list(const RegressListArgs& args) {
  const std::string& data = args.options.data_root;
  std::string err;
  // SOFA's lists point at $REGRESSION_DIR/references/examples: the data folder plays that role.
  regression::ListEnvironment env = regression::ListEnvironment::from_process();
  if (!env.regression_dir) env.regression_dir = data;
  auto list = regression::read_scene_list(args.list_file, env, &err);
  if (!list) {
    std::fprintf(stderr, "sinew regress: cannot read %s: %s\n", args.list_file.c_str(), err.c_str());
    return 2;
  }
  for (const auto& p : list->problems)
    std::fprintf(stderr, "sinew regress: %s: %s\n", args.list_file.c_str(), p.c_str());
  const TestKind kind = args.list_file.find("Topology") != std::string::npos ? TestKind::topology : TestKind::state;
  std::regex re;
  if (!args.filter.empty()) {
    try {
      re = std::regex(args.filter);
    } catch (const std::regex_error& e) {
      std::fprintf(stderr, "sinew regress: bad --filter: %s\n", e.what());
      return 2;
    }
  }
  int passed = 0, failed = 0;
  for (const auto& entry : list->scenes) {
    if (!args.filter.empty() && !std::regex_search(entry.scene, re)) continue;
    const RegressResult r = regress_scene_isolated(*list, entry, kind, args.options);
    (r.passed ? passed : failed)++;
    std::printf("%s  %-90s value %-12.6g eps %-8g %2d files %7.2fs%s%s\n", r.passed ? "PASS" : "FAIL",
                entry.scene.c_str(), r.value, entry.epsilon, r.files, r.seconds, r.reason.empty() ? "" : "  ",
                r.reason.c_str());
    std::fflush(stdout);
  }
  std::printf("%d passed, %d failed\n", passed, failed);
  return failed == 0 ? 0 : 1;
}

}  // namespace sinew::runner

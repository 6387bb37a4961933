// Bad-input audit, whole scenes (data-driven): `sinew check` on every scene of
// SOFA's SCENES.tsv, then on fuzzed variants written to a temp folder (an
// attribute deleted or corrupted, a tag renamed, the scene or one of its mesh
// files truncated or filled with garbage), and `sinew run -n 2` on variants of
// the scenes that load. Each run is a separate process under a time limit:
// no crash, no hang, and every failure reported with a file:line message.
//
// Skips with a message when the SOFA data folder (SINEW_DATA_DIR, or the
// SINEW_SOFA_DATA environment variable) or the sinew executable is absent.
// SINEW_FUZZ_SEED changes the seed (default fixed: reproducible); SINEW_FUZZ_VERBOSE=1 lists the variants.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <regex>
#include <sstream>

#include "test_scene.h"
#include "test_paths.h"

namespace fs = std::filesystem;
using sinew::test::TempDir;

namespace {

std::string data_root() {
  if (const char* env = std::getenv("SINEW_SOFA_DATA"); env && fs::is_directory(env)) return env;
#ifdef SINEW_DATA_DIR
  if (fs::is_directory(SINEW_DATA_DIR)) return SINEW_DATA_DIR;
#endif
  return {};
}

std::string sinew_exe() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  const fs::path p = self.parent_path() / "sinew";
  return fs::exists(p) ? p.string() : std::string();
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

struct RunResult {
  int status = 0;  // exit code; 124/137: time limit; > 128: killed by a signal
  std::string output;
};

RunResult run_sinew(const std::string& exe, const std::string& args, const std::string& data, const fs::path& out) {
  const std::string cmd = "SINEW_SOFA_DATA=" + quote(data) + " timeout -s KILL 20 " + quote(exe) + " " + args +
                          " > " + quote(out.string()) + " 2>&1 < /dev/null";
  const int st = std::system(cmd.c_str());
  RunResult r;
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + (WIFSIGNALED(st) ? WTERMSIG(st) : 0);
  r.output = read_text(out);
  return r;
}

// Problems with one run: crash, hang, or a failure without a located error.
std::string judge(const RunResult& r, const std::string& what) {
  if (r.status == 124 || r.status == 137) return what + ": no answer within 20 s (hang?)";
  if (r.status != 0 && r.status != 1)
    return what + ": crashed (status " + std::to_string(r.status) + ")\n" + r.output.substr(0, 2000);
  if (r.status == 0) return {};
  static const std::regex located(R"((^|\n)[^\n:]+:[0-9]+: error: )");
  static const std::regex any_error(R"((^|\n)([^\n]*)error: )");
  if (!std::regex_search(r.output, located))
    return what + ": failed without any file:line error\n" + r.output.substr(0, 2000);
  // Every error line must name a file and a line.
  std::istringstream in(r.output);
  for (std::string line; std::getline(in, line);) {
    const auto pos = line.find("error: ");
    if (pos == std::string::npos || line.rfind("sinew:", 0) == 0) continue;
    static const std::regex loc(R"(^[^ :]+:[0-9]+: error: )");
    if (!std::regex_search(line, loc)) return what + ": error without file:line: " + line;
  }
  return {};
}

struct SceneEntry {
  std::string rel;  // relative to examples/
};

std::vector<SceneEntry> read_scene_list(const std::string& data) {
  std::vector<SceneEntry> out;
  std::ifstream in(data + "/SCENES.tsv");
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    out.push_back({line.substr(0, line.find('\t'))});
  }
  return out;
}

// ----------------------------------------------------------------- mutations
struct Tag {
  std::size_t begin, end;  // the whole "<Name ...>" span
  std::string name;
};
struct Attr {
  std::size_t name_begin, value_begin, value_end;  // value without its quotes
  std::string name, value;
};

std::vector<Tag> tags_of(const std::string& xml) {
  std::vector<Tag> out;
  static const std::regex re(R"(<([A-Za-z_][A-Za-z0-9_.:-]*)[^<>]*>)");
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), re); it != std::sregex_iterator(); ++it)
    out.push_back({static_cast<std::size_t>(it->position(0)),
                   static_cast<std::size_t>(it->position(0) + it->length(0)), (*it)[1].str()});
  return out;
}

// Viewer-only and plugin declarations: mutating them tests little.
bool boring(const std::string& tag) {
  return tag == "RequiredPlugin" || tag == "VisualStyle" || tag == "DefaultVisualManagerLoop" ||
         tag == "InteractiveCamera" || tag == "BackgroundSetting" || tag == "LightManager";
}

std::vector<Attr> attrs_of(const std::string& xml) {
  std::vector<Attr> out;
  for (const Tag& t : tags_of(xml)) {
    if (boring(t.name)) continue;
    const std::string body = xml.substr(t.begin, t.end - t.begin);
    static const std::regex re(R"re(\s([A-Za-z_][A-Za-z0-9_.:-]*)\s*=\s*"([^"]*)")re");
    for (auto it = std::sregex_iterator(body.begin(), body.end(), re); it != std::sregex_iterator(); ++it) {
      const std::size_t nb = t.begin + static_cast<std::size_t>(it->position(1));
      const std::size_t vb = t.begin + static_cast<std::size_t>(it->position(2));
      out.push_back({nb, vb, vb + static_cast<std::size_t>(it->length(2)), (*it)[1].str(), (*it)[2].str()});
    }
  }
  return out;
}

struct Variant {
  std::string text, what;
};

const char* kGarbage[] = {"", "abc", "nan", "-1", "1e400", "0", "-1e9", "1 2", "@nowhere", "999999999", "-0.5",
                          "inf", "1,5", "@../../.x", "0 0 0 0 0 0 0"};
const char* kTags[] = {"MechanicalObject", "UniformMass", "TetrahedronFEMForceField", "MeshOBJLoader",
                       "EulerImplicitSolver", "CGLinearSolver", "FixedProjectiveConstraint", "BarycentricMapping",
                       "Node", "MeshTopology", "SparseLDLSolver", "SpringForceField", "HexahedronFEMForceField"};

// A mesh file the scene refers to (filename=...), resolved like SOFA's data paths.
std::optional<fs::path> resolve_mesh(const std::string& value, const fs::path& scene_dir, const std::string& data) {
  if (value.empty() || value[0] == '@') return std::nullopt;
  for (const fs::path& base : {scene_dir, fs::path(data) / "share", fs::path(data) / "examples"}) {
    std::error_code ec;
    const fs::path p = base / value;
    if (fs::is_regular_file(p, ec) && fs::file_size(p, ec) < (8u << 20)) return p;
  }
  return std::nullopt;
}

Variant mutate(const std::string& xml, std::mt19937& rng, const fs::path& scene_dir, const std::string& data,
               const TempDir& tmp, const std::string& stem) {
  auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
  const auto attrs = attrs_of(xml);
  std::vector<Tag> tags;
  for (const Tag& t : tags_of(xml))
    if (!boring(t.name)) tags.push_back(t);
  std::vector<const Attr*> files;
  for (const Attr& a : attrs)
    if ((a.name == "filename" || a.name == "fileMesh" || a.name == "fileTopology") &&
        resolve_mesh(a.value, scene_dir, data))
      files.push_back(&a);
  for (int attempt = 0; attempt < 10; ++attempt) {
    const std::size_t kind = pick(6);
    if (kind == 0 && !attrs.empty()) {  // delete an attribute
      const Attr& a = attrs[pick(attrs.size())];
      std::string t = xml;
      t.erase(a.name_begin, a.value_end + 1 - a.name_begin);
      return {t, "attribute '" + a.name + "' deleted"};
    }
    if (kind == 1 && !attrs.empty()) {  // corrupt an attribute value
      const Attr& a = attrs[pick(attrs.size())];
      const std::string g = kGarbage[pick(std::size(kGarbage))];
      std::string t = xml;
      t.replace(a.value_begin, a.value_end - a.value_begin, g);
      return {t, "attribute '" + a.name + "' = \"" + g + "\""};
    }
    if (kind == 2 && tags.size() > 1) {  // wrong tag (unknown or another component), not the root
      const Tag& tg = tags[1 + pick(tags.size() - 1)];
      const std::string nn = pick(2) ? tg.name + "x" : kTags[pick(std::size(kTags))];
      std::string t = xml;
      t.replace(tg.begin + 1, tg.name.size(), nn);
      // Keep the closing tag consistent when the element has a body.
      if (const auto close = t.find("</" + tg.name + ">", tg.begin); close != std::string::npos)
        t.replace(close + 2, tg.name.size(), nn);
      return {t, "tag <" + tg.name + "> -> <" + nn + ">"};
    }
    if (kind == 3 && !xml.empty()) {  // truncated scene
      const std::size_t cut = pick(xml.size());
      return {xml.substr(0, cut), "scene truncated at byte " + std::to_string(cut)};
    }
    if ((kind == 4 || kind == 5) && !files.empty()) {  // truncated mesh / garbage numbers in the mesh
      const Attr& a = *files[pick(files.size())];
      const fs::path src = *resolve_mesh(a.value, scene_dir, data);
      std::string body = read_text(src);
      std::string what;
      if (kind == 4) {
        const std::size_t cut = body.empty() ? 0 : pick(body.size());
        body.resize(cut);
        what = "mesh " + a.value + " truncated at byte " + std::to_string(cut);
      } else {
        static const std::regex num(R"(-?[0-9]+(\.[0-9]*)?([eE][-+]?[0-9]+)?)");
        std::vector<std::pair<std::size_t, std::size_t>> nums;
        const std::size_t limit = std::min<std::size_t>(body.size(), 200000);
        const std::string head = body.substr(0, limit);
        for (auto it = std::sregex_iterator(head.begin(), head.end(), num); it != std::sregex_iterator(); ++it)
          nums.emplace_back(it->position(0), it->length(0));
        if (nums.empty()) continue;
        const auto [p, n] = nums[pick(nums.size())];
        const std::string g = pick(2) ? "x1" : "99999999";
        body.replace(p, n, g);
        what = "mesh " + a.value + ": number at byte " + std::to_string(p) + " -> " + g;
      }
      const std::string copy = tmp.write(stem + "_" + src.filename().string(), body);
      std::string t = xml;
      t.replace(a.value_begin, a.value_end - a.value_begin, copy);
      return {t, what};
    }
  }
  return {xml + "<", "trailing '<'"};
}

}  // namespace

TEST(BadInputScenes, CheckEverySofaSceneAndFuzzedVariants) {
  const std::string data = data_root();
  if (data.empty() || !fs::exists(data + "/SCENES.tsv"))
    GTEST_SKIP() << "SOFA data folder not found (set SINEW_SOFA_DATA or SINEW_DATA_DIR): scene audit skipped";
  const std::string exe = sinew_exe();
  if (exe.empty()) GTEST_SKIP() << "the sinew executable is not beside the test binary: scene audit skipped";

  const auto scenes = read_scene_list(data);
  ASSERT_FALSE(scenes.empty());
  unsigned seed = 20261122;
  if (const char* s = std::getenv("SINEW_FUZZ_SEED")) seed = static_cast<unsigned>(std::strtoul(s, nullptr, 10));
  std::mt19937 rng(seed);
  TempDir tmp;
  const fs::path out = fs::path(tmp.dir()) / "out.txt";
  const auto t0 = std::chrono::steady_clock::now();
  const double budget = 45.0;  // seconds: the fuzzing stops early rather than run long
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };

  std::vector<std::string> problems;
  std::vector<bool> loads(scenes.size());
  // 1. The scenes as they are.
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const fs::path p = fs::path(data) / "examples" / scenes[i].rel;
    const RunResult r = run_sinew(exe, "check " + quote(p.string()), data, out);
    loads[i] = r.status == 0;
    if (auto j = judge(r, scenes[i].rel); !j.empty()) problems.push_back(j);
  }
  // 2. Fuzzed variants, round-robin over the scenes, until the budget is spent.
  int variants = 0;
  const int rounds = 8;
  for (int round = 0; round < rounds && elapsed() < budget; ++round) {
    for (std::size_t i = 0; i < scenes.size() && elapsed() < budget; ++i) {
      const fs::path src = fs::path(data) / "examples" / scenes[i].rel;
      const std::string xml = read_text(src);
      const std::string stem = "v" + std::to_string(round) + "_" + std::to_string(i);
      const Variant v = mutate(xml, rng, src.parent_path(), data, tmp, stem);
      const std::string file = tmp.write(stem + "_" + src.filename().string(), v.text);
      const std::string args = " --data-path " + quote(src.parent_path().string()) + " " + quote(file);
      // Variants of scenes that load are also stepped; the others only checked.
      const std::string cmd = loads[i] ? "run -n 2 --hideProgressBar" + args : "check" + args;
      const RunResult r = run_sinew(exe, cmd, data, out);
      ++variants;
      if (std::getenv("SINEW_FUZZ_VERBOSE"))
        std::printf("[ variant  ] status %d  %s [%s]\n", r.status, scenes[i].rel.c_str(), v.what.c_str());
      if (auto j = judge(r, scenes[i].rel + " [" + v.what + "] (" + file + ")"); !j.empty()) {
        problems.push_back(j);
        // Keep the failing variant for the report.
        std::error_code ec;
        fs::create_directories("/tmp/sinew_badinput_failures", ec);
        fs::copy_file(file, "/tmp/sinew_badinput_failures/" + fs::path(file).filename().string(),
                      fs::copy_options::overwrite_existing, ec);
      }
    }
  }
  std::string all;
  for (const auto& p : problems) all += p + "\n\n";
  EXPECT_TRUE(problems.empty()) << problems.size() << " problem(s) over " << scenes.size() << " scenes and "
                                << variants << " variants (seed " << seed << "):\n"
                                << all;
  std::printf("[ audit    ] %zu scenes, %d fuzzed variants, %.1f s, seed %u\n", scenes.size(), variants, elapsed(),
              seed);
}

// One failing scene never takes the others down: `sinew check bad good` still reports the good one ok.
TEST(BadInputScenes, OneFailingSceneDoesNotStopTheOthers) {
  const std::string exe = sinew_exe();
  if (exe.empty()) GTEST_SKIP() << "the sinew executable is not beside the test binary";
  TempDir tmp;
  const std::string bad = tmp.write("bad.scn", R"(<Node name="root">
  <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0  0 0 1"/>
  <MeshTopology tetrahedra="0 1 2 3  0 1 2 9"/>
  <UniformMass totalMass="1"/>
  <TetrahedronFEMForceField name="fem"/>
</Node>)");
  const std::string good = tmp.write("good.scn", R"(<Node name="root">
  <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0  0 0 1"/>
  <MeshTopology tetrahedra="0 1 2 3"/>
  <UniformMass totalMass="1"/>
  <TetrahedronFEMForceField name="fem"/>
</Node>)");
  const RunResult r =
      run_sinew(exe, "check " + quote(bad) + " " + quote(good), tmp.dir(), fs::path(tmp.dir()) / "out.txt");
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("bad.scn:5: error: component 'fem' (TetrahedronFEMForceField): element 1"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find(good + ": ok"), std::string::npos) << r.output;
}

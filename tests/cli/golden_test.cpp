// Golden hashes, found by data: every tests/golden/<scene>/<name>.toml must reproduce its committed
// hashes bit for bit on every backend. The CPU backend is held to <name>.framemd5; the GL backend,
// on both its platforms (EGL and OSMesa drive the same llvmpipe), to <name>.gl.framemd5 where the
// backends differ (a mesh pass: fur, museum), else to the CPU's file (the GLSL twin renders the
// same bits on every Mesa). A <name>.gl.framemd5 names the Mesa it was made on ("#mesa: 22.3"):
// rasterisers of other releases need not give its bits, so there, where the hashes differ, the
// GL frames are held to the CPU's by Filament's rule (`verify --tolerance filament`), the agreement
// rule of the backends' own tests, instead of one file per Mesa release. After an intended change
// of the picture: scripts/regen-golden.sh, look at the frames, commit. A user's shader's goldens
// (tests/golden/shader_<example>/) run on GL only; its <name>.framemd5 is GL's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <tuple>
#include <vector>

#include "cli/harness.h"

namespace sdfreel::test {
namespace {

namespace fs = std::filesystem;

struct Golden {
  std::string scene, name;  // tests/golden/<scene>/<name>.toml
  std::string path(const std::string& ext) const {
    return source_path("tests/golden/" + scene + "/" + name + ext);
  }
};

std::vector<Golden> goldens() {
  std::vector<Golden> all;
  for (const auto& dir : fs::directory_iterator(source_path("tests/golden"))) {
    if (!dir.is_directory()) continue;
    for (const auto& f : fs::directory_iterator(dir.path()))
      if (f.path().extension() == ".toml")
        all.push_back({dir.path().filename().string(), f.path().stem().string()});
  }
  std::sort(all.begin(), all.end(), [](const Golden& a, const Golden& b) {
    return std::tie(a.scene, a.name) < std::tie(b.scene, b.name);
  });
  return all;
}

// "25.0" of the Mesa the GL render's manifest names ("" when it names none).
std::string mesa_release(const std::string& manifest, const std::string& backend) {
  const auto j = nlohmann::json::parse(read_file(manifest));
  const std::string key = backend + ".mesa";
  if (!j.at("versions").contains(key)) return "";
  const std::string v = j["versions"][key];
  const size_t second = v.find('.', v.find('.') + 1);
  return v.substr(0, second);
}

// The file a backend is held to: the CPU's; for GL, <name>.gl.framemd5 where the backends
// differ, else the CPU's.
std::string golden_file(const Golden& g, const std::string& backend) {
  if (backend == "cpu" || !fs::exists(g.path(".gl.framemd5"))) return g.path(".framemd5");
  return g.path(".gl.framemd5");
}

// The Mesa release a golden file was made on ("#mesa: 22.3"), "" where it names none.
std::string made_on_mesa(const std::string& framemd5) {
  const std::string key = "\n#mesa: ";
  const size_t at = ("\n" + framemd5).find(key);
  if (at == std::string::npos) return "";
  const size_t from = at + key.size() - 1;
  return framemd5.substr(from, framemd5.find('\n', from) - from);
}

class GoldenFrames : public ::testing::TestWithParam<std::tuple<Golden, std::string>> {};

TEST_P(GoldenFrames, MatchCommittedHashes) {
  const Golden& g = std::get<0>(GetParam());
  const std::string& backend = std::get<1>(GetParam());
  const std::string dir = scratch_dir("golden-" + g.scene + "-" + g.name + "-" + backend);
  // In place, so that a user's shader is found beside the timeline where it names it.
  const RunResult r =
      run_sdfreel("render '" + g.path(".toml") + "' --out out --backend " + backend, dir);
  // A machine (or build) without this GL platform cannot run it at all: nothing to compare.
  if (r.status != 0 &&
      (r.err.find("cannot start the " + backend + " backend") != std::string::npos ||
       r.err.find("GL backend is not built") != std::string::npos))
    GTEST_SKIP() << r.err;
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string file = golden_file(g, backend);
  const std::string want = read_file(file);
  ASSERT_FALSE(want.empty()) << "no committed golden file " << file
                             << "; run scripts/regen-golden.sh";
  const std::string made_on = made_on_mesa(want);
  const std::string here = mesa_release(dir + "/out/manifest.json", backend);
  const bool same =
      framemd5_data_lines(read_file(dir + "/out/frames.framemd5")) == framemd5_data_lines(want);
  if (!same && !made_on.empty() && made_on != here) {
    // Another Mesa's rasteriser: hold these GL frames to the CPU's by Filament's rule.
    const RunResult cpu =
        run_sdfreel("render '" + g.path(".toml") + "' --out cpu --backend cpu", dir);
    ASSERT_EQ(cpu.status, 0) << cpu.err;
    const RunResult v = run_sdfreel("verify '" + g.path(".toml") +
                                        "' --manifest cpu/manifest.json --tolerance filament "
                                        "--out agreement --backend " +
                                        backend,
                                    dir);
    std::printf("%s was made on Mesa %s; on Mesa %s the GL frames are held to the CPU's:\n%s",
                file.c_str(), made_on.c_str(), here.c_str(), (v.out + v.err).c_str());
    EXPECT_EQ(v.status, 0) << v.out << v.err;
    return;
  }
  EXPECT_EQ(framemd5_data_lines(read_file(dir + "/out/frames.framemd5")), framemd5_data_lines(want))
      << "frames differ from " << file << "; if the change is intended, run "
      << "scripts/regen-golden.sh and look at the frames before committing";
}

std::string golden_name(const ::testing::TestParamInfo<std::tuple<Golden, std::string>>& i) {
  const Golden& g = std::get<0>(i.param);
  return g.scene + "_" + g.name + "_" + std::get<1>(i.param);
}

// Every golden on every backend, but a user's shader (tests/golden/shader_*) on GL only: it has
// no CPU twin, and its <name>.framemd5 is the GL's.
std::vector<std::tuple<Golden, std::string>> golden_runs() {
  std::vector<std::tuple<Golden, std::string>> runs;
  for (const Golden& g : goldens())
    for (const char* backend : {"cpu", "egl", "osmesa"})
      if (g.scene.rfind("shader_", 0) != 0 || std::string(backend) != "cpu")
        runs.emplace_back(g, backend);
  return runs;
}

INSTANTIATE_TEST_SUITE_P(Golden, GoldenFrames, ::testing::ValuesIn(golden_runs()), golden_name);

}  // namespace
}  // namespace sdfreel::test

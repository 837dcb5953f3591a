// `sdfreel slurm` without a cluster: the dry-run scripts, run by hand the way Slurm runs them, a
// fake sbatch, and bad options. tests/slurm/ submits to a real Slurm.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <sstream>

#include "cli/harness.h"

namespace sdfreel::test {
namespace {

namespace fs = std::filesystem;

// The dry run's "# ---- NAME" sections by NAME (a script path, or "submit with").
std::map<std::string, std::string> sections(const std::string& out) {
  std::map<std::string, std::string> s;
  std::stringstream ss(out);
  std::string line, name;
  while (std::getline(ss, line)) {
    if (line.rfind("# ---- ", 0) == 0) {
      name = line.substr(7);
      s[name];
    } else if (!name.empty()) {
      s[name] += line + "\n";
    }
  }
  return s;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

std::vector<std::string> entries(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::recursive_directory_iterator(dir)) names.push_back(e.path().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(Slurm, DryRunPrintsTheArrayAndEncodeScriptsAndWritesNothing) {
  const std::string dir = scratch_dir("slurm-dry-run");
  write_file(dir + "/t.toml", small_timeline(6));
  const auto before = entries(dir);
  const RunResult r = run_sdfreel(
      "slurm t.toml --tasks 3 --partition render --time 1:30:00 --cpus-per-task 2 "
      "--sbatch-arg=--account=vfx --sbatch-arg=--qos=high --backend osmesa --out farm --dry-run",
      dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(entries(dir), before);

  const std::string out = fs::canonical(dir).string() + "/farm";
  const auto s = sections(r.out);
  ASSERT_EQ(s.size(), 3u) << r.out;
  const std::string& array = s.at(out + "/slurm/render.sh");
  for (const char* line :
       {"#SBATCH --array=0-2\n", "#SBATCH --partition=render\n", "#SBATCH --time=1:30:00\n",
        "#SBATCH --cpus-per-task=2\n", "#SBATCH --account=vfx\n", "#SBATCH --qos=high\n",
        "#SBATCH --open-mode=append\n"})
    EXPECT_TRUE(contains(array, line)) << line << " in\n" << array;
  EXPECT_TRUE(contains(array, "#SBATCH --output=" + out + "/logs/task-%a.log\n")) << array;
  EXPECT_TRUE(contains(array, "render '" + fs::canonical(dir).string() + "/t.toml' --out '" + out +
                                  "' --shard \"${SLURM_ARRAY_TASK_ID}/3\" --no-video --resume "
                                  "--threads 2 '--backend' 'osmesa'\n"))
      << array;
  // Every #SBATCH line precedes the first command, or sbatch ignores it.
  EXPECT_LT(array.rfind("#SBATCH"), array.find("\necho "));

  const std::string& encode = s.at(out + "/slurm/encode.sh");
  EXPECT_TRUE(contains(encode, "#SBATCH --output=" + out + "/logs/encode.log\n")) << encode;
  EXPECT_TRUE(contains(encode, "#SBATCH --partition=render\n")) << encode;
  EXPECT_TRUE(
      contains(encode, "encode '" + out + "' -o '" + out + "/small.mkv' '--codec' 'ffv1'\n"))
      << encode;
  EXPECT_FALSE(contains(encode, "--array")) << encode;

  EXPECT_EQ(s.at("submit with"), "sbatch --parsable " + out +
                                     "/slurm/render.sh\nsbatch --parsable "
                                     "--dependency=afterok:ARRAY_JOB_ID " +
                                     out + "/slurm/encode.sh\n");
}

TEST(Slurm, TheScriptsRunAsSlurmWouldRenderTheSameFramesAsOneRender) {
  const std::string dir = scratch_dir("slurm-by-hand");
  write_file(dir + "/t.toml", small_timeline(5));
  ASSERT_EQ(run_sdfreel("render t.toml --out plain", dir).status, 0);
  const RunResult r = run_sdfreel("slurm t.toml --tasks 3 --out farm --dry-run", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto s = sections(r.out);
  const std::string out = fs::canonical(dir).string() + "/farm";
  write_file(dir + "/render.sh", s.at(out + "/slurm/render.sh"));
  write_file(dir + "/encode.sh", s.at(out + "/slurm/encode.sh"));

  // The encode refuses to run before every shard is there.
  for (int task : {2, 0}) {
    const RunResult t = run("SLURM_ARRAY_TASK_ID=" + std::to_string(task) + " sh render.sh", dir);
    ASSERT_EQ(t.status, 0) << t.err;
    EXPECT_TRUE(contains(t.err, "sdfreel: task " + std::to_string(task) + "/3")) << t.err;
  }
  EXPECT_EQ(run("sh encode.sh", dir).status, 1);
  EXPECT_FALSE(fs::exists(out + "/small.mkv"));
  const RunResult last = run("SLURM_ARRAY_TASK_ID=1 sh render.sh", dir);
  ASSERT_EQ(last.status, 0) << last.err;
  EXPECT_TRUE(contains(last.err, "frame 2/2 done in ")) << last.err;  // parseable progress
  const RunResult enc = run("sh encode.sh", dir);
  ASSERT_EQ(enc.status, 0) << enc.err;

  EXPECT_EQ(read_file(out + "/frames.framemd5"), read_file(dir + "/plain/frames.framemd5"));
  EXPECT_TRUE(fs::exists(out + "/small.mkv"));
  // A requeued task keeps the frames already written and renders none again.
  const RunResult again = run("SLURM_ARRAY_TASK_ID=1 sh render.sh", dir);
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_TRUE(contains(again.err, " kept (frame")) << again.err;
  EXPECT_FALSE(contains(again.err, "done in")) << again.err;
}

TEST(Slurm, ATaskFailsWhenAFrameOfItsShardCannotBeWritten) {
  const std::string dir = scratch_dir("slurm-task-fails");
  write_file(dir + "/t.toml", small_timeline(4));
  const RunResult r = run_sdfreel("slurm t.toml --tasks 2 --out farm --dry-run", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string out = fs::canonical(dir).string() + "/farm";
  write_file(dir + "/render.sh", sections(r.out).at(out + "/slurm/render.sh"));
  // A folder where frame 3's PNG goes: its write (rename) fails.
  fs::create_directories(out + "/frames/00003.png");
  EXPECT_EQ(run("SLURM_ARRAY_TASK_ID=0 sh render.sh", dir).status, 0);
  const RunResult t = run("SLURM_ARRAY_TASK_ID=1 sh render.sh", dir);
  EXPECT_EQ(t.status, 1) << t.err;
  EXPECT_EQ(framemd5_data_lines(read_file(out + "/frames.framemd5")).size(), 3u);
}

TEST(Slurm, SubmitsTheArrayThenTheEncodeAfterItWithSbatch) {
  const std::string dir = scratch_dir("slurm-fake-sbatch");
  write_file(dir + "/t.toml", small_timeline(4));
  // A stand-in sbatch: records its arguments, answers like --parsable (job id, maybe ;cluster).
  fs::create_directories(dir + "/bin");
  write_file(dir + "/bin/sbatch",
             "#!/bin/sh\necho \"$*\" >> \"$SBATCH_CALLS\"\n"
             "n=$(wc -l < \"$SBATCH_CALLS\")\necho \"$((40 + n));cluster\"\n");
  fs::permissions(dir + "/bin/sbatch", fs::perms::owner_all);
  const std::string env = "PATH=\"" + dir + "/bin:$PATH\" SBATCH_CALLS=\"" + dir + "/calls\" ";
  const RunResult sub =
      run(env + "'" + SDFREEL_BINARY + "' slurm t.toml --tasks 2 --out farm", dir);
  ASSERT_EQ(sub.status, 0) << sub.err;
  EXPECT_EQ(sub.out, "array_job=41\nencode_job=42\n");
  const std::string out = fs::canonical(dir).string() + "/farm";
  EXPECT_EQ(read_file(dir + "/calls"), "--parsable " + out +
                                           "/slurm/render.sh\n--parsable --dependency=afterok:41 " +
                                           out + "/slurm/encode.sh\n");
  EXPECT_TRUE(fs::is_directory(out + "/logs"));
  EXPECT_TRUE(contains(read_file(out + "/slurm/render.sh"), "#SBATCH --array=0-1\n"));
  EXPECT_TRUE(contains(read_file(out + "/slurm/encode.sh"), " encode '" + out + "'"));
}

TEST(Slurm, WithoutSbatchFailsAndWritesNothing) {
  const std::string dir = scratch_dir("slurm-no-sbatch");
  write_file(dir + "/t.toml", small_timeline(4));
  fs::create_directories(dir + "/empty-bin");
  const auto before = entries(dir);
  const RunResult r =
      run("PATH=\"" + dir + "/empty-bin\" '" + SDFREEL_BINARY + "' slurm t.toml --tasks 2", dir);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_TRUE(contains(r.err, "sbatch")) << r.err;
  EXPECT_EQ(entries(dir), before);
}

TEST(Slurm, BadOptionsAreExit2AndWriteNothing) {
  const std::string dir = scratch_dir("slurm-bad-options");
  write_file(dir + "/t.toml", small_timeline(4));
  write_file(dir + "/bad.toml", "[video]\nscene = \"sdf_morph\"\nfps = \"fast\"\n");
  // Should a bad option get through, this sbatch leaves a trace instead of submitting anything.
  fs::create_directories(dir + "/bin");
  write_file(dir + "/bin/sbatch", "#!/bin/sh\ntouch \"$(dirname \"$0\")/../sbatch-ran\"\necho 1\n");
  fs::permissions(dir + "/bin/sbatch", fs::perms::owner_all);
  const auto before = entries(dir);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"t.toml", "--tasks"},
      {"t.toml --tasks 0", "--tasks"},
      {"t.toml --tasks 5", "--tasks 5"},  // more tasks than frames
      {"t.toml --tasks 2 --time soon", "--time"},
      {"t.toml --tasks 2 --time 1:2:3:4", "--time"},
      {"t.toml --tasks 2 --partition 'a b'", "--partition"},
      {"t.toml --tasks 2 --sbatch-arg=qos", "--sbatch-arg"},
      {"t.toml --tasks 2 --sbatch-arg=\"$(printf -- '--qos=a\\n#SBATCH --x')\"", "control"},
      {"t.toml --tasks 2 --out 'with space'", "blanks"},
      {"t.toml --tasks 2 --out 'a%b'", "%"},
      {"t.toml --tasks 2 --cpus-per-task 0", "--cpus-per-task"},
      {"t.toml --tasks 2 --backend vulkan", "--backend"},
      {"t.toml --tasks 2 --resolution 64", "--resolution"},
      {"bad.toml --tasks 2", "bad.toml:3:"},
      {"missing.toml --tasks 2", "missing.toml"},
  };
  // Submission mode, where a check that let a bad option through would write and submit; one case
  // with --dry-run, which checks the same options first.
  for (const auto& [args, message] : cases) {
    const RunResult r =
        run("PATH=\"" + dir + "/bin:$PATH\" '" + SDFREEL_BINARY + "' slurm " + args, dir);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
    EXPECT_TRUE(contains(r.err, message)) << args << ": " << r.err;
    EXPECT_EQ(r.out, "") << args;
  }
  const RunResult dry = run_sdfreel("slurm t.toml --tasks 2 --time soon --dry-run", dir);
  EXPECT_EQ(dry.status, 2) << dry.err;
  EXPECT_EQ(dry.out, "");
  EXPECT_EQ(entries(dir), before);
}

}  // namespace
}  // namespace sdfreel::test

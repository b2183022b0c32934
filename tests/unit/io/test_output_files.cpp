// Output files: checked before anything is written, each through a temporary file
// of its own, all or none; links, devices and descriptors written where they lead.
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <feran/core/error.hpp>
#include <feran/io/output_files.hpp>

namespace feran::test_output_files {

namespace fs = std::filesystem;

class OutputFilesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("feran_outputs_" + std::to_string(::getpid()) + "_" +
                                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
    model = (dir / "model.toml").string();
    put(model, "title = \"m\"\n");
  }
  void TearDown() override { fs::remove_all(dir); }

  static void put(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }
  static std::string get(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
  // Every name in the directory that is not one of @p keep (the temporaries left).
  std::vector<std::string> others(std::initializer_list<std::string> keep) const {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir)) {
      const std::string name = e.path().filename().string();
      if (std::find(keep.begin(), keep.end(), name) == keep.end()) out.push_back(name);
    }
    return out;
  }
  // The message of the Error that @p f throws ("" when it throws none).
  template <class F>
  static std::string error_of(F&& f) {
    try {
      f();
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  }

  fs::path dir;
  std::string model;
};

TEST_F(OutputFilesTest, NothingReachesATargetBeforeCommit) {
  const fs::path old_file = dir / "old.json", new_file = dir / "new.csv";
  put(old_file, "the user's file");
  {
    OutputFiles files(model);
    files.write(files.add("--json", old_file.string()), "new content");
    files.write(files.add("--csv", new_file.string()), "a,b\n");
    // The temporaries exist (each unique, beside its target); the targets are as they were.
    EXPECT_EQ(others({"model.toml", "old.json"}).size(), 2u);
    EXPECT_EQ(get(old_file), "the user's file");
    EXPECT_FALSE(fs::exists(new_file));
  }  // destroyed without commit: a failed run
  EXPECT_EQ(get(old_file), "the user's file");
  EXPECT_FALSE(fs::exists(new_file));
  EXPECT_TRUE(others({"model.toml", "old.json"}).empty());
}

TEST_F(OutputFilesTest, CommitWritesEveryOutputAndKeepsPermissions) {
  const fs::path old_file = dir / "old.json", new_file = dir / "new.csv";
  put(old_file, "old");
  ::chmod(old_file.c_str(), 0640);
  OutputFiles files(model);
  files.write(files.add("--json", old_file.string()), "{}\n");
  files.write(files.add("--csv", new_file.string()), "a,b\n");
  files.commit();
  EXPECT_EQ(get(old_file), "{}\n");
  EXPECT_EQ(get(new_file), "a,b\n");
  struct stat st {};
  ASSERT_EQ(::stat(old_file.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 07777, 0640u);  // a replaced file keeps its mode
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ASSERT_EQ(::stat(new_file.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 07777, 0666u & ~mask);  // a new one: as any program would create it
  EXPECT_TRUE(others({"model.toml", "old.json", "new.csv"}).empty());
}

// Concurrent runs writing one path each have their own temporary: the file ends up
// as one run's whole output, never a mix (a fixed FILE.part, shared by both, held
// NUL bytes and rows of each).
TEST_F(OutputFilesTest, ConcurrentWritersNeverMix) {
  const fs::path target = dir / "runup.csv";
  const fs::path users_part = dir / "runup.csv.part";
  put(users_part, "a file of the user's that a fixed temporary name would overwrite");
  const std::string a(300000, 'a'), b(200000, 'b');
  OutputFiles first(model), second(model);
  const int fa = first.add("--csv", target.string(), true);
  const int fb = second.add("--csv", target.string(), true);
  for (int i = 0; i < 10; ++i) {
    first.append(fa, a);
    second.append(fb, b);
  }
  first.commit();
  EXPECT_EQ(get(target).size(), 10 * a.size());
  second.commit();
  const std::string final_text = get(target);
  EXPECT_EQ(final_text.size(), 10 * b.size());
  EXPECT_EQ(final_text.find_first_not_of('b'), std::string::npos);
  EXPECT_EQ(get(users_part), "a file of the user's that a fixed temporary name would overwrite");
}

TEST_F(OutputFilesTest, SymbolicLinksAreFollowed) {
  const fs::path real = dir / "real.json", link = dir / "link.json";
  put(real, "old");
  fs::create_symlink("real.json", link);
  const fs::path dangling = dir / "dangling.csv";
  fs::create_symlink("made.csv", dangling);
  OutputFiles files(model);
  files.write(files.add("--json", link.string()), "new");
  files.write(files.add("--csv", dangling.string()), "x\n");
  files.commit();
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(get(real), "new");
  EXPECT_TRUE(fs::is_symlink(dangling));
  EXPECT_EQ(get(dir / "made.csv"), "x\n");
}

TEST_F(OutputFilesTest, RefusedBeforeAnythingRuns) {
  const fs::path link_to_model = dir / "link.toml", hard_link = dir / "hard.toml", sub = dir / "sub";
  fs::create_symlink("model.toml", link_to_model);
  fs::create_hard_link(model, hard_link);
  fs::create_directories(sub);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {model, "it is the model file"},
      {link_to_model.string(), "it is the model file"},
      {hard_link.string(), "it is the model file"},
      {sub.string(), "it is a directory"},
      {(dir / "missing" / "x.json").string(), "the directory '" + (dir / "missing").string() + "' does not exist"},
      {(dir / "model.toml" / "x.json").string(), "'" + model + "' is not a directory"},
  };
  for (const auto& [path_, expected] : cases) {
    const std::string& path = path_;  // a structured binding is not captured by clang 14
    OutputFiles files(model);
    const std::string message = error_of([&] { files.add("--json", path); });
    EXPECT_NE(message.find("--json '" + path + "': cannot write: " + expected), std::string::npos)
        << path << ": " << message;
  }
  EXPECT_EQ(get(model), "title = \"m\"\n");
  EXPECT_TRUE(others({"model.toml", "link.toml", "hard.toml", "sub"}).empty());
}

TEST_F(OutputFilesTest, TwoOutputsNeverShareAFile) {
  const fs::path a = dir / "a.json";
  fs::create_symlink("a.json", dir / "alias.json");
  for (const std::string& second : {a.string(), (dir / "." / "a.json").string(), (dir / "alias.json").string()}) {
    OutputFiles files(model);
    files.add("--json", a.string());
    EXPECT_NE(error_of([&] { files.add("--csv", second); }).find("--json already writes"), std::string::npos) << second;
  }
  // Discarding twice is harmless.
  OutputFiles files(model);
  files.add("--json", "/dev/null");
  EXPECT_EQ(error_of([&] { files.add("--csv", "/dev/null"); }), "");
}

TEST_F(OutputFilesTest, SpecialFilesAreWrittenInPlace) {
  const fs::path fifo = dir / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = get(fifo); });
  {
    OutputFiles files(model);
    files.write(files.add("--json", fifo.string()), "through the pipe\n");
    files.commit();
  }
  reader.join();
  EXPECT_EQ(received, "through the pipe\n");
  struct stat st {};
  ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));  // not replaced by a regular file

  // A device that refuses the data: the system's reason, and the device stays.
  OutputFiles full(model);
  full.write(full.add("--csv", "/dev/full"), "x");
  EXPECT_NE(error_of([&] { full.commit(); }).find("--csv '/dev/full': cannot write: No space left on device"),
            std::string::npos);
  ASSERT_EQ(::stat("/dev/full", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
}

TEST_F(OutputFilesTest, DescriptorsAreWrittenAsTheyAre) {
  // /dev/fd/N writes to descriptor N itself: a file opened for appending keeps what
  // it held (opening the path anew would truncate it).
  const fs::path log = dir / "log.txt";
  put(log, "before\n");
  const int fd = ::open(log.c_str(), O_WRONLY | O_APPEND);
  ASSERT_GE(fd, 0);
  {
    OutputFiles files(model);
    files.write(files.add("--json", "/dev/fd/" + std::to_string(fd)), "after\n");
    files.commit();
  }
  ::close(fd);
  EXPECT_EQ(get(log), "before\nafter\n");
  OutputFiles files(model);
  EXPECT_NE(error_of([&] { files.add("--json", "/proc/self/fd/999"); }).find("descriptor 999 is not open"),
            std::string::npos);
}

// A temporary that cannot be completed (here: over the file size limit) fails the
// commit before any target is renamed: all or none.
TEST_F(OutputFilesTest, AllOrNone) {
  const fs::path small = dir / "small.json", big = dir / "big.csv";
  put(small, "old");
  std::signal(SIGXFSZ, SIG_IGN);
  rlimit old_limit{};
  ::getrlimit(RLIMIT_FSIZE, &old_limit);
  rlimit limit = old_limit;
  limit.rlim_cur = 4096;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &limit), 0);
  std::string message;
  {
    OutputFiles files(model);
    files.write(files.add("--json", small.string()), "new");
    files.write(files.add("--csv", big.string()), std::string(100000, 'x'));
    message = error_of([&] { files.commit(); });
  }
  ::setrlimit(RLIMIT_FSIZE, &old_limit);
  std::signal(SIGXFSZ, SIG_DFL);
  EXPECT_NE(message.find("--csv '" + big.string() + "': cannot write: File too large"), std::string::npos) << message;
  EXPECT_EQ(get(small), "old");
  EXPECT_FALSE(fs::exists(big));
  EXPECT_TRUE(others({"model.toml", "small.json"}).empty());
}

TEST_F(OutputFilesTest, StreamedOutputHoldsEverythingAppended) {
  const fs::path target = dir / "stream.csv";
  OutputFiles files(model);
  const int id = files.add("--csv", target.string(), true);
  std::string expected;
  for (int i = 0; i < 100000; ++i) {
    const std::string row = std::to_string(i) + ",x\n";
    files.append(id, row);
    expected += row;
  }
  files.commit();
  EXPECT_EQ(get(target), expected);
}

// What a signal handler calls before the program ends: the temporaries go.
TEST_F(OutputFilesTest, SignalSafeRemovalOfTemporaries) {
  OutputFiles files(model);
  files.write(files.add("--json", (dir / "a.json").string()), "x");
  EXPECT_EQ(others({"model.toml"}).size(), 1u);
  remove_temporary_outputs();
  EXPECT_TRUE(others({"model.toml"}).empty());
}

}  // namespace feran::test_output_files

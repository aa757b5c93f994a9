// Files written whole or not at all (files/output_file.h): what is at the target before the
// commit stays as it was, nothing but a regular file is ever replaced, and no temporary file is
// left beside the target whatever happens.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "files/output_file.h"

namespace frictionlab::files {
namespace {

namespace fs = std::filesystem;

// A fresh folder of its own for each test, removed after it.
class OutputFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string name = std::string("frictionlab_output_file_") + ::testing::UnitTest::GetInstance()->current_test_info()->name() +
                             "_" + std::to_string(::getpid());
    folder_ = fs::temp_directory_path() / name;
    fs::remove_all(folder_);
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }

  std::string at(const std::string& name) const { return (folder_ / name).string(); }
  // Every name in the folder but `keep`: a temporary file left behind shows here.
  std::string others_than(const std::string& keep) const {
    std::string found;
    for (const auto& entry : fs::directory_iterator(folder_)) {
      if (entry.path().filename() != keep) found += entry.path().filename().string() + " ";
    }
    return found;
  }

  fs::path folder_;
};

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_plain(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

TEST_F(OutputFileTest, ACommittedFileHoldsWhatWasWrittenAndReplacesTheOldOne) {
  const std::string path = at("run.csv");
  write_plain(path, "old\n");
  {
    OutputFile file(path);
    file.write("t,x\n");
    file.write("0,1\n");
    EXPECT_EQ(read_all(path), "old\n") << "the target changed before the commit";
    file.commit();
  }
  EXPECT_EQ(read_all(path), "t,x\n0,1\n");
  EXPECT_EQ(others_than("run.csv"), "") << "a temporary file was left beside the target";
}

TEST_F(OutputFileTest, AFileNeverCommittedLeavesTheTargetAsItWasAndNoTemporaryFile) {
  const std::string old_path = at("kept.png");
  write_plain(old_path, "old picture");
  {
    OutputFile file(old_path);
    file.write("half a pict");
  }  // as when an error ends the writing
  EXPECT_EQ(read_all(old_path), "old picture");
  EXPECT_EQ(others_than("kept.png"), "");

  const std::string new_path = at("never.png");
  {
    OutputFile file(new_path);
    file.write("half");
  }
  EXPECT_FALSE(fs::exists(new_path));
  EXPECT_EQ(others_than("kept.png"), "");
}

TEST_F(OutputFileTest, TheFinishedFileHasTheUsualPermissionsNotTheTemporaryFilesPrivateOnes) {
  const mode_t mask = ::umask(022);
  const std::string path = at("settings.ini");
  write_whole_file(path, "theme = light\n", 14);
  ::umask(mask);
  struct stat status {};
  ASSERT_EQ(::stat(path.c_str(), &status), 0);
  EXPECT_EQ(status.st_mode & 0777, 0644u);  // 0666 less the mask; mkstemps alone gives 0600
  EXPECT_EQ(read_all(path), "theme = light\n");
}

// The message names the path and what is there, so a teacher knows what to change.
void expect_refused(const std::string& path, const std::string& what_is_there) {
  try {
    OutputFile file(path);
    ADD_FAILURE() << path << ": written over " << what_is_there;
  } catch (const std::runtime_error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find(what_is_there), std::string::npos) << message;
  }
}

TEST_F(OutputFileTest, NothingButARegularFileIsReplaced) {
  fs::create_directory(at("a_folder"));
  expect_refused(at("a_folder"), "a folder");
  EXPECT_TRUE(fs::is_directory(at("a_folder")));

  write_plain(at("pointed_at.txt"), "not FrictionLab's");
  fs::create_symlink(at("pointed_at.txt"), at("link.csv"));
  expect_refused(at("link.csv"), "a symbolic link");
  EXPECT_TRUE(fs::is_symlink(at("link.csv")));
  EXPECT_EQ(read_all(at("pointed_at.txt")), "not FrictionLab's");

  // A FIFO in the test's own folder stands for every file that is not a regular one: a device
  // node would be the same refusal, but a test that broke would then write beside /dev/null.
  ASSERT_EQ(::mkfifo(at("pipe.csv").c_str(), 0600), 0);
  expect_refused(at("pipe.csv"), "a FIFO");
}

TEST_F(OutputFileTest, ALinkPutAtTheTargetWhileWritingIsNotReplacedAtTheCommit) {
  const std::string path = at("history.csv");
  write_plain(at("elsewhere.txt"), "someone else's");
  OutputFile file(path);
  file.write("t,x\n");
  fs::create_symlink(at("elsewhere.txt"), path);
  EXPECT_THROW(file.commit(), std::runtime_error);
  EXPECT_TRUE(fs::is_symlink(path));
  EXPECT_EQ(read_all(at("elsewhere.txt")), "someone else's");
}

bool only_csv_files(const std::string& path) { return fs::path(path).extension() == ".csv"; }

TEST_F(OutputFileTest, AskedWhetherARegularFileMayBeReplacedOnlyWhenOneIsThere) {
  write_plain(at("notes.txt"), "a teacher's notes");
  EXPECT_THROW(OutputFile(at("notes.txt"), only_csv_files), std::runtime_error);
  EXPECT_EQ(read_all(at("notes.txt")), "a teacher's notes");

  write_plain(at("old.csv"), "old");
  {
    OutputFile file(at("old.csv"), only_csv_files);
    file.write("new");
    file.commit();
  }
  EXPECT_EQ(read_all(at("old.csv")), "new");

  // Nothing there: nothing to ask about, whatever the name.
  OutputFile file(at("new.txt"), only_csv_files);
  file.write("fresh");
  file.commit();
  EXPECT_EQ(read_all(at("new.txt")), "fresh");
}

}  // namespace
}  // namespace frictionlab::files

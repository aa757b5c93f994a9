#include "files/output_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace frictionlab::files {
namespace {

// The temporary file being written now, for the signal handler: a fixed buffer, since a
// handler may only call async-signal-safe functions (unlink is one).
char partial_name[4096];
volatile std::sig_atomic_t partial_written = 0;

void on_interrupt(int signal_number) {
  if (partial_written != 0) ::unlink(partial_name);
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

std::string what_is_there(mode_t mode) {
  if (S_ISLNK(mode)) return "a symbolic link";
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  if (S_ISSOCK(mode)) return "a socket";
  return "something that is not a regular file";
}

// Refuses a target that is not a regular file; lstat, so a symbolic link is seen as one.
void check_target(const std::string& path, bool (*may_replace)(const std::string&)) {
  struct stat status {};
  if (::lstat(path.c_str(), &status) != 0) return;  // nothing there (or not reachable: open says)
  if (!S_ISREG(status.st_mode)) {
    std::string message = path;
    message += ": ";
    message += what_is_there(status.st_mode);
    message += " is there; FrictionLab writes only over regular files, so give a file name";
    throw std::runtime_error(message);
  }
  if (may_replace != nullptr && !may_replace(path)) {
    throw std::runtime_error(path + ": a file FrictionLab did not write is there; remove it or give another name");
  }
}

}  // namespace

OutputFile::OutputFile(std::string path, bool (*may_replace)(const std::string&)) : path_(std::move(path)) {
  check_target(path_, may_replace);
  const std::filesystem::path target(path_);
  const std::filesystem::path folder = target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
  // Hidden, beside the target (so the rename stays on one file system), and new: mkstemps
  // creates it exclusively, so a link planted under a guessable name cannot redirect it.
  std::string hidden = ".";
  hidden += target.filename().string();
  hidden += ".XXXXXX.partial";
  const std::string pattern = (folder / hidden).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int descriptor = ::mkstemps(name.data(), static_cast<int>(std::strlen(".partial")));
  if (descriptor < 0) throw std::runtime_error(path_ + ": cannot write there (" + std::strerror(errno) + ")");
  temporary_ = name.data();
  // mkstemps makes it private (0600); the finished file gets the usual permissions.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(descriptor, 0666 & ~mask);
  file_ = ::fdopen(descriptor, "wb");
  if (file_ == nullptr) {
    ::close(descriptor);
    ::unlink(temporary_.c_str());
    throw std::runtime_error(path_ + ": cannot write there (" + std::strerror(errno) + ")");
  }
  if (temporary_.size() < sizeof partial_name) {
    std::memcpy(partial_name, temporary_.c_str(), temporary_.size() + 1);
    partial_written = 1;
  }
}

OutputFile::~OutputFile() {
  if (committed_) return;
  if (file_ != nullptr) std::fclose(file_);
  ::unlink(temporary_.c_str());
  partial_written = 0;
}

void OutputFile::write(const void* data, std::size_t size) {
  if (failed_ || size == 0) return;
  failed_ = std::fwrite(data, 1, size, file_) != size;
}

void OutputFile::commit() {
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (failed_ || !closed) throw std::runtime_error(path_ + ": the file could not be written whole (disk full?)");
  // Whatever appeared at the target meanwhile is checked again: still nothing but a regular file is replaced.
  check_target(path_, nullptr);
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0) {
    throw std::runtime_error(path_ + ": cannot put the file there (" + std::strerror(errno) + ")");
  }
  committed_ = true;
  partial_written = 0;
}

void write_whole_file(const std::string& path, const void* data, std::size_t size) {
  OutputFile file(path);
  file.write(data, size);
  file.commit();
}

void remove_partial_files_on_interrupt() {
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
}

}  // namespace frictionlab::files

// Files FrictionLab writes (CSV, PNG, settings): whole or not at all, and never over anything
// but a regular file. The bytes go to a temporary file made beside the target (a new name,
// created exclusively, so no link planted there is followed) and renamed over the target when
// complete; an interrupted run (an error, Ctrl-C) leaves no temporary file behind.
#pragma once

#include <cstddef>
#include <cstdio>
#include <string>

namespace frictionlab::files {

class OutputFile {
 public:
  // Throws std::runtime_error, naming `path`, when something that is not a regular file is
  // there (a device such as /dev/null, a FIFO, a folder, a symbolic link): those are never
  // replaced. `may_replace` says whether a regular file there may be (it is asked with the
  // file's path; null: any regular file may).
  explicit OutputFile(std::string path, bool (*may_replace)(const std::string& path) = nullptr);
  ~OutputFile();  // removes the temporary file unless committed
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  void write(const void* data, std::size_t size);
  void write(const std::string& text) { write(text.data(), text.size()); }
  // Flushes, closes and renames the temporary file over the target. Throws std::runtime_error.
  void commit();

  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::string temporary_;
  std::FILE* file_ = nullptr;
  bool failed_ = false;
  bool committed_ = false;
};

// The same for bytes already in memory.
void write_whole_file(const std::string& path, const void* data, std::size_t size);

// On SIGINT or SIGTERM, the temporary file being written (one at a time in this program) is
// removed before the program ends with the signal's usual status. Call once, early.
void remove_partial_files_on_interrupt();

}  // namespace frictionlab::files

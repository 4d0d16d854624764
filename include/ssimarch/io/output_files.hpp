// All-or-nothing output (docs/reliability.md): a run writes each of its files to a temporary file
// beside the destination and renames them all only after every write succeeded, so that a run that
// fails (a full disk, a bad path, an error after the first file, the time budget) leaves the files
// of an earlier run untouched and no half-written file behind.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace ssimarch {

/// A file could not be written (opened, written, flushed or renamed); what() names the file.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The output files of one run. open() each, write, then commit(); without commit() (an exception,
/// an early return) the destructor removes the temporaries. "-" is standard output. A destination
/// that exists and is not a regular file (/dev/null, /dev/full, a pipe) is written in place, since
/// it cannot be replaced by a rename; its write errors still make commit() throw.
class OutputFiles {
 public:
  OutputFiles();
  ~OutputFiles();
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;

  /// A stream for `destination`; throws OutputError when its temporary cannot be created.
  std::ostream& open(const std::filesystem::path& destination);
  /// Flushes and closes every file, checks each for errors, then renames the temporaries onto their
  /// destinations. Throws OutputError (and removes the temporaries) when any write failed.
  void commit();

 private:
  struct File;
  std::vector<std::unique_ptr<File>> files_;
  bool committed_ = false;
};

/// Throws OutputError when `destination` is the same file as one this run has read
/// (core/input_files.hpp): an output never replaces an input. OutputFiles::open checks it; a
/// command checks it early too, before the work, once its inputs are read.
void refuse_input_as_output(const std::filesystem::path& destination);

/// Removes the temporaries of every OutputFiles not yet committed (for a watchdog that ends the
/// process when the run exceeds its time budget; thread-safe).
void remove_pending_outputs() noexcept;

}  // namespace ssimarch

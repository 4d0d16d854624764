#include "ssimarch/io/output_files.hpp"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>
#include <mutex>
#include <set>

#include "ssimarch/core/input_files.hpp"

namespace ssimarch {

namespace fs = std::filesystem;

namespace {

// Temporaries of uncommitted runs, for remove_pending_outputs().
std::mutex& pending_mutex() {
  static std::mutex m;
  return m;
}
std::set<std::string>& pending() {
  static std::set<std::string> s;
  return s;
}

void track(const fs::path& p, bool add) {
  std::lock_guard lock(pending_mutex());
  if (add) pending().insert(p.string());
  else pending().erase(p.string());
}

// A name beside the destination (same file system, so the rename is atomic) that no other
// process or run uses: the process id and a counter.
fs::path temporary_for(const fs::path& destination) {
  static std::atomic<unsigned> counter{0};
  const fs::path dir = destination.parent_path();
  // Appended piece by piece: GCC 12 warns falsely on chains of std::string + at -O3 (bug 105651).
  std::string name = ".";
  name.append(destination.filename().string());
  name.append(".tmp-");
  name.append(std::to_string(::getpid()));
  name.append("-");
  name.append(std::to_string(counter++));
  return dir.empty() ? fs::path(name) : dir / name;
}

bool replaceable(const fs::path& destination) {
  std::error_code ec;
  const fs::file_status s = fs::status(destination, ec);
  return ec || !fs::exists(s) || fs::is_regular_file(s);
}

std::string reason() {
  std::string r;
  if (errno) r.append(": ").append(std::strerror(errno));
  return r;
}

}  // namespace

struct OutputFiles::File {
  fs::path destination, temporary;  // temporary empty: written in place (or standard output)
  std::ofstream stream;
  bool standard_output = false;
};

OutputFiles::OutputFiles() = default;

OutputFiles::~OutputFiles() {
  if (committed_) return;
  for (const auto& f : files_) {
    if (f->temporary.empty()) continue;
    f->stream.close();
    std::error_code ec;
    fs::remove(f->temporary, ec);
    track(f->temporary, false);
  }
}

std::ostream& OutputFiles::open(const fs::path& destination) {
  auto f = std::make_unique<File>();
  f->destination = destination;
  if (destination == "-") {
    f->standard_output = true;
    files_.push_back(std::move(f));
    return std::cout;
  }
  if (fs::is_directory(destination)) throw OutputError(destination.string() + ": is a directory, not a file");
  refuse_input_as_output(destination);
  if (replaceable(destination)) f->temporary = temporary_for(destination);
  const fs::path& target = f->temporary.empty() ? destination : f->temporary;
  errno = 0;
  f->stream.open(target, std::ios::binary | std::ios::trunc);
  if (!f->stream) throw OutputError(destination.string() + ": cannot be opened for writing" + reason());
  if (!f->temporary.empty()) track(f->temporary, true);
  files_.push_back(std::move(f));
  return files_.back()->stream;
}

void OutputFiles::commit() {
  for (const auto& f : files_) {
    errno = 0;
    if (f->standard_output) {
      std::cout.flush();
      if (!std::cout) throw OutputError("standard output: write failed" + reason());
      continue;
    }
    f->stream.flush();
    const bool flushed = static_cast<bool>(f->stream);
    f->stream.close();
    if (!flushed || f->stream.fail()) throw OutputError(f->destination.string() + ": write failed" + reason());
  }
  for (const auto& f : files_) {
    if (f->temporary.empty()) continue;
    std::error_code ec;
    fs::rename(f->temporary, f->destination, ec);
    if (ec) throw OutputError(f->destination.string() + ": cannot be replaced: " + ec.message());
    track(f->temporary, false);
  }
  committed_ = true;
}

void refuse_input_as_output(const fs::path& destination) {
  std::error_code ec;
  if (!fs::is_regular_file(destination, ec)) return;  // a device or pipe is written in place, replaces nothing
  if (const auto input = input_file_at(destination))
    throw OutputError(destination.string() + ": is an input of this run (" + input->string() +
                      "); it is not replaced: write the output to another file");
}

void remove_pending_outputs() noexcept {
  std::lock_guard lock(pending_mutex());
  for (const std::string& p : pending()) ::unlink(p.c_str());
  pending().clear();
}

}  // namespace ssimarch

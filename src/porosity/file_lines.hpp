// Lines of a byte range of a regular file, read in large blocks (internal to porosity): the
// streaming reader of packing files (packing_share.cpp) holds one block, never the whole text.
// A range [begin, end) owns the lines whose first byte lies in it, so consecutive ranges split a
// file into its lines exactly once; a line is yielded without its '\n' (and a final '\r').
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ssimarch::internal {

class FileLines {
 public:
  static constexpr std::size_t kBlock = std::size_t{1} << 22;  // 4 MiB reads

  /// Thrown by next() for a line longer than max_line; `index` counts the lines before it.
  struct LineTooLong {
    long index;
  };

  FileLines(const std::filesystem::path& path, std::uint64_t begin, std::uint64_t end, std::uint64_t max_line)
      : f_(std::fopen(path.c_str(), "rb")), end_(end), max_line_(max_line) {
    if (!f_) return;
    buf_.resize(kBlock);
    pos_ = begin;
    if (begin > 0) {
      // The line containing byte begin-1 belongs to the range before: skip to its end.
      std::fseek(f_, static_cast<long>(begin - 1), SEEK_SET);
      file_pos_ = begin - 1;
      pos_ = begin - 1;
      skip_first_ = true;
    } else {
      std::fseek(f_, 0, SEEK_SET);
      file_pos_ = 0;
    }
  }
  ~FileLines() {
    if (f_) std::fclose(f_);
  }
  FileLines(const FileLines&) = delete;
  FileLines& operator=(const FileLines&) = delete;

  bool ok() const { return f_ != nullptr; }
  /// Offset of the first byte of the line last returned by next().
  std::uint64_t line_offset() const { return line_offset_; }
  /// Offset just after the line last returned (after its '\n').
  std::uint64_t after_line() const { return pos_; }
  long lines() const { return count_; }

  /// The next line starting before `end`, or false at the range's (or the file's) end.
  bool next(std::string_view& line) {
    if (skip_first_) {
      skip_first_ = false;
      // A '\n' at begin-1 ends the previous line: the range starts at begin.
      if (!take_line(line, /*count=*/false)) return false;
    }
    if (pos_ >= end_) return false;
    if (!take_line(line, true)) return false;
    return true;
  }

 private:
  // Reads the line at pos_ into `line`; false at the end of the file.
  bool take_line(std::string_view& line, bool count) {
    line_offset_ = pos_;
    long_line_.clear();
    for (;;) {
      if (head_ == tail_ && !refill()) {
        if (long_line_.empty()) return false;  // nothing left
        break;                                 // last line without '\n'
      }
      const char* b = buf_.data() + head_;
      const void* nl = std::memchr(b, '\n', tail_ - head_);
      const std::size_t n = nl ? static_cast<std::size_t>(static_cast<const char*>(nl) - b) : tail_ - head_;
      if (long_line_.size() + n > max_line_ && count) throw LineTooLong{count_};
      if (nl && long_line_.empty()) {
        line = std::string_view(b, n);
        head_ += n + 1;
        pos_ += n + 1;
        finish(line, count);
        return true;
      }
      long_line_.append(b, n);
      head_ += n + (nl ? 1 : 0);
      pos_ += n + (nl ? 1 : 0);
      if (nl) break;
    }
    line = long_line_;
    finish(line, count);
    return true;
  }
  void finish(std::string_view& line, bool count) {
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (count) ++count_;
  }
  bool refill() {
    // Lines that straddle blocks were copied to long_line_ already: the buffer restarts empty.
    head_ = 0;
    tail_ = std::fread(buf_.data(), 1, buf_.size(), f_);
    file_pos_ += tail_;
    return tail_ > 0;
  }

  std::FILE* f_;
  std::uint64_t end_, max_line_;
  std::uint64_t pos_ = 0, file_pos_ = 0, line_offset_ = 0;
  std::vector<char> buf_;
  std::size_t head_ = 0, tail_ = 0;
  std::string long_line_;
  long count_ = 0;
  bool skip_first_ = false;
};

}  // namespace ssimarch::internal

// Packing readers and writer. Format description: include/ssimarch/porosity/packing.hpp, docs/porosity.md.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "ssimarch/core/error.hpp"
#include "ssimarch/core/input_files.hpp"

#include "ssimarch/porosity/packing.hpp"

#include "particle_row_check.hpp"

namespace ssimarch {

namespace {

std::string trim(std::string_view s) {
  std::size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return std::string(s.substr(b, e - b));
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> out;
  if (sep == ' ') {
    std::istringstream is(line);
    for (std::string t; is >> t;) out.push_back(t);
    return out;
  }
  std::size_t b = 0;
  for (;;) {
    const std::size_t e = line.find(sep, b);
    out.push_back(trim(std::string_view(line).substr(b, e == std::string::npos ? std::string::npos : e - b)));
    if (e == std::string::npos) break;
    b = e + 1;
  }
  return out;
}

// 1-based column of the first character of field k of `line` (fields as split() makes them).
std::size_t field_column(const std::string& line, char sep, std::size_t k) {
  std::size_t pos = 0;
  auto skip_space = [&] {
    while (pos < line.size() && std::isspace(static_cast<unsigned char>(line[pos]))) ++pos;
  };
  for (std::size_t i = 0; i < k && pos < line.size(); ++i) {
    if (sep == ' ') {
      skip_space();
      while (pos < line.size() && !std::isspace(static_cast<unsigned char>(line[pos]))) ++pos;
    } else {
      pos = line.find(sep, pos);
      pos = pos == std::string::npos ? line.size() : pos + 1;
    }
  }
  skip_space();
  return pos + 1;
}

std::optional<double> parse_number(const std::string& t) {
  double v = 0;
  const char* b = t.data();
  const char* e = t.data() + t.size();
  if (b != e && *b == '+') ++b;
  const auto r = std::from_chars(b, e, v);
  if (r.ec != std::errc() || r.ptr != e) return std::nullopt;
  return v;
}

// Collects up to kMaxReportedRows row errors and throws them together.
class Errors {
 public:
  explicit Errors(std::string name) : name_(std::move(name)) {}
  void add(long line, const std::string& what) { add_at(location(line), what); }
  void add(long line, std::size_t column, const std::string& what) { add_at(location(line, column), what); }
  void add_at(const std::string& where, const std::string& what) {
    if (count_++ < internal::kMaxReportedRows) msg_ += "\n  " + where + ": " + what;
  }
  void raise_if_any() const {
    if (count_ == 0) return;
    std::string m = std::to_string(count_) + " bad row" + (count_ > 1 ? "s" : "") + ":" + msg_;
    if (count_ > internal::kMaxReportedRows)
      m += "\n  ... and " + std::to_string(count_ - internal::kMaxReportedRows) + " more";
    throw InputError(name_, m);
  }
  [[noreturn]] void fatal(long line, const std::string& what) const { throw InputError(location(line), what); }
  /// "file:line" or "file:line:column" (column 1-based, in characters of the line as read).
  std::string location(long line, std::size_t column = 0) const {
    std::string where = name_;
    where.append(":").append(std::to_string(line));
    if (column) where.append(":").append(std::to_string(column));
    return where;
  }

 private:
  std::string name_, msg_;
  long count_ = 0;
};

// Lines of a packing file, bounded: a line longer than limits.max_line_bytes or a file longer than
// limits.max_packing_bytes ends the read with an InputError (a wrong path such as /dev/zero has no
// newline to stop std::getline). A UTF-8 byte order mark before the first line is dropped.
class LineReader {
 public:
  LineReader(std::istream& in, const Errors& err, const InputLimits& limits) : in_(in), err_(err), limits_(limits) {}

  bool next(std::string& line) {
    line.clear();
    std::streambuf* sb = in_.rdbuf();
    bool any = false;
    for (int c = sb->sbumpc(); c != std::char_traits<char>::eof(); c = sb->sbumpc()) {
      any = true;
      if (++bytes_ > limits_.max_packing_bytes)
        err_.fatal(line_ + 1, "the file is larger than " + byte_count_text(limits_.max_packing_bytes) +
                                  ", the limit for a packing file (--max-input-mb raises it)");
      if (c == '\n') break;
      if (line.size() >= limits_.max_line_bytes)
        err_.fatal(line_ + 1, "a line longer than " + byte_count_text(limits_.max_line_bytes) +
                                  " (not a packing file? a row of numbers is under 200 bytes)");
      line.push_back(static_cast<char>(c));
    }
    if (!any) return false;
    if (++line_ == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    return true;
  }
  long line_number() const { return line_; }

 private:
  std::istream& in_;
  const Errors& err_;
  InputLimits limits_;
  long line_ = 0;
  std::uint64_t bytes_ = 0;
};


}  // namespace

Packing read_packing_csv(std::istream& in, const std::string& name, const InputLimits& limits) {
  Errors err(name);
  LineReader reader(in, err, limits);
  std::string line;
  long ln = 0;
  std::vector<std::string> header;
  while (reader.next(line)) {
    ln = reader.line_number();
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    header = split(lower(t), ',');
    break;
  }
  if (header.empty()) err.fatal(ln, "empty file: expected a CSV header (x,y,z,d or x,y,z,ux,uy,uz,d,l)");
  std::map<std::string, int> col;
  for (int k = 0; k < static_cast<int>(header.size()); ++k) {
    std::string h = header[k];
    if (h == "diameter") h = "d";
    if (h == "length") h = "l";
    if (col.count(h) &&
        (h == "x" || h == "y" || h == "z" || h == "d" || h == "ux" || h == "uy" || h == "uz" || h == "l"))
      err.fatal(ln, "the header names column '" + h + "' twice (fields " + std::to_string(col[h] + 1) + " and " +
                        std::to_string(k + 1) + ")");
    col[h] = k;
  }
  std::string clump;  // the clump column's name, if any (Packing::clumps)
  for (std::string_view c : internal::kCsvClumpColumns)
    if (col.count(std::string(c))) {
      if (!clump.empty())
        err.fatal(ln, "the header names two clump columns ('" + clump + "' and '" + std::string(c) +
                          "'): one particle id per row");
      clump = c;
    }
  for (const char* req : {"x", "y", "z", "d"})
    if (!col.count(req)) err.fatal(ln, std::string("header lacks column '") + req + "' (need x,y,z,d for spheres)");
  const bool sc = col.count("ux") || col.count("uy") || col.count("uz") || col.count("l");
  if (sc)
    for (const char* req : {"ux", "uy", "uz", "l"})
      if (!col.count(req))
        err.fatal(ln, std::string("header lacks column '") + req + "' (spherocylinders need x,y,z,ux,uy,uz,d,l)");
  Packing out;
  out.spherocylinders = sc;
  const std::size_t ncol = header.size();
  while (reader.next(line)) {
    ln = reader.line_number();
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const auto f = split(t, ',');
    if (f.size() < ncol) {
      err.add(ln, "expected " + std::to_string(ncol) + " fields, found " + std::to_string(f.size()));
      continue;
    }
    if (std::any_of(f.begin() + static_cast<std::ptrdiff_t>(ncol), f.end(),
                    [](const std::string& x) { return !trim(x).empty(); })) {
      err.add(ln, internal::more_fields_than_columns(ncol, f.size()));
      continue;
    }
    auto get = [&](const char* c, double& v) {
      const auto x = parse_number(f[col.at(c)]);
      if (!x) {
        err.add(ln, field_column(line, ',', col.at(c)), std::string("column '") + c + "': not a number: '" +
                                                             f[col.at(c)] + "'");
        return false;
      }
      v = *x;
      return true;
    };
    Particle p;
    bool ok = get("x", p.centre.x()) && get("y", p.centre.y()) && get("z", p.centre.z()) && get("d", p.diameter);
    if (ok && sc) ok = get("ux", p.axis.x()) && get("uy", p.axis.y()) && get("uz", p.axis.z()) && get("l", p.length);
    double id = 0;
    if (ok && !clump.empty()) ok = get(clump.c_str(), id);
    if (!ok) continue;
    if (const std::string w = internal::validate_particle(p, sc); !w.empty()) {
      err.add(ln, w);
      continue;
    }
    if (!clump.empty()) {
      if (const std::string w = internal::validate_clump(id); !w.empty()) {
        err.add(ln, field_column(line, ',', col.at(clump)), "column '" + clump + "': " + w);
        continue;
      }
      out.clumps.push_back(static_cast<long>(id));
    }
    out.particles.push_back(p);
  }
  err.raise_if_any();
  return out;
}

namespace {

// The columns of an 'ITEM: ATOMS' header: where x, y, z (plain, unwrapped "u" or scaled "s")
// and the radius or diameter are.
struct AtomColumns {
  std::map<std::string, int> index;
  std::string axis[3];
  bool scaled = false;
  std::string size;   // "radius" or "diameter"
  std::string clump;  // the clump column (Packing::clumps), empty if none
  std::size_t count = 0;
};

// A LAMMPS dump read item by item (docs/porosity.md, "LAMMPS dumps"); every error names the line.
class DumpReader {
 public:
  DumpReader(std::istream& in, const std::string& name, const InputLimits& limits)
      : err_(name), reader_(in, err_, limits), limits_(limits) {}

  Packing read(const std::string& name) {
    Packing last;
    bool have = false;
    std::string line;
    while (next(line)) {
      const std::string t = trim(line);
      if (t.rfind("ITEM: NUMBER OF ATOMS", 0) == 0) {
        natoms_ = atom_count();
      } else if (t.rfind("ITEM: BOX BOUNDS", 0) == 0) {
        box_bounds();
      } else if (t.rfind("ITEM: ATOMS", 0) == 0) {
        last = snapshot(atom_columns(t));
        have = true;
      }
    }
    err_.raise_if_any();
    if (!have) throw InputError(name, "no 'ITEM: ATOMS' section found (not a LAMMPS dump?)");
    return last;
  }

 private:
  bool next(std::string& s) {
    if (!reader_.next(s)) return false;
    ln_ = reader_.line_number();
    return true;
  }

  long atom_count() {
    std::string line;
    if (!next(line)) err_.fatal(ln_, "missing atom count after 'ITEM: NUMBER OF ATOMS'");
    const auto v = parse_number(trim(line));
    if (!v || *v < 0 || *v != std::floor(*v)) err_.fatal(ln_, "bad atom count '" + trim(line) + "'");
    // Checked before the conversion (a double beyond long's range has no defined conversion):
    // more atoms than bytes the file may hold cannot be there.
    if (*v > static_cast<double>(limits_.max_packing_bytes))
      err_.fatal(ln_, "atom count " + trim(line) + " is more than the file can hold (at most " +
                          byte_count_text(limits_.max_packing_bytes) + " are read)");
    return static_cast<long>(*v);
  }

  void box_bounds() {
    std::string line;
    for (int k = 0; k < 3; ++k) {
      if (!next(line)) err_.fatal(ln_, "missing box bounds line");
      const auto f = split(trim(line), ' ');
      const auto a = f.size() >= 2 ? parse_number(f[0]) : std::nullopt;
      const auto b = f.size() >= 2 ? parse_number(f[1]) : std::nullopt;
      if (!a || !b) err_.fatal(ln_, "bad box bounds '" + trim(line) + "'");
      lo_[k] = *a;
      hi_[k] = *b;
    }
    box_ = true;
  }

  AtomColumns atom_columns(const std::string& header) {
    if (natoms_ < 0) err_.fatal(ln_, "'ITEM: ATOMS' before 'ITEM: NUMBER OF ATOMS'");
    AtomColumns c;
    const auto cols = split(header.substr(11), ' ');
    c.count = cols.size();
    for (int k = 0; k < static_cast<int>(cols.size()); ++k) c.index[cols[k]] = k;
    const char* axes[3] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k) {
      const std::string a = axes[k];
      if (c.index.count(a)) {
        c.axis[k] = a;
      } else if (c.index.count(a + "u")) {
        c.axis[k] = a + "u";
      } else if (c.index.count(a + "s")) {
        c.axis[k] = a + "s";
        c.scaled = true;
      } else {
        err_.fatal(ln_, "ATOMS columns lack '" + a + "' (or " + a + "u, " + a + "s)");
      }
    }
    if (c.scaled && !box_)
      err_.fatal(
          ln_, "scaled coordinates (xs, ys, zs) but no 'ITEM: BOX BOUNDS' before 'ITEM: ATOMS': their box is unknown");
    if (c.index.count("radius"))
      c.size = "radius";
    else if (c.index.count("diameter"))
      c.size = "diameter";
    else
      err_.fatal(ln_, "ATOMS columns lack 'radius' (or 'diameter'): only sphere dumps are supported");
    for (std::string_view name : internal::kDumpClumpColumns)
      if (c.clump.empty() && c.index.count(std::string(name))) c.clump = name;
    return c;
  }

  // One atom's line as a sphere (and its clump id), or nullopt after saying what is wrong with it.
  std::optional<Particle> atom(const std::string& line, AtomColumns& c, long& clump) {
    const auto f = split(trim(line), ' ');
    if (f.size() != c.count) {
      err_.add(ln_, "expected " + std::to_string(c.count) + " fields (the ATOMS columns), found " +
                        std::to_string(f.size()));
      return std::nullopt;
    }
    auto number = [&](const std::string& column) -> std::optional<double> {
      const int k = c.index[column];
      const auto v = parse_number(f[static_cast<std::size_t>(k)]);
      if (!v)
        err_.add(ln_, field_column(line, ' ', k),
                 "column '" + column + "': not a number: '" + f[static_cast<std::size_t>(k)] + "'");
      return v;
    };
    Particle p;
    for (int k = 0; k < 3; ++k) {
      const auto v = number(c.axis[k]);
      if (!v) return std::nullopt;
      p.centre[k] = c.scaled ? lo_[k] + *v * (hi_[k] - lo_[k]) : *v;
    }
    const auto size = number(c.size);
    if (!size) return std::nullopt;
    p.diameter = c.size == "radius" ? 2 * *size : *size;
    if (const std::string w = internal::validate_particle(p, false); !w.empty()) {
      err_.add(ln_, w);
      return std::nullopt;
    }
    if (!c.clump.empty()) {
      const auto id = number(c.clump);
      if (!id) return std::nullopt;
      if (const std::string w = internal::validate_clump(*id); !w.empty()) {
        err_.add(ln_, field_column(line, ' ', c.index[c.clump]), "column '" + c.clump + "': " + w);
        return std::nullopt;
      }
      clump = static_cast<long>(*id);
    }
    return p;
  }

  Packing snapshot(AtomColumns c) {
    Packing snap;
    std::string line;
    for (long i = 0; i < natoms_; ++i) {
      if (!next(line))
        err_.fatal(ln_, "file ends after " + std::to_string(i) + " of " + std::to_string(natoms_) + " atoms");
      long clump = 0;
      if (const auto p = atom(line, c, clump)) {
        snap.particles.push_back(*p);
        if (!c.clump.empty()) snap.clumps.push_back(clump);
      }
    }
    return snap;
  }

  Errors err_;
  LineReader reader_;
  const InputLimits& limits_;
  long ln_ = 0;
  long natoms_ = -1;
  double lo_[3] = {0, 0, 0}, hi_[3] = {1, 1, 1};
  bool box_ = false;
};

}  // namespace

Packing read_lammps_dump(std::istream& in, const std::string& name, const InputLimits& limits) {
  return DumpReader(in, name, limits).read(name);
}

Packing read_packing(const std::filesystem::path& path, const InputLimits& limits, unsigned threads) {
  note_input_file(path);
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path.string(), "is a directory, not a packing file");
  if (std::filesystem::is_regular_file(path, ec)) {
    // Compressed dumps (LIGGGHTS and LAMMPS write *.gz) are named as such, not misread as text.
    unsigned char magic[4] = {0, 0, 0, 0};
    std::ifstream probe(path, std::ios::binary);
    probe.read(reinterpret_cast<char*>(magic), sizeof magic);
    const bool gzip = magic[0] == 0x1f && magic[1] == 0x8b,
               zstd = magic[0] == 0x28 && magic[1] == 0xb5 && magic[2] == 0x2f;
    const bool bzip2 = magic[0] == 'B' && magic[1] == 'Z' && magic[2] == 'h', xz = magic[0] == 0xfd && magic[1] == '7';
    if (gzip || zstd || bzip2 || xz)
      throw InputError(path.string(), std::string("is ") +
                                          (gzip    ? "gzip"
                                           : zstd  ? "zstd"
                                           : bzip2 ? "bzip2"
                                                   : "xz") +
                                          "-compressed: decompress it first (e.g. " +
                                          (gzip    ? "gunzip -k"
                                           : zstd  ? "unzstd"
                                           : bzip2 ? "bunzip2 -k"
                                                   : "unxz -k") +
                                          " FILE) and give the decompressed file");
  }
  // Regular files: the streaming block reader (packing_share.cpp); devices and pipes: line by line.
  if (std::filesystem::is_regular_file(path, ec)) return read_packing_share(path, limits, nullptr, threads);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "cannot open file");
  // The format from the first non-blank line; a stream that cannot seek back (a pipe) is read once.
  std::string first;
  {
    const Errors probe_errors(path.string());
    LineReader probe(in, probe_errors, limits);
    while (probe.next(first) && trim(first).empty()) {
    }
  }
  in.clear();
  in.seekg(0);
  if (!in) throw InputError(path.string(), "cannot be read twice (a pipe?): give a regular file");
  if (trim(first).rfind("ITEM:", 0) == 0) return read_lammps_dump(in, path.string(), limits);
  return read_packing_csv(in, path.string(), limits);
}

long particle_count(const Packing& packing) {
  return packing.clumps.empty() ? static_cast<long>(packing.particles.size()) : distinct_count(packing.clumps);
}

namespace {

std::vector<long> sorted_unique(std::span<const long> ids) {
  std::vector<long> v(ids.begin(), ids.end());
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

}  // namespace

long distinct_count(std::span<const long> ids) { return static_cast<long>(sorted_unique(ids).size()); }

long distinct_count(std::span<const long> ids, const ProfileCommunicator& comm) {
  const std::vector<long> v = sorted_unique(ids);
  // Process of an id: its value modulo the process count (equal ids meet on one process).
  const auto n = static_cast<std::size_t>(comm.size());
  auto owner = [n](long id) { return static_cast<std::size_t>(static_cast<unsigned long>(id) % n); };
  std::vector<std::size_t> counts(n, 0), at(n, 0);
  for (long id : v) counts[owner(id)] += sizeof(long);
  for (std::size_t q = 1; q < n; ++q) at[q] = at[q - 1] + counts[q - 1];
  std::string bytes(v.size() * sizeof(long), '\0');
  for (long id : v) {
    std::memcpy(bytes.data() + at[owner(id)], &id, sizeof(long));
    at[owner(id)] += sizeof(long);
  }
  bytes = comm.exchange(std::move(bytes), counts);
  std::vector<long> mine(bytes.size() / sizeof(long));
  if (!mine.empty()) std::memcpy(mine.data(), bytes.data(), mine.size() * sizeof(long));
  long total = distinct_count(mine);
  comm.sum(std::span<long>(&total, 1));
  return total;
}

void write_packing_csv(std::ostream& out, std::span<const Particle> ps) {
  const bool sc = std::any_of(ps.begin(), ps.end(), [](const Particle& p) { return p.length != 0; });
  out << (sc ? "x,y,z,ux,uy,uz,d,l\n" : "x,y,z,d\n");
  char buf[64];
  auto num = [&](double v) {
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    out.write(buf, r.ptr - buf);
  };
  for (const Particle& p : ps) {
    num(p.centre.x()); out << ','; num(p.centre.y()); out << ','; num(p.centre.z()); out << ',';
    if (sc) { num(p.axis.x()); out << ','; num(p.axis.y()); out << ','; num(p.axis.z()); out << ','; }
    num(p.diameter);
    if (sc) { out << ','; num(p.length); }
    out << '\n';
  }
}

}  // namespace ssimarch

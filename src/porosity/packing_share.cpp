// Streaming reader of packing files, whole or one process's share (packing.hpp, docs/porosity.md
// "Input formats", docs/scaling.md "Reading"). Two passes over the share's byte range in 4 MiB
// blocks: the first counts its lines (their numbers in the file come from the counts of the
// shares before it) and finds the last LAMMPS snapshot; the second parses rows with
// std::from_chars into a vector reserved to the row count. The text is never held.
#include <algorithm>
#include <charconv>
#include <cstring>
#include <cmath>
#include <optional>
#include <system_error>

#include "ssimarch/core/error.hpp"
#include "ssimarch/core/input_files.hpp"
#include "ssimarch/porosity/packing.hpp"

#include "particle_row_check.hpp"

#include "file_lines.hpp"
#include "parallel.hpp"

namespace ssimarch {

namespace {

constexpr std::string_view kAtomCountItem = "ITEM: NUMBER OF ATOMS";

std::string_view trim_view(std::string_view s) {
  auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f' || c == '\n'; };
  while (!s.empty() && space(s.front())) s.remove_prefix(1);
  while (!s.empty() && space(s.back())) s.remove_suffix(1);
  return s;
}

// Fields of a row: comma-separated (trimmed) or whitespace-separated; into a reused vector.
void split_fields(std::string_view line, char sep, std::vector<std::string_view>& out) {
  out.clear();
  if (sep == ' ') {
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
      const std::size_t b = i;
      while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
      if (i > b) out.push_back(line.substr(b, i - b));
    }
    return;
  }
  for (std::size_t b = 0;;) {
    const std::size_t e = line.find(sep, b);
    out.push_back(trim_view(line.substr(b, e == std::string_view::npos ? std::string_view::npos : e - b)));
    if (e == std::string_view::npos) break;
    b = e + 1;
  }
}

std::optional<double> number(std::string_view t) {
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);
  double v = 0;
  const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
  if (r.ec != std::errc() || r.ptr != t.data() + t.size()) return std::nullopt;
  return v;
}

// 1-based column of the first character of field k of `line`.
std::size_t column_of(std::string_view line, char sep, std::size_t k) {
  std::size_t pos = 0;
  auto space = [&] { return pos < line.size() && (line[pos] == ' ' || line[pos] == '\t'); };
  for (std::size_t i = 0; i < k && pos < line.size(); ++i) {
    if (sep == ' ') {
      while (space()) ++pos;
      while (pos < line.size() && !space()) ++pos;
    } else {
      pos = line.find(sep, pos);
      pos = pos == std::string_view::npos ? line.size() : pos + 1;
    }
  }
  while (space()) ++pos;
  return pos + 1;
}

// Row errors of a piece of the file, with file line numbers; up to kMaxReportedRows kept. Pieces
// merge in file order (`merge`), so the first rows reported are the file's first bad rows.
struct RowErrors {
  std::string name;
  std::vector<std::string> lines;
  long count = 0;
  void add(long line, const std::string& what, std::size_t column = 0) {
    if (count++ >= internal::kMaxReportedRows) return;
    // Appended piece by piece (GCC 12's -Wrestrict misfires on "literal" + std::string temporaries).
    std::string t;
    t.append("\n  ").append(name).append(":").append(std::to_string(line));
    if (column) t.append(":").append(std::to_string(column));
    lines.push_back(t.append(": ").append(what));
  }
  void merge(const RowErrors& o) {
    for (const std::string& l : o.lines)
      if (lines.size() < static_cast<std::size_t>(internal::kMaxReportedRows)) lines.push_back(l);
    count += o.count;
  }
  std::string message() const {
    if (count == 0) return {};
    std::string m = std::to_string(count) + " bad row" + (count > 1 ? "s" : "") + ":";
    for (const std::string& l : lines) m += l;
    if (count > internal::kMaxReportedRows)
      m += "\n  ... and " + std::to_string(count - internal::kMaxReportedRows) + " more";
    return m;
  }
};

// The values a row may hold: x y z d ux uy uz l (d: radius or diameter) and the clump id.
constexpr int kValues = 9, kClump = 8;
// Rows whose wanted fields are all among the first kFastFields are read by fast_row.
constexpr std::size_t kFastFields = 16;

// Where the numbers of a row are: CSV columns or LAMMPS ATOMS columns, and how to read them.
struct Layout {
  char sep = ',';
  bool lammps = false, sc = false, scaled = false, radius = false, box = false;
  std::size_t ncol = 0;
  int col[kValues] = {-1, -1, -1, -1, -1, -1, -1, -1, -1};  // field of each value, -1: none
  std::string name[kValues];
  // Whether this layout reads value k: those of a sphere (4) or a spherocylinder (8), and the clump id.
  bool reads(int k) const { return k < 4 || (k < 8 && sc) || (k == kClump && col[kClump] >= 0); }
  double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
  long natoms = -1;
  std::uint64_t data_begin = 0;  // first byte of the rows
  long data_line = 1;            // file line of the first byte of the header (CSV) or snapshot
};

// The numbers of a well-formed row, read in one sweep without splitting the row into a vector of
// fields: true when the row has at least L.ncol fields and every wanted field is a number and
// nothing else, exactly the rows parse_row accepts (fields as split_fields() cuts them, numbers as
// number() reads them). A bad row goes to parse_row, which says what is wrong.
bool fast_row(std::string_view line, const Layout& L, double* v) {
  int want[kFastFields];  // value index of field f, -1 if not wanted
  std::fill(std::begin(want), std::end(want), -1);
  std::size_t need = L.ncol;
  for (int k = 0; k < kValues; ++k) {
    if (!L.reads(k)) continue;
    if (L.col[k] >= static_cast<int>(kFastFields)) return false;
    want[L.col[k]] = k;
    need = std::max(need, static_cast<std::size_t>(L.col[k]) + 1);
  }
  auto space = [](char c) { return c == ' ' || c == '\t'; };
  auto trimmed = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f' || c == '\n'; };
  const char* p = line.data();
  const char* const end = p + line.size();
  for (std::size_t f = 0; f < need; ++f) {
    const char *b = p, *e = p;
    if (L.lammps) {  // a run of characters other than blanks and tabs
      while (b < end && space(*b)) ++b;
      if (b == end) return false;
      e = b;
      while (e < end && !space(*e)) ++e;
      p = e;
    } else {  // up to the next separator, trimmed
      if (f > 0 && p++ == end) return false;
      e = static_cast<const char*>(std::memchr(p, L.sep, static_cast<std::size_t>(end - p)));
      if (!e) e = end;
      p = e;
      while (b < e && trimmed(*b)) ++b;
      while (e > b && trimmed(e[-1])) --e;
    }
    if (f < kFastFields && want[f] >= 0) {
      if (b < e && *b == '+') ++b;
      const auto r = std::from_chars(b, e, v[want[f]]);
      if (r.ec != std::errc() || r.ptr != e) return false;
    }
  }
  // A field past the header's (a shifted column, issue 29): slow_row names it. Trailing blanks, and
  // in CSV trailing empty fields (a separator at the end of the row), are no field.
  for (; p < end; ++p)
    if (!trimmed(*p) && (L.lammps || *p != L.sep)) return false;
  return true;
}

// The row split into fields and each wanted field read on its own: for rows fast_row declines,
// to name what is wrong (false, an error recorded) or to read them after all.
bool slow_row(std::string_view line, const Layout& L, long ln, std::vector<std::string_view>& f, RowErrors& err,
              double* v) {
  split_fields(L.lammps ? line : trim_view(line), L.sep, f);
  if (f.size() < L.ncol) {
    err.add(ln, "expected " + std::to_string(L.ncol) + " fields, found " + std::to_string(f.size()));
    return false;
  }
  for (std::size_t k = L.ncol; k < f.size(); ++k)
    if (!trim_view(f[k]).empty()) {
      err.add(ln, internal::more_fields_than_columns(L.ncol, f.size()));
      return false;
    }
  for (int k = 0; k < kValues; ++k) {
    if (!L.reads(k)) continue;
    const auto x = number(f[static_cast<std::size_t>(L.col[k])]);
    if (!x) {
      err.add(ln, "column '" + L.name[k] + "': not a number: '" + std::string(f[static_cast<std::size_t>(L.col[k])]) + "'",
              column_of(line, L.sep, static_cast<std::size_t>(L.col[k])));
      return false;
    }
    v[k] = *x;
  }
  return true;
}

// Parses one data row into p (and its clump id); false (and an error recorded) when it is bad.
bool parse_row(std::string_view line, const Layout& L, long ln, std::vector<std::string_view>& f, RowErrors& err,
               Particle& p, long& clump) {
  double v[kValues] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
  if (!fast_row(line, L, v) && !slow_row(line, L, ln, f, err, v)) return false;
  for (int k = 0; k < 3; ++k) p.centre[k] = L.scaled ? L.lo[k] + v[k] * (L.hi[k] - L.lo[k]) : v[k];
  p.diameter = L.radius ? 2 * v[3] : v[3];
  if (L.sc) {
    p.axis = Vec3(v[4], v[5], v[6]);
    p.length = v[7];
  }
  if (const std::string w = internal::validate_particle(p, L.sc); !w.empty()) {
    err.add(ln, w);
    return false;
  }
  if (L.reads(kClump)) {
    if (const std::string w = internal::validate_clump(v[kClump]); !w.empty()) {
      err.add(ln, "column '" + L.name[kClump] + "': " + w,
              column_of(line, L.sep, static_cast<std::size_t>(L.col[kClump])));
      return false;
    }
    clump = static_cast<long>(v[kClump]);
  }
  return true;
}

// The CSV header: the first line that is neither blank nor a '#' comment (every share reads it).
Layout csv_layout(const std::filesystem::path& path, const InputLimits& limits) {
  const std::string name = path.string();
  internal::FileLines lines(path, 0, ~std::uint64_t{0}, limits.max_line_bytes);
  std::string_view line;
  long ln = 0;
  Layout L;
  std::vector<std::string_view> header;
  while (lines.next(line)) {
    ++ln;
    if (ln == 1 && line.substr(0, 3) == "\xEF\xBB\xBF") line.remove_prefix(3);
    const std::string_view t = trim_view(line);
    if (t.empty() || t[0] == '#') continue;
    split_fields(t, ',', header);
    break;
  }
  if (header.empty()) throw InputError(name + ":" + std::to_string(ln), "empty file: expected a CSV header (x,y,z,d or x,y,z,ux,uy,uz,d,l)");
  L.ncol = header.size();
  L.data_begin = lines.after_line();
  L.data_line = ln + 1;
  const char* keys[8] = {"x", "y", "z", "d", "ux", "uy", "uz", "l"};
  for (std::size_t k = 0; k < header.size(); ++k) {
    std::string h(header[k]);
    std::transform(h.begin(), h.end(), h.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (h == "diameter") h = "d";
    if (h == "length") h = "l";
    for (int j = 0; j < 8; ++j)
      if (h == keys[j]) {
        if (L.col[j] >= 0)
          throw InputError(name + ":" + std::to_string(ln), "the header names column '" + std::string(keys[j]) +
                                                                "' twice (fields " + std::to_string(L.col[j] + 1) +
                                                                " and " + std::to_string(k + 1) + ")");
        L.col[j] = static_cast<int>(k);
      }
    for (std::string_view c : internal::kCsvClumpColumns)
      if (h == c) {
        if (L.col[kClump] >= 0)
          throw InputError(name + ":" + std::to_string(ln), "the header names two clump columns ('" + L.name[kClump] +
                                                                "' and '" + h + "'): one particle id per row");
        L.col[kClump] = static_cast<int>(k);
        L.name[kClump] = h;
      }
  }
  const std::string where = name + ":" + std::to_string(ln);
  for (int j = 0; j < 4; ++j)
    if (L.col[j] < 0) throw InputError(where, std::string("header lacks column '") + keys[j] + "' (need x,y,z,d for spheres)");
  L.sc = L.col[4] >= 0 || L.col[5] >= 0 || L.col[6] >= 0 || L.col[7] >= 0;
  for (int j = 4; j < 8 && L.sc; ++j)
    if (L.col[j] < 0)
      throw InputError(where, std::string("header lacks column '") + keys[j] + "' (spherocylinders need x,y,z,ux,uy,uz,d,l)");
  for (int j = 0; j < 8; ++j) L.name[j] = keys[j];
  return L;
}

// The header of the last LAMMPS snapshot, from its "ITEM: NUMBER OF ATOMS" line at `at` (file
// line `at_line`) to its "ITEM: ATOMS" line.
Layout lammps_layout(const std::filesystem::path& path, std::uint64_t at, long at_line, const InputLimits& limits) {
  const std::string name = path.string();
  internal::FileLines lines(path, at, ~std::uint64_t{0}, limits.max_line_bytes);
  std::string_view line;
  long ln = at_line - 1;
  auto next = [&] {
    if (!lines.next(line)) return false;
    ++ln;
    return true;
  };
  auto fatal = [&](const std::string& what) { throw InputError(name + ":" + std::to_string(ln), what); };
  Layout L;
  L.lammps = true;
  L.sep = ' ';
  std::vector<std::string_view> f;
  while (next()) {
    const std::string_view t = trim_view(line);
    if (t.rfind(kAtomCountItem, 0) == 0) {
      if (!next()) fatal("missing atom count after 'ITEM: NUMBER OF ATOMS'");
      const auto v = number(trim_view(line));
      if (!v || *v < 0 || *v != std::floor(*v)) fatal("bad atom count '" + std::string(trim_view(line)) + "'");
      if (*v > static_cast<double>(limits.max_packing_bytes))
        fatal("atom count " + std::string(trim_view(line)) + " is more than the file can hold (at most " +
              byte_count_text(limits.max_packing_bytes) + " are read)");
      L.natoms = static_cast<long>(*v);
    } else if (t.rfind("ITEM: BOX BOUNDS", 0) == 0) {
      for (int k = 0; k < 3; ++k) {
        if (!next()) fatal("missing box bounds line");
        split_fields(trim_view(line), ' ', f);
        const auto a = f.size() >= 2 ? number(f[0]) : std::nullopt, b = f.size() >= 2 ? number(f[1]) : std::nullopt;
        if (!a || !b) fatal("bad box bounds '" + std::string(trim_view(line)) + "'");
        L.lo[k] = *a;
        L.hi[k] = *b;
      }
      L.box = true;
    } else if (t.rfind("ITEM: ATOMS", 0) == 0) {
      split_fields(t.substr(11), ' ', f);
      L.ncol = f.size();
      auto find = [&](const std::string& c) {
        for (std::size_t k = 0; k < f.size(); ++k)
          if (f[k] == c) return static_cast<int>(k);
        return -1;
      };
      const char* axes[3] = {"x", "y", "z"};
      for (int k = 0; k < 3; ++k) {
        const std::string a = axes[k];
        for (const std::string& c : {a, a + "u", a + "s"})
          if (L.col[k] < 0 && (L.col[k] = find(c)) >= 0) {
            L.name[k] = c;
            L.scaled = L.scaled || c == a + "s";
          }
        if (L.col[k] < 0) fatal("ATOMS columns lack '" + a + "' (or " + a + "u, " + a + "s)");
      }
      if (L.scaled && !L.box)
        fatal("scaled coordinates (xs, ys, zs) but no 'ITEM: BOX BOUNDS' before 'ITEM: ATOMS': their box is unknown");
      L.radius = find("radius") >= 0;
      L.col[3] = L.radius ? find("radius") : find("diameter");
      L.name[3] = L.radius ? "radius" : "diameter";
      if (L.col[3] < 0) fatal("ATOMS columns lack 'radius' (or 'diameter'): only sphere dumps are supported");
      for (std::string_view c : internal::kDumpClumpColumns)
        if (L.col[kClump] < 0 && (L.col[kClump] = find(std::string(c))) >= 0) L.name[kClump] = c;
      L.data_begin = lines.after_line();
      L.data_line = ln + 1;
      return L;
    }
  }
  fatal("no 'ITEM: ATOMS' line after 'ITEM: NUMBER OF ATOMS'");
  return L;
}

// What the first pass learns about a share: its lines, and its last LAMMPS snapshot start.
struct ShareScan {
  long lines = 0;
  long long snapshot = -1;   // byte offset of the last "ITEM: NUMBER OF ATOMS" line in the share
  long snapshot_line = 0;    // its line index within the share (1-based)
  long too_long = -1;        // index within the share of a line over the limit
};

ShareScan scan_share(const std::filesystem::path& path, std::uint64_t b, std::uint64_t e, const InputLimits& limits) {
  ShareScan s;
  internal::FileLines lines(path, b, e, limits.max_line_bytes);
  std::string_view line;
  try {
    while (lines.next(line))
      if (!line.empty() && line[0] == 'I' && line.rfind(kAtomCountItem, 0) == 0) {
        s.snapshot = static_cast<long long>(lines.line_offset());
        s.snapshot_line = lines.lines();
      }
  } catch (const internal::FileLines::LineTooLong& t) {
    s.too_long = t.index;
  }
  s.lines = lines.lines();
  return s;
}

// A share is read by threads in pieces: equal byte ranges of at least kMinPiece bytes, which own
// their lines as shares do (file_lines.hpp). The particles and the errors do not depend on the
// number of pieces: pieces are put together in file order.
constexpr std::uint64_t kMinPiece = std::uint64_t{4} << 20;

struct Piece {
  std::uint64_t b = 0, e = 0;
  ShareScan scan;
  long first_line = 0;  // file line of the piece's first line
  std::size_t at = 0;   // where its rows go in the share's particles (its lines are an upper bound)
  std::size_t rows = 0;
  RowErrors err;
};

std::vector<Piece> scan_pieces(const std::filesystem::path& path, std::uint64_t b, std::uint64_t e,
                               const InputLimits& limits, unsigned threads) {
  const unsigned workers = internal::worker_count(threads);
  const std::uint64_t n = std::clamp<std::uint64_t>((e - std::min(b, e)) / kMinPiece, 1, 4 * workers);
  std::vector<Piece> pieces(static_cast<std::size_t>(n));
  for (std::uint64_t k = 0; k < n; ++k) {
    pieces[k].b = b + (e - b) * k / n;
    pieces[k].e = b + (e - b) * (k + 1) / n;
  }
  internal::parallel_chunks(static_cast<int>(n), threads, [&](int k) {
    Piece& p = pieces[static_cast<std::size_t>(k)];
    p.scan = scan_share(path, p.b, p.e, limits);
  }, nullptr);
  return pieces;
}

// What the pieces' scans say of the whole share (line numbers relative to its first line).
ShareScan share_scan(std::vector<Piece>& pieces) {
  ShareScan s;
  for (Piece& p : pieces) {
    if (p.scan.too_long >= 0 && s.too_long < 0) s.too_long = s.lines + p.scan.too_long;
    if (p.scan.snapshot >= 0) s.snapshot = p.scan.snapshot, s.snapshot_line = s.lines + p.scan.snapshot_line;
    p.at = static_cast<std::size_t>(s.lines);
    s.lines += p.scan.lines;
  }
  return s;
}

// Parses the rows of a piece that lie after the header into `out`, from its first line on.
void parse_piece(const std::filesystem::path& path, const Layout& L, const InputLimits& limits, Piece& piece,
                 Particle* out, long* clumps) {
  const std::uint64_t from = std::max(piece.b, L.data_begin);
  if (from >= piece.e && piece.b < piece.e) return;
  internal::FileLines lines(path, from, piece.e, limits.max_line_bytes);
  long ln = from == piece.b ? piece.first_line - 1 : L.data_line - 1;
  std::string_view line;
  std::vector<std::string_view> f;
  while (lines.next(line)) {
    ++ln;
    // Blank and comment lines: trim_view() only when the first character says the line may be one.
    if (line.empty() || line[0] == '#' || std::string_view(" \t\r\v\f\n").find(line[0]) != std::string_view::npos) {
      const std::string_view t = trim_view(line);
      if (t.empty() || (!L.lammps && t[0] == '#')) continue;
    }
    long clump = 0;
    if (parse_row(line, L, ln, f, piece.err, out[piece.rows], clump)) {
      if (clumps) clumps[piece.rows] = clump;
      ++piece.rows;
    }
  }
}

// Parses every piece on the threads and closes the gaps the headers and bad rows left.
void parse_share(const std::filesystem::path& path, const Layout& L, const InputLimits& limits, long first_line,
                 std::vector<Piece>& pieces, unsigned threads, Packing& out, RowErrors& err) {
  std::size_t lines = 0;
  for (Piece& p : pieces) {
    p.first_line = first_line + static_cast<long>(p.at);
    p.err.name = err.name;
    lines += static_cast<std::size_t>(p.scan.lines);
  }
  out.particles.resize(lines);
  const bool clumps = L.reads(kClump);
  out.clumps.resize(clumps ? lines : 0);
  internal::parallel_chunks(static_cast<int>(pieces.size()), threads, [&](int k) {
    Piece& p = pieces[static_cast<std::size_t>(k)];
    parse_piece(path, L, limits, p, out.particles.data() + p.at, clumps ? out.clumps.data() + p.at : nullptr);
  }, nullptr);
  std::size_t n = 0;
  for (const Piece& p : pieces) {
    const auto b = static_cast<std::ptrdiff_t>(p.at), e = static_cast<std::ptrdiff_t>(p.at + p.rows);
    std::copy(out.particles.begin() + b, out.particles.begin() + e,
              out.particles.begin() + static_cast<std::ptrdiff_t>(n));
    if (clumps)
      std::copy(out.clumps.begin() + b, out.clumps.begin() + e, out.clumps.begin() + static_cast<std::ptrdiff_t>(n));
    n += p.rows;
    err.merge(p.err);
  }
  out.particles.resize(n);
  out.clumps.resize(clumps ? n : 0);
}

bool starts_lammps(const std::filesystem::path& path, const InputLimits& limits) {
  internal::FileLines lines(path, 0, ~std::uint64_t{0}, limits.max_line_bytes);
  std::string_view line;
  for (bool first = true; lines.next(line); first = false) {
    if (first && line.substr(0, 3) == "\xEF\xBB\xBF") line.remove_prefix(3);
    if (!trim_view(line).empty()) return trim_view(line).rfind("ITEM:", 0) == 0;
  }
  return false;
}

}  // namespace

Packing read_packing_share(const std::filesystem::path& path, const InputLimits& limits,
                           const ProfileCommunicator* comm, unsigned threads) {
  note_input_file(path);
  const std::string name = path.string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(name, "is not a regular file (a share is a byte range)");
  const std::uint64_t size = std::filesystem::file_size(path, ec);
  if (ec) throw InputError(name, "cannot open file");
  if (size > limits.max_packing_bytes)
    throw InputError(name, "the file is larger than " + byte_count_text(limits.max_packing_bytes) +
                               ", the limit for a packing file (--max-input-mb raises it)");
  const long part = comm ? comm->rank() : 0, parts = comm ? comm->size() : 1;
  const std::uint64_t b = size * static_cast<std::uint64_t>(part) / static_cast<std::uint64_t>(parts);
  const std::uint64_t e = size * static_cast<std::uint64_t>(part + 1) / static_cast<std::uint64_t>(parts);
  // Pass 1: lines of the share; file line numbers from the shares before.
  std::vector<Piece> pieces = scan_pieces(path, b, e, limits, threads);
  const ShareScan scan = share_scan(pieces);
  const long first_line = 1 + (comm ? comm->exclusive_prefix_sum(scan.lines) : 0);
  // An input error as "where \x1f message": the lowest share's is raised by every share.
  std::string problem;
  auto raise_first = [&] {
    if (comm) problem = comm->first_error(problem);
    if (problem.empty()) return;
    const std::size_t sep = problem.find('\x1f');
    throw InputError(problem.substr(0, sep), problem.substr(sep + 1));
  };
  if (scan.too_long >= 0)
    problem = name + ":" + std::to_string(first_line + scan.too_long) + "\x1f" + "a line longer than " +
              byte_count_text(limits.max_line_bytes) + " (not a packing file? a row of numbers is under 200 bytes)";
  raise_first();
  Packing out;
  RowErrors err{name, {}, 0};
  try {
    const bool lammps = starts_lammps(path, limits);
    Layout L;
    if (lammps) {
      long long at = scan.snapshot;
      long at_line = scan.snapshot >= 0 ? first_line + scan.snapshot_line - 1 : 0;
      if (comm) {
        at = comm->max(static_cast<long>(at));
        at_line = comm->max(scan.snapshot == at ? at_line : 0);
      }
      if (at < 0) throw InputError(name, "no 'ITEM: ATOMS' section found (not a LAMMPS dump?)");
      L = lammps_layout(path, static_cast<std::uint64_t>(at), at_line, limits);
    } else {
      L = csv_layout(path, limits);
    }
    out.spherocylinders = L.sc;
    parse_share(path, L, limits, first_line, pieces, threads, out, err);
    long rows[2] = {static_cast<long>(out.particles.size()) + err.count, err.count};
    if (comm) comm->sum(std::span<long>(rows, 2));
    if (L.lammps && rows[0] != L.natoms && rows[1] == 0)
      problem = name + "\x1f" + "the last snapshot has " + std::to_string(rows[0]) +
                " atom rows, its 'ITEM: NUMBER OF ATOMS' says " + std::to_string(L.natoms);
  } catch (const InputError& x) {
    problem = x.where() + "\x1f" + x.message();  // a header error: every share finds the same one
  }
  if (problem.empty() && err.count > 0) problem = name + "\x1f" + err.message();
  raise_first();
  return out;
}

}  // namespace ssimarch

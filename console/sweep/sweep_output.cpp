#include "console/sweep/sweep_output.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "console/build_revision.hpp"
#include "console/sweep/csv_line.hpp"
#include "console/sweep/run_plan.hpp"
#include "robot/core/error.hpp"

namespace stride::sweep {
namespace {

namespace fs = std::filesystem;

std::uint64_t fnv1a(std::uint64_t h, std::string_view s) {
  for (unsigned char c : s) h = (h ^ c) * 0x100000001b3ULL;
  return (h ^ 0xff) * 0x100000001b3ULL;  // a separator, so ("ab","c") != ("a","bc")
}

std::string manifest_value(const std::string& text, const std::string& key) {
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(key + ": ", 0) == 0) return line.substr(key.size() + 2);
  return "";
}

int open_append(const fs::path& p, bool truncate) {
  const int fd = ::open(p.c_str(), O_WRONLY | O_CREAT | O_APPEND | (truncate ? O_TRUNC : 0), 0644);
  if (fd < 0) throw Error("cannot write '" + p.string() + "': " + std::strerror(errno));
  return fd;
}

// Rows of a runs.csv; a last line without its '\n' was cut by a kill and is dropped.
std::map<std::int64_t, std::vector<std::string>> read_rows(const fs::path& p,
                                                           const std::vector<std::string>& header,
                                                           std::string& kept) {
  const std::string text = read_whole_file(p);
  std::map<std::int64_t, std::vector<std::string>> rows;
  std::size_t start = 0, line_no = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    if (end == std::string::npos) break;  // unfinished
    const std::string_view line(text.data() + start, end - start);
    ++line_no;
    const auto fields = parse_csv_line(line);
    if (!fields || fields->size() != header.size())
      throw Error(p.string() + ":" + std::to_string(line_no) + ": expected " +
                  std::to_string(header.size()) + " fields (the sweep's columns)");
    if (line_no == 1) {
      if (*fields != header)
        throw Error(p.string() + ":1: the columns differ from this sweep's; not resuming");
    } else {
      std::int64_t id = -1;
      try {
        id = std::stoll((*fields)[0]);
      } catch (const std::exception&) {
        throw Error(p.string() + ":" + std::to_string(line_no) + ": bad run id");
      }
      rows[id] = *fields;
    }
    start = end + 1;
  }
  kept = text.substr(0, start);
  return rows;
}

}  // namespace

std::string read_whole_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void create_output_dir(const std::string& dir) {
  const fs::path d(dir);
  std::error_code ec;
  fs::create_directories(d, ec);
  if (ec || !fs::is_directory(d, ec))
    throw Error("--out: cannot create directory '" + dir +
                "': " + (ec ? ec.message() : std::string("not a directory")));
}

void write_whole_file(const std::string& path, const std::string& text) {
  const fs::path p(path);
  const fs::path tmp = p.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    if (!out) {
      std::error_code ignored;
      fs::remove(tmp, ignored);  // no half-written file left behind
      throw Error("cannot write '" + tmp.string() + "'");
    }
  }
  std::error_code ec;
  fs::rename(tmp, p, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw Error("cannot write '" + p.string() + "': " + ec.message());
  }
}

std::string plan_fingerprint(const Sweep& sweep) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const std::string& c : sweep.csv_header()) h = fnv1a(h, c);
  const SweepSpec& spec = sweep.spec();
  if (spec.start_heading_spread > 0 || spec.start_position_spread > 0)  // older plans: unchanged
    h = fnv1a(h, "start " + std::to_string(spec.start_heading_spread) + " " +
                     std::to_string(spec.start_position_spread));
  if (spec.robot_link != RobotLink::InProcess)  // LoLA's rows differ: never resumed as in-process
    h = fnv1a(h, spec.robot_link == RobotLink::Lola ? "link lola" : "link packets");
  for (const RunPlan& r : sweep.plan().runs) {
    for (const Setting& s : r.settings) h = fnv1a(fnv1a(h, s.target), s.value);
    for (const std::string& c : r.cells) h = fnv1a(h, c);
  }
  char buf[20];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

SweepOutput::SweepOutput(const Sweep& sweep, const std::string& dir, bool resume, bool overwrite,
                         const std::string& command)
    : sweep_(sweep), dir_(dir) {
  create_output_dir(dir);
  lock_.emplace(dir);  // before anything is read: a second sweep here must not run its walks
  const fs::path d(dir);
  const fs::path runs = d / "runs.csv";
  const std::string fingerprint = plan_fingerprint(sweep);
  const std::vector<std::string> header = sweep.csv_header();
  std::error_code ec;  // the directory was created and checked: an error reads as "absent"
  if (resume && fs::exists(runs, ec)) {
    const std::string was = manifest_value(read_whole_file(d / "manifest.txt"), "plan");
    if (was != fingerprint)
      throw Error("--resume: '" + dir + "' holds another sweep's runs (plan " +
                  (was.empty() ? "unknown" : was) + ", this one " + fingerprint +
                  "): same sweep file, seeds, scenes and settings needed");
    std::string kept;
    rows_ = read_rows(runs, header, kept);
    write_file("runs.csv", kept.empty() ? csv_line(header) : kept);  // drops a cut last line
    runs_fd_ = open_append(runs, false);
  } else {
    if (fs::exists(runs, ec) && !overwrite)
      throw Error("--out: '" + dir +
                  "' already holds a runs.csv (--resume to continue it, "
                  "--overwrite to start again)");
    runs_fd_ = open_append(runs, true);
    append(runs_fd_, csv_line(header), "runs.csv");
  }
  timing_fd_ = open_append(d / "timing.csv", !resume);
  if (!resume || fs::file_size(d / "timing.csv", ec) == 0)
    append(timing_fd_, "run,seconds,attempts,worker\n", "timing.csv");
  std::ostringstream m;
  m << "sweep: " << sweep.spec().name << "\nfile: " << sweep.spec().file
    << "\nrevision: " << console::build_revision() << "\nplan: " << fingerprint
    << "\nruns: " << sweep.plan().runs.size() << "\ncommand: " << command << "\n";
  write_file("manifest.txt", m.str());
  if (!sweep.spec().file.empty()) write_file("sweep.xml", read_whole_file(sweep.spec().file));
  fs::create_directories(d / "traces", ec);
}

SweepOutput::~SweepOutput() {
  if (runs_fd_ >= 0) ::close(runs_fd_);
  if (timing_fd_ >= 0) ::close(timing_fd_);
}

void SweepOutput::append(int fd, const std::string& text, const std::string& what) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw Error("cannot write " + dir_ + "/" + what + ": " + std::strerror(errno));
    done += static_cast<std::size_t>(n);
  }
}

// A trace that cannot be written fails its run, saying why, and the sweep goes on: one bad path
// must not end an overnight sweep. runs.csv or timing.csv failing does end it (nothing records).
void SweepOutput::add(RunRow& row, int worker) {
  if (!row.trace_csv.empty()) {
    try {
      write_file("traces/run-" + std::to_string(row.run) + ".csv", row.trace_csv);
    } catch (const Error& e) {
      row.ok = false;
      row.reason = std::string("trace not written: ") + e.what();
    }
  }
  std::vector<std::string> cells = sweep_.csv_cells(row);
  append(runs_fd_, csv_line(cells), "runs.csv");
  append(timing_fd_,
         std::to_string(row.run) + "," + number_text(row.seconds) + "," +
             std::to_string(row.attempts) + "," + std::to_string(worker) + "\n",
         "timing.csv");
  rows_[row.run] = std::move(cells);
}

void SweepOutput::sort_rows() {
  std::string text = csv_line(sweep_.csv_header());
  for (const auto& [id, cells] : rows_) text += csv_line(cells);
  write_file("runs.csv", text);
  ::close(runs_fd_);
  runs_fd_ = open_append(fs::path(dir_) / "runs.csv", false);
}

void SweepOutput::write_file(const std::string& name, const std::string& text) const {
  write_whole_file((fs::path(dir_) / name).string(), text);
}

}  // namespace stride::sweep

#include "control/journal.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string_view>

#include "control/journal_record.hpp"

namespace kerf::control {

namespace rec = journal_record;

namespace {

std::string sys_error(const std::string& path, const char* what, int err) {
  return "journal " + path + ": " + what + " (" + std::strerror(err) + ")";
}

// Splits `text` at single spaces into at most `max` words; false when there are more.
std::size_t split(std::string_view text, std::string_view* words, std::size_t max) {
  std::size_t n = 0;
  while (!text.empty()) {
    if (n == max) return max + 1;
    const std::size_t sp = text.find(' ');
    words[n++] = text.substr(0, sp);
    text = sp == std::string_view::npos ? std::string_view{} : text.substr(sp + 1);
  }
  return n;
}

template <class T>
bool number(std::string_view s, T& v, int base = 10) {
  if (s.empty()) return false;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v, base);
  return r.ec == std::errc{} && r.ptr == s.data() + s.size();
}

bool real(std::string_view s, double& v) {
  if (s.empty()) return false;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  return r.ec == std::errc{} && r.ptr == s.data() + s.size() && std::isfinite(v);
}

bool parse_header(std::string_view text, JobId& job, int& version) {
  std::string_view w[4];
  if (split(text, w, 4) != 4 || w[0] != "kerf-journal") return false;
  if (w[2].substr(0, 4) != "job=" || w[3].substr(0, 9) != "segments=") return false;
  return number(w[1], version) && number(w[2].substr(4), job.hash, 16) &&
         number(w[3].substr(9), job.segments);
}

// The cut slot: "cut none" or "cut <segment> <x> <y>".
bool parse_slot(std::string_view text, bool& has, CutPoint& p) {
  std::string_view w[4];
  const std::size_t n = split(text, w, 4);
  if (n == 2 && w[0] == "cut" && w[1] == "none") return !(has = false);
  has = true;
  return n == 4 && w[0] == "cut" && number(w[1], p.segment) && real(w[2], p.at.x) &&
         real(w[3], p.at.y);
}

// Fixed-width header or slot line into out (kMaxLine bytes).
std::size_t header_line(const JobId& job, char* out) {
  char text[rec::kMaxLine];
  const int n =
      std::snprintf(text, sizeof text, "kerf-journal %d job=%016llx segments=%u", rec::kVersion,
                    static_cast<unsigned long long>(job.hash), static_cast<unsigned>(job.segments));
  return rec::encode(text, static_cast<std::size_t>(n), rec::kFixedWidth, out);
}

std::size_t slot_line(const CutPoint* p, char* out) {
  char text[rec::kMaxLine];
  int n = 0;
  if (p == nullptr) {
    n = std::snprintf(text, sizeof text, "cut none");
  } else {
    if (!std::isfinite(p->at.x) || !std::isfinite(p->at.y)) return 0;
    n = std::snprintf(text, sizeof text, "cut %u %.6f %.6f", static_cast<unsigned>(p->segment),
                      p->at.x, p->at.y);
  }
  if (n < 0 || static_cast<std::size_t>(n) >= sizeof text) return 0;
  return rec::encode(text, static_cast<std::size_t>(n), rec::kFixedWidth, out);
}

// Parses a whole journal. Returns false with `reason` for a file that is not
// a journal or holds an impossible record (valid checksum, bad content);
// a corrupt record only ends the reading (torn_tail). `good_end` is the
// offset just past the last record trusted.
bool parse(std::string_view data, JournalState& s, std::size_t& good_end, std::string& reason) {
  s = JournalState{};
  const char* text = nullptr;
  std::size_t len = 0;
  int version = 0;
  if (data.size() < rec::kAppendOffset || !rec::decode(data.data(), rec::kFixedWidth, text, len) ||
      !parse_header({text, len}, s.job, version)) {
    reason = "line 1: not a kerf journal, or its header is corrupt";
    return false;
  }
  if (version != rec::kVersion) {
    reason = "line 1: journal version " + std::to_string(version) + " not supported";
    return false;
  }
  bool slot = false;
  CutPoint cut;
  if (!rec::decode(data.data() + rec::kSlotOffset, rec::kFixedWidth, text, len) ||
      !parse_slot({text, len}, slot, cut))
    s.cut_slot_corrupt = true;
  std::size_t at = rec::kAppendOffset;
  for (int line = 3; at < data.size(); ++line) {
    const std::size_t nl = data.find('\n', at);
    if (nl == std::string_view::npos || nl + 1 - at > rec::kMaxLine ||
        !rec::decode(data.data() + at, nl + 1 - at, text, len)) {
      s.torn_tail = true;
      break;
    }
    std::string_view w[3];
    const std::size_t n = split({text, len}, w, 2);
    std::uint32_t k = 0;
    const std::string where = "line " + std::to_string(line) + ": ";
    if (s.finished) {
      reason = where + "record after `finished`";
      return false;
    }
    if (n == 2 && w[0] == "run" && number(w[1], k)) {
      if (k != s.runs + 1) {
        reason = where + "run " + std::to_string(k) + " follows run " + std::to_string(s.runs);
        return false;
      }
      s.runs = k;
    } else if (n == 2 && w[0] == "done" && number(w[1], k)) {
      if (k >= s.job.segments || k > s.last_completed + 1) {
        reason = where + "segment " + std::to_string(k) + " done out of order (last done " +
                 std::to_string(s.last_completed) + ", " + std::to_string(s.job.segments) +
                 " segments)";
        return false;
      }
      if (k <= s.last_completed) ++s.duplicates;
      s.last_completed = std::max<std::int64_t>(s.last_completed, k);
      ++s.executed_total;
    } else if (n == 1 && w[0] == "finished") {
      s.finished = true;
    } else {
      reason = where + "unknown record '" + std::string(text, len) + "'";
      return false;
    }
    at = nl + 1;
  }
  good_end = at;
  // The slot only says something about the segment after the last one done.
  s.has_cut_to = slot && cut.segment == s.last_completed + 1;
  if (s.has_cut_to) s.cut_to = cut;
  return true;
}

bool read_all(int fd, std::string& data) {
  data.clear();
  char buf[4096];
  for (;;) {
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return false;
    if (n == 0) return true;
    data.append(buf, static_cast<std::size_t>(n));
  }
}

bool write_all(int fd, const char* p, std::size_t n, std::uint64_t at) {
  while (n > 0) {
    const ssize_t w = ::pwrite(fd, p, n, static_cast<off_t>(at));
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    p += w;
    n -= static_cast<std::size_t>(w);
    at += static_cast<std::uint64_t>(w);
  }
  return true;
}

// Makes a rename durable: the directory entry is only on disk once the directory is synced.
bool sync_dir(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  const std::string dir = slash == std::string::npos ? "."
                          : slash == 0               ? "/"
                                                     : path.substr(0, slash);
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool ok = ::fsync(fd) == 0;
  ::close(fd);
  return ok;
}

std::string hex(std::uint64_t h) {
  char b[17];
  std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(h));
  return b;
}

}  // namespace

std::unique_ptr<Journal> Journal::create(const std::string& path, const JobId& job,
                                         std::string& error) {
  // Refuse to replace a journal another controller has open.
  const int old = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (old >= 0 && ::flock(old, LOCK_EX | LOCK_NB) != 0) {
    error = "journal " + path + ": in use by another process";
    ::close(old);
    return nullptr;
  }
  const std::string tmp = path + ".tmp";
  std::unique_ptr<Journal> j(new Journal);
  j->path_ = path;
  j->error_.reserve(256);  // cut_to() reports errors without allocating
  j->fd_ = ::open(tmp.c_str(), O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  char lines[3 * rec::kMaxLine];
  std::size_t n = header_line(job, lines);
  n += slot_line(nullptr, lines + n);
  n += rec::encode("run 1", 5, 0, lines + n);
  const char* what = nullptr;
  if (j->fd_ < 0)
    what = "cannot create the temporary file";
  else if (::flock(j->fd_, LOCK_EX | LOCK_NB) != 0)
    what = "cannot lock the temporary file";
  else if (!write_all(j->fd_, lines, n, 0) || ::fsync(j->fd_) != 0)
    what = "cannot write";
  else if (::rename(tmp.c_str(), path.c_str()) != 0)
    what = "cannot rename the temporary file";
  else if (!sync_dir(path))
    what = "cannot sync its directory";
  const int err = errno;
  if (old >= 0) ::close(old);
  if (what != nullptr) {
    error = sys_error(path, what, err);
    if (j->fd_ >= 0) ::unlink(tmp.c_str());
    return nullptr;
  }
  j->append_at_ = n;
  j->state_.job = job;
  j->state_.runs = 1;
  return j;
}

std::unique_ptr<Journal> Journal::resume(const std::string& path, const JobId& job,
                                         std::string& error) {
  std::unique_ptr<Journal> j(new Journal);
  j->path_ = path;
  j->error_.reserve(256);
  j->fd_ = ::open(path.c_str(), O_RDWR | O_CLOEXEC);
  if (j->fd_ < 0) {
    error = sys_error(path, errno == ENOENT ? "no journal to resume" : "cannot open", errno);
    return nullptr;
  }
  if (::flock(j->fd_, LOCK_EX | LOCK_NB) != 0) {
    error = "journal " + path + ": in use by another process";
    return nullptr;
  }
  std::string data, reason;
  std::size_t good_end = 0;
  if (!read_all(j->fd_, data)) {
    error = sys_error(path, "cannot read", errno);
    return nullptr;
  }
  JournalState& s = j->state_;
  if (!parse(data, s, good_end, reason)) {
    error = "journal " + path + ": " + reason;
    return nullptr;
  }
  if (s.job.hash != job.hash || s.job.segments != job.segments) {
    error = "journal " + path + ": written for another job (hash " + hex(s.job.hash) + ", " +
            std::to_string(s.job.segments) + " segments; this job hash " + hex(job.hash) + ", " +
            std::to_string(job.segments) + " segments)";
    return nullptr;
  }
  if (s.finished) {
    error = "journal " + path + ": the job was finished; nothing to resume";
    return nullptr;
  }
  // Cut the torn tail off, or records appended after it would never be read.
  if (s.torn_tail && ::ftruncate(j->fd_, static_cast<off_t>(good_end)) != 0) {
    error = sys_error(path, "cannot truncate its torn tail", errno);
    return nullptr;
  }
  j->append_at_ = good_end;
  char text[32];
  const int n = std::snprintf(text, sizeof text, "run %u", static_cast<unsigned>(s.runs + 1));
  if (!j->append(text, static_cast<std::size_t>(n))) {
    error = j->error_;
    return nullptr;
  }
  ++s.runs;
  return j;
}

bool Journal::read(const std::string& path, JournalState& state, std::string& error) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    error = sys_error(path, "cannot open", errno);
    return false;
  }
  std::string data, reason;
  const bool ok = read_all(fd, data);
  const int err = errno;
  ::close(fd);
  if (!ok) {
    error = sys_error(path, "cannot read", err);
    return false;
  }
  std::size_t good_end = 0;
  if (!parse(data, state, good_end, reason)) {
    error = "journal " + path + ": " + reason;
    return false;
  }
  return true;
}

Journal::~Journal() {
  if (fd_ >= 0) ::close(fd_);  // also releases the lock
}

void Journal::fail(const char* what, int err) {
  char buf[256];  // error_ has this capacity reserved: no allocation here
  std::snprintf(buf, sizeof buf, "journal %s: %s%s%s%s", path_.c_str(), what, err != 0 ? " (" : "",
                err != 0 ? std::strerror(err) : "", err != 0 ? ")" : "");
  error_.assign(buf);
}

bool Journal::append(const char* text, std::size_t n, bool sync) {
  char line[rec::kMaxLine];
  const std::size_t len = rec::encode(text, n, 0, line);
  if (len == 0) {
    fail("record too long", 0);
    return false;
  }
  if (!write_all(fd_, line, len, append_at_) || (sync && ::fdatasync(fd_) != 0)) {
    const int err = errno;
    // Drop whatever part was written, so a later record does not follow a torn one.
    if (::ftruncate(fd_, static_cast<off_t>(append_at_)) != 0) {
    }
    fail("cannot append a record", err);
    return false;
  }
  append_at_ += len;
  return true;
}

bool Journal::sync() {
  if (::fdatasync(fd_) == 0) return true;
  fail("cannot sync", errno);
  return false;
}

bool Journal::completed(std::uint32_t segment, bool sync) {
  JournalState& s = state_;
  if (s.finished) {
    fail("completed() after finished()", 0);
    return false;
  }
  if (segment >= s.job.segments || segment > s.last_completed + 1) {
    char what[96];
    std::snprintf(what, sizeof what, "segment %u completed out of order (last %lld, %u segments)",
                  static_cast<unsigned>(segment), static_cast<long long>(s.last_completed),
                  static_cast<unsigned>(s.job.segments));
    fail(what, 0);
    return false;
  }
  char text[32];
  const int n = std::snprintf(text, sizeof text, "done %u", static_cast<unsigned>(segment));
  if (!append(text, static_cast<std::size_t>(n), sync)) return false;
  if (segment <= s.last_completed) ++s.duplicates;
  s.last_completed = std::max<std::int64_t>(s.last_completed, segment);
  ++s.executed_total;
  s.has_cut_to = s.has_cut_to && s.cut_to.segment == s.last_completed + 1;
  return true;
}

bool Journal::cut_to(const CutPoint& p) {
  char line[rec::kMaxLine];
  const std::size_t len = slot_line(&p, line);
  if (len == 0) {
    fail("cut_to: point not finite or too large", 0);
    return false;
  }
  if (!write_all(fd_, line, len, rec::kSlotOffset)) {
    fail("cannot write the cut_to slot", errno);
    return false;
  }
  state_.has_cut_to = p.segment == state_.last_completed + 1;
  if (state_.has_cut_to) state_.cut_to = p;
  return true;
}

bool Journal::finished() {
  if (!append("finished", 8)) return false;
  state_.finished = true;
  return true;
}

}  // namespace kerf::control

// The GPIO script format: `AT_SECONDS EVENT [ARGS]` per line, `#` comments.
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "kerf/sim/scripted_gpio.hpp"

namespace kerf::sim {

namespace {

std::vector<std::string> split(std::string_view line) {
  std::vector<std::string> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    std::size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r') ++j;
    if (j > i) words.emplace_back(line.substr(i, j - i));
    i = j;
  }
  return words;
}

// A whole word that is a finite number >= 0.
bool parse_seconds(const std::string& word, double& out) {
  if (word.empty()) return false;
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(word.c_str(), &end);
  if (end != word.c_str() + word.size() || errno != 0 || !std::isfinite(v) || v < 0.0)
    return false;
  out = v;
  return true;
}

bool parse_on_off(const std::string& word, bool& on) {
  if (word == "on") on = true;
  else if (word == "off") on = false;
  else return false;
  return true;
}

// `words`: EVENT [ARGS] (the time is already read). The reason on failure.
bool parse_event(const std::vector<std::string>& words, std::size_t limit_count, GpioEvent& e,
                 std::string& reason) {
  const std::string& name = words[0];
  const std::size_t nargs = words.size() - 1;
  auto too_many = [&](std::size_t allowed) {
    if (nargs <= allowed) return false;
    reason = "unexpected \"" + words[allowed + 1] + "\" after " + name;
    return true;
  };
  if (name == "estop") {
    e.kind = GpioEvent::Kind::estop;
    if (nargs < 1 || !parse_on_off(words[1], e.on)) {
      reason = "estop needs on or off";
      return false;
    }
    return !too_many(1);
  }
  if (name == "limit") {
    e.kind = GpioEvent::Kind::limit;
    char* end = nullptr;
    const long index = nargs >= 1 ? std::strtol(words[1].c_str(), &end, 10) : -1;
    if (nargs < 2 || end != words[1].c_str() + words[1].size() || words[1].empty() || index < 0 ||
        !parse_on_off(words[2], e.on)) {
      reason = "limit needs an index and on or off (limit 0 on)";
      return false;
    }
    if (static_cast<std::size_t>(index) >= limit_count) {
      reason = "limit " + words[1] + " out of range (" + std::to_string(limit_count) +
               " limit lines)";
      return false;
    }
    e.limit = static_cast<int>(index);
    return !too_many(2);
  }
  if (name == "arc-lost" || name == "no-arc") {
    e.kind = name == "arc-lost" ? GpioEvent::Kind::arc_lost : GpioEvent::Kind::no_arc;
    return !too_many(0);
  }
  if (name == "hold" || name == "cycle-start" || name == "reset") {
    e.kind = name == "hold" ? GpioEvent::Kind::hold
             : name == "reset" ? GpioEvent::Kind::reset
                               : GpioEvent::Kind::cycle_start;
    if (nargs >= 1 && (!parse_seconds(words[1], e.duration_s) || !(e.duration_s > 0.0))) {
      reason = "bad press duration \"" + words[1] + "\" (seconds > 0)";
      return false;
    }
    return !too_many(1);
  }
  reason = "unknown event \"" + name + "\"";
  return false;
}

}  // namespace

bool parse_gpio_script(std::string_view text, const std::string& source, std::size_t limit_count,
                       std::vector<GpioEvent>& out, std::string& error) {
  std::vector<GpioEvent> events;
  double last_t = 0.0;
  std::string last_word;  // the previous time as written, for the error
  std::size_t line_no = 0;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    std::size_t eol = text.find('\n', pos);
    if (eol == std::string_view::npos) eol = text.size();
    std::string_view line = text.substr(pos, eol - pos);
    pos = eol + 1;
    ++line_no;
    line = line.substr(0, line.find('#'));
    const std::vector<std::string> words = split(line);
    if (words.empty()) continue;
    const std::string where = source + ":" + std::to_string(line_no) + ": ";
    GpioEvent e;
    if (!parse_seconds(words[0], e.t_s)) {
      error = where + "bad time \"" + words[0] + "\" (seconds >= 0)";
      return false;
    }
    if (!events.empty() && e.t_s < last_t) {
      error = where + "time " + words[0] + " goes backwards (the event before is at " +
              last_word + ")";
      return false;
    }
    if (words.size() < 2) {
      error = where + "missing event after the time";
      return false;
    }
    std::string reason;
    if (!parse_event(std::vector<std::string>(words.begin() + 1, words.end()), limit_count, e,
                     reason)) {
      error = where + reason;
      return false;
    }
    last_t = e.t_s;
    last_word = words[0];
    events.push_back(e);
  }
  out.insert(out.end(), events.begin(), events.end());
  return true;
}

bool load_gpio_script(const std::string& path, std::size_t limit_count,
                      std::vector<GpioEvent>& out, std::string& error) {
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    error = path + ": cannot open the GPIO script";
    return false;
  }
  std::ostringstream text;
  text << file.rdbuf();
  return parse_gpio_script(text.str(), path, limit_count, out, error);
}

bool parse_gpio_fault(std::string_view spec, std::size_t limit_count,
                      std::vector<GpioEvent>& out, std::string& error) {
  const std::string text(spec);
  const std::string head = "--fault " + text + ": ";
  const std::size_t at = text.find('@');
  if (at == std::string::npos) {
    error = head + "expected KIND@SECONDS[:DURATION]";
    return false;
  }
  const std::string kind = text.substr(0, at);
  const std::size_t colon = text.find(':', at);
  const std::string when = text.substr(at + 1, colon == std::string::npos ? std::string::npos
                                                                          : colon - at - 1);
  GpioEvent e;
  double duration = 0.0;
  if (!parse_seconds(when, e.t_s)) {
    error = head + "bad time \"" + when + "\" (seconds >= 0)";
    return false;
  }
  if (colon != std::string::npos &&
      (!parse_seconds(text.substr(colon + 1), duration) || !(duration > 0.0))) {
    error = head + "bad duration \"" + text.substr(colon + 1) + "\" (seconds > 0)";
    return false;
  }
  std::vector<GpioEvent> events;
  if (kind == "estop" || kind.rfind("limit-", 0) == 0) {
    e.kind = kind == "estop" ? GpioEvent::Kind::estop : GpioEvent::Kind::limit;
    if (e.kind == GpioEvent::Kind::limit) {
      const std::string n = kind.substr(6);
      char* end = nullptr;
      const long index = std::strtol(n.c_str(), &end, 10);
      if (n.empty() || end != n.c_str() + n.size() || index < 0 ||
          static_cast<std::size_t>(index) >= limit_count) {
        error = head + "no limit line " + n + " (" + std::to_string(limit_count) + " limit lines)";
        return false;
      }
      e.limit = static_cast<int>(index);
    }
    events.push_back(e);
    if (duration > 0.0) {  // released again after DURATION
      GpioEvent off = e;
      off.on = false;
      off.t_s = e.t_s + duration;
      events.push_back(off);
    }
  } else if (kind == "hold" || kind == "cycle-start" || kind == "reset") {
    e.kind = kind == "hold" ? GpioEvent::Kind::hold
             : kind == "reset" ? GpioEvent::Kind::reset
                               : GpioEvent::Kind::cycle_start;
    e.duration_s = duration;
    events.push_back(e);
  } else if (kind == "arc-lost" || kind == "no-arc") {
    if (colon != std::string::npos) {
      error = head + kind + " takes no duration";
      return false;
    }
    e.kind = kind == "arc-lost" ? GpioEvent::Kind::arc_lost : GpioEvent::Kind::no_arc;
    events.push_back(e);
  } else {
    error = head + "unknown GPIO fault \"" + kind + "\"";
    return false;
  }
  out.insert(out.end(), events.begin(), events.end());
  return true;
}

}  // namespace kerf::sim

#include "job/program_window.hpp"

#include <cmath>

#include "job/gcode_expr.hpp"

namespace kerf::job {

namespace {

// One line's torch word, program end and the like (scan_program).
struct LineFacts {
  bool torch = false, end = false, unknown = false;
};

// `words`: letter and value (NaN: computed when the line runs).
template <class Words>
LineFacts line_facts(const Words& words, int torch_output) {
  LineFacts f;
  bool out_on = false;
  double p = std::nan("");
  bool has_p = false;
  for (const auto& [letter, v] : words) {
    if (letter == 'P') has_p = true, p = v;
    if (letter != 'M' || std::isnan(v)) continue;
    const int c = code10(v);
    if (c == 30 || c == 40) f.torch = true;
    if (c == 20 || c == 300) f.end = true;
    if (c == 620 || c == 640) out_on = true;
  }
  if (out_on && torch_output >= 0 && has_p) {
    if (std::isnan(p)) f.unknown = true;
    else if (p >= 0 && p <= 255 && p == std::floor(p) && std::lround(p) == torch_output) f.torch = true;
  }
  return f;
}

}  // namespace

bool scan_program(const std::string& file, const InterpSettings& settings, std::size_t part_bytes, ProgramScan& scan,
                  std::string& error) {
  scan = ProgramScan{};
  GcodePartReader reader;
  if (!reader.open(file, part_bytes, error)) return false;
  GcodeFile part;
  bool ended = false;
  std::vector<std::pair<char, double>> words;
  ExprPool pool;
  LineCode code;
  std::string why;
  while (reader.next(part, error)) {
    if (!part.ok) return error = describe_error(part), false;
    for (const GBlock& b : part.blocks) {
      if (b.dynamic) {
        pool.nodes.clear();
        code = LineCode{};
        if (!parse_line(b.text, pool, code, why)) return error = where(file, b.line) + why, false;
        if (code.oword != LineCode::Oword::none) return scan.o_words = true, true;
      }
      if (ended) continue;
      words.clear();
      if (b.dynamic) {
        for (const LineCode::Word& w : code.words) {
          const ExprNode& n = pool.nodes[static_cast<std::size_t>(w.expr)];
          words.emplace_back(w.letter, n.op == ExprNode::Op::number ? n.value : std::nan(""));
        }
      } else {
        for (const GWord& w : b.words) words.emplace_back(w.letter, w.value);
      }
      const LineFacts f = line_facts(words, settings.torch_output);
      scan.torch_word = scan.torch_word || f.torch;
      scan.torch_unknown = scan.torch_unknown || f.unknown;
      ended = f.end;
    }
  }
  return error.empty();
}

WindowProgramStream::WindowProgramStream(const InterpSettings& settings, const MachineState& state, bool dry_run)
    : settings_(settings),
      dry_run_(dry_run),
      interp_(settings_, state, it_),
      flow_(part_, [this](std::string_view pin, double& v, std::string& why) {
        return qtplasmac_pin(pin, interp_.hal_cut_feed(), v, why);
      }, settings_.max_blocks, it_.constructs, it_.notes),
      builder_(settings_.z_axis, dry_run, settings_.start, window_) {
  summary_.dry_run = dry_run;
}

bool WindowProgramStream::open(const std::string& file, std::size_t part_bytes, std::string& error) {
  summary_.points.file = file;
  return reader_.open(file, part_bytes, error);
}

ProgramStream::Next WindowProgramStream::next(ProgramPiece& path, ProgramAction& action) {
  for (;;) {
    if (action_at_ < window_.actions.size() && window_.actions[action_at_].before_path <= builder_.paths_taken()) {
      action = window_.actions[action_at_++];
      if (action_at_ == window_.actions.size()) window_.actions.clear(), action_at_ = 0;
      return Next::action;
    }
    if (builder_.first_path_final()) {
      builder_.take_first_path(path);
      return Next::path;
    }
    if (state_ == State::failed) return Next::error;
    if (state_ == State::ended) return Next::end;
    advance();
  }
}

// One step: a canonical move built, a block run, or the next part read.
void WindowProgramStream::advance() {
  if (canon_at_ < it_.canon.size()) {
    builder_.step(it_.canon[canon_at_++]);
    if (canon_at_ == it_.canon.size()) it_.canon.clear(), canon_at_ = 0;
    return;
  }
  if (interp_.ended()) return finish();
  const GBlock* b = nullptr;
  std::span<const GWord> words;
  std::string error, why;
  if (flow_.next(b, words, error)) {
    if (!interp_.run(b->line, words, why)) fail(where(part_.file, b->line) + why);
    return;
  }
  if (!error.empty()) return fail(error);
  if (!reader_.next(part_, error)) return error.empty() ? finish() : fail(error);
  if (!part_.ok) return fail(describe_error(part_));
  if (!flow_.start_part(part_, error)) fail(error);
}

void WindowProgramStream::finish() {
  summary_.interp.constructs = it_.constructs;
  builder_.finish(summary_.interp.constructs);
  summary_.interp.notes = it_.notes;
  summary_.interp.state = it_.state;
  summary_.interp.analog_inputs = it_.analog_inputs;
  summary_.z_moves = window_.z_moves;
  summary_.final_z = window_.final_z;
  summary_.points.duplicates_dropped = window_.points.duplicates_dropped;
  state_ = State::ended;
  if (builder_.paths_taken() + window_.paths.size() == 0)
    fail(summary_.points.file + ": no cut moves (G1/G2/G3" + (dry_run_ ? std::string(")") : " with the torch on)"));
}

void WindowProgramStream::fail(std::string why) {
  error_ = std::move(why);
  state_ = State::failed;
}

}  // namespace kerf::job

#include "job/gcode_flow.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "io/point_file.hpp"
#include "job/gcode_interp.hpp"

namespace kerf::job {

using Oword = LineCode::Oword;

bool is_qtplasmac_directive(const std::string& name) {
  static const char* const kNames[] = {"holes",    "h_diameter",   "h_velocity", "i_diameter", "m_diameter",
                                       "oclength", "pierce-only", "keep-z-motion", "tube-cut"};
  for (const char* n : kNames)
    if (name == n) return true;
  return false;
}

bool qtplasmac_pin(std::string_view pin, double cut_feed, double& value, std::string& reason) {
  if (pin == "plasmac.cut-feed-rate") return value = cut_feed, true;
  reason = "#<_hal[" + std::string(pin) + "]>: kerf has no such pin (of QtPlasmaC's, only plasmac.cut-feed-rate)";
  return false;
}

// Each pin read is recorded for the report, at the line that reads it.
GcodeFlow::GcodeFlow(const GcodeFile& g, GcodeParams::HalRead hal, std::size_t max_blocks,
                     std::map<std::string, Construct>& constructs, std::vector<std::string>& notes)
    : g_(&g),
      params_([this, hal = std::move(hal)](std::string_view pin, double& v, std::string& why) {
        if (!hal(pin, v, why)) return false;
        seen("#<_hal[" + std::string(pin) + "]>", "run", line());
        return true;
      }),
      max_blocks_(max_blocks),
      constructs_(constructs),
      notes_(notes) {}

bool GcodeFlow::fail(std::size_t line, std::string why) {
  error_ = g_->file + ":" + std::to_string(line) + ": " + why;
  return false;
}

void GcodeFlow::seen(const std::string& name, const char* handling, std::size_t line) {
  Construct& c = constructs_[name];
  if (c.count++ == 0) c.first_line = line, c.handling = handling;
}

bool GcodeFlow::start_part(const GcodeFile& part, std::string& error) {
  g_ = &part;
  code_of_.clear();
  codes_.clear();
  pool_.nodes.clear();
  pc_ = run_ = 0;
  return prepare(error);
}

bool GcodeFlow::prepare(std::string& error) {
  code_of_.assign(g_->blocks.size(), -1);
  for (std::size_t i = 0; i < g_->blocks.size(); ++i) {
    const GBlock& b = g_->blocks[i];
    if (!b.dynamic) continue;
    LineCode code;
    std::string why;
    if (!parse_line(b.text, pool_, code, why)) return fail(b.line, why), error = error_, false;
    code_of_[i] = static_cast<int>(codes_.size());
    codes_.push_back(std::move(code));
  }
  return match(error);
}

// Pairs each O-word with the block that closes it, like LinuxCNC's o-word
// stack, and refuses what would not run: an unclosed or crossed block, a
// break outside its loop, a call to a subroutine that is not in the file.
bool GcodeFlow::match(std::string& error) {
  struct Open {
    std::size_t at;
    Oword kind;
    std::size_t last_branch;
  };
  if (codes_.empty()) return true;  // a plain program: nothing to match
  std::vector<Open> stack;
  partner_.assign(g_->blocks.size(), 0);
  next_branch_.assign(g_->blocks.size(), 0);
  auto code = [&](std::size_t i) -> const LineCode& { return codes_[static_cast<std::size_t>(code_of_[i])]; };
  auto name = [&](std::size_t i) { return "o" + code(i).oname + " " + oword_name(code(i).oword); };
  auto bad = [&](std::size_t i, const std::string& why) { return fail(g_->blocks[i].line, why), error = error_, false; };
  std::vector<std::size_t> calls;
  for (std::size_t i = 0; i < g_->blocks.size(); ++i) {
    if (code_of_[i] < 0 || code(i).oword == Oword::none) continue;
    const LineCode& c = code(i);
    const bool top_ok = !stack.empty() && code(stack.back().at).oname == c.oname;
    const Oword top = stack.empty() ? Oword::none : stack.back().kind;
    auto closes = [&](Oword opener) {
      if (!top_ok || top != opener)
        return bad(i, name(i) + (stack.empty() ? " closes nothing"
                                               : " does not close " + name(stack.back().at) + " (line " +
                                                     std::to_string(g_->blocks[stack.back().at].line) + ")"));
      partner_[i] = stack.back().at;
      partner_[stack.back().at] = i;
      stack.pop_back();
      return true;
    };
    auto enclosing = [&](std::initializer_list<Oword> kinds) -> const Open* {
      for (auto it = stack.rbegin(); it != stack.rend(); ++it)
        if (code(it->at).oname == c.oname && std::find(kinds.begin(), kinds.end(), it->kind) != kinds.end())
          return &*it;
      return nullptr;
    };
    switch (c.oword) {
      case Oword::sub:
        if (!stack.empty()) return bad(i, name(i) + " inside " + name(stack.back().at) + ": subroutines nest not");
        if (subs_.count(c.oname) != 0) return bad(i, name(i) + ": the subroutine is defined twice");
        subs_[c.oname] = i;
        stack.push_back({i, c.oword, i});
        break;
      case Oword::while_:
        if (top_ok && top == Oword::do_) {
          if (!closes(Oword::do_)) return false;
          break;
        }
        [[fallthrough]];
      case Oword::do_: case Oword::if_: case Oword::repeat: stack.push_back({i, c.oword, i}); break;
      case Oword::endsub: if (!closes(Oword::sub)) return false; break;
      case Oword::endwhile: if (!closes(Oword::while_)) return false; break;
      case Oword::endrepeat: if (!closes(Oword::repeat)) return false; break;
      case Oword::elseif: case Oword::else_:
        if (!top_ok || top != Oword::if_) return bad(i, name(i) + " without its o" + c.oname + " if");
        if (code(stack.back().last_branch).oword == Oword::else_) return bad(i, name(i) + " after o" + c.oname + " else");
        next_branch_[stack.back().last_branch] = i;
        stack.back().last_branch = i;
        partner_[i] = stack.back().at;
        break;
      case Oword::endif: {
        if (top_ok && top == Oword::if_) next_branch_[stack.back().last_branch] = i;
        if (!closes(Oword::if_)) return false;
        break;
      }
      case Oword::break_: case Oword::continue_: {
        const Open* loop = enclosing({Oword::while_, Oword::do_, Oword::repeat});
        if (loop == nullptr) return bad(i, name(i) + " outside a loop o" + c.oname);
        partner_[i] = loop->at;
        break;
      }
      case Oword::return_: {
        const Open* sub = enclosing({Oword::sub});
        if (sub == nullptr) return bad(i, name(i) + " outside o" + c.oname + " sub");
        break;
      }
      case Oword::call: calls.push_back(i); break;
      case Oword::none: break;
    }
    if ((c.oword == Oword::if_ || c.oword == Oword::elseif || c.oword == Oword::while_ ||
         c.oword == Oword::repeat) && c.args.size() != 1)
      return bad(i, name(i) + " needs one [condition or count]");
  }
  if (!stack.empty()) {
    const Oword k = stack.back().kind;
    const char* closer = k == Oword::sub ? "endsub" : k == Oword::do_ ? "while" : k == Oword::if_ ? "endif"
                         : k == Oword::repeat ? "endrepeat" : "endwhile";
    return bad(stack.back().at, name(stack.back().at) + " has no o" + code(stack.back().at).oname + " " + closer);
  }
  for (const std::size_t i : calls)
    if (subs_.count(code(i).oname) == 0)
      return bad(i, name(i) + ": no o" + code(i).oname +
                        " sub in this file (subroutines in files of their own are not supported)");
  return true;
}

bool GcodeFlow::value(int expr, double& v, std::size_t line) {
  std::string why;
  if (!eval_expr(pool_, expr, params_, v, why)) return fail(line, why);
  return true;
}

bool GcodeFlow::condition(std::size_t at, const LineCode& code, bool& truth) {
  double v = 0;
  if (!value(code.args.at(0), v, g_->blocks[at].line)) return false;
  truth = v != 0;
  return true;
}

bool GcodeFlow::run_oword(std::size_t at, const LineCode& c) {
  const std::size_t line = g_->blocks[at].line;
  seen(std::string("O-word ") + oword_name(c.oword), "run", line);
  auto code = [&](std::size_t i) -> const LineCode& { return codes_[static_cast<std::size_t>(code_of_[i])]; };
  bool truth = false;
  switch (c.oword) {
    case Oword::sub: pc_ = partner_[at] + 1; return true;
    case Oword::endsub: case Oword::return_: {
      if (calls_.empty()) return pc_ = at + 1, true;
      if (!c.args.empty()) {
        double v = 0;
        if (!value(c.args[0], v, line)) return false;
        params_.write("_value", v);
        params_.write("_value_returned", 1);
      }
      repeats_.resize(calls_.back().repeats);
      params_.pop_call();
      pc_ = calls_.back().return_to;
      calls_.pop_back();
      return true;
    }
    case Oword::call: {
      std::vector<double> args(c.args.size());
      for (std::size_t k = 0; k < args.size(); ++k)
        if (!value(c.args[k], args[k], line)) return false;
      std::string why;
      if (!params_.push_call(args, why)) return fail(line, why);
      calls_.push_back({at + 1, repeats_.size()});
      pc_ = subs_.at(c.oname) + 1;
      return true;
    }
    case Oword::if_: {
      for (std::size_t j = at;; j = next_branch_[j]) {
        const Oword k = code(j).oword;
        if (k == Oword::else_ || k == Oword::endif) return pc_ = j + 1, true;
        if (!condition(j, code(j), truth)) return false;
        if (truth) return pc_ = j + 1, true;
      }
    }
    case Oword::elseif: case Oword::else_: pc_ = partner_[partner_[at]] + 1; return true;  // a branch ran
    case Oword::endif: case Oword::do_: pc_ = at + 1; return true;
    case Oword::while_:
      if (!condition(at, c, truth)) return false;
      if (code(partner_[at]).oword == Oword::do_) pc_ = truth ? partner_[at] + 1 : at + 1;
      else pc_ = truth ? at + 1 : partner_[at] + 1;
      return true;
    case Oword::endwhile: pc_ = partner_[at]; return true;
    case Oword::repeat: {
      double n = 0;
      if (!value(c.args.at(0), n, line)) return false;
      if (n < 1) return pc_ = partner_[at] + 1, true;
      repeats_.push_back({at, static_cast<long long>(std::min(n, 1e15))});
      pc_ = at + 1;
      return true;
    }
    case Oword::endrepeat:
      if (repeats_.empty() || repeats_.back().at != partner_[at]) return fail(line, "internal: repeat count lost");
      if (--repeats_.back().left > 0) return pc_ = partner_[at] + 1, true;
      repeats_.pop_back();
      pc_ = at + 1;
      return true;
    case Oword::break_: case Oword::continue_: {
      const std::size_t open = partner_[at], end = partner_[open];  // endwhile, endrepeat or a do's while
      const std::size_t floor = calls_.empty() ? 0 : calls_.back().repeats;
      const bool leave = c.oword == Oword::break_;
      while (repeats_.size() > floor && repeats_.back().at >= open && repeats_.back().at <= end &&
             (leave || repeats_.back().at != open))
        repeats_.pop_back();
      const bool head = code(open).oword == Oword::while_;
      pc_ = leave ? end + 1 : head ? open : end;
      return true;
    }
    case Oword::none: break;
  }
  return true;
}

bool GcodeFlow::run_dynamic(const GBlock& b, const LineCode& c) {
  words_.clear();
  bool letters[27] = {};
  for (const LineCode::Word& w : c.words) {
    GWord g;
    g.letter = w.letter;
    if (!value(w.expr, g.value, b.line)) return false;
    if (std::fabs(g.value) > io::kMaxCoordinate) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%c = %g: a value out of range", w.letter, g.value);
      return fail(b.line, buf);
    }
    const int k = w.letter == '$' ? 26 : w.letter - 'A';
    if (w.letter != 'G' && w.letter != 'M' && letters[k]) return fail(b.line, std::string("word ") + w.letter + " appears twice");
    letters[k] = true;
    words_.push_back(g);
  }
  // Every read on the line before any assignment takes effect.
  struct Set {
    const ExprNode* target;
    int number;
    double v;
  };
  std::vector<Set> sets;
  for (const LineCode::Assign& a : c.assigns) {
    Set s{&pool_.nodes[static_cast<std::size_t>(a.target)], 0, 0};
    double n = 0;
    if (s.target->op == ExprNode::Op::param) {
      if (!value(s.target->a, n, b.line)) return false;
      if (std::fabs(n - std::round(n)) > 1e-4 || std::fabs(n) > 1e6) return fail(b.line, "a parameter number must be an integer");
      s.number = static_cast<int>(std::lround(n));
    }
    if (!value(a.expr, s.v, b.line)) return false;
    sets.push_back(s);
  }
  for (const Set& s : sets) {
    if (s.target->op == ExprNode::Op::named) {
      if (s.target->name.rfind("_hal[", 0) == 0) return fail(b.line, "#<" + s.target->name + ">: a HAL pin cannot be set");
      params_.write(s.target->name, s.v);
      if (is_qtplasmac_directive(s.target->name)) {
        const std::string name = "#<" + s.target->name + ">";
        if (constructs_.count(name) == 0)
          notes_.push_back(name + " (line " + std::to_string(b.line) +
                           "): QtPlasmaC directive, recorded: kerf's [cut] rules apply");
        seen(name, "recorded", b.line);
      }
    } else {
      std::string why;
      if (!params_.write(s.number, s.v, why)) return fail(b.line, why);
    }
  }
  if (b.text.find('#') != std::string_view::npos) seen("# parameters", "run", b.line);
  if (b.text.find('[') != std::string_view::npos) seen("[...] expressions", "run", b.line);
  return true;
}

bool GcodeFlow::next(const GBlock*& block, std::span<const GWord>& words, std::string& error) {
  while (pc_ < g_->blocks.size()) {
    const std::size_t i = pc_;
    const GBlock& b = g_->blocks[i];
    if (!b.dynamic && b.words.empty()) {
      ++pc_;
      continue;
    }
    // Only what loops run again counts: a straight file of any length is never refused.
    if (++run_ > g_->blocks.size() + max_blocks_) {
      fail(b.line, "loops run more than " + std::to_string(max_blocks_) +
                       " blocks beyond the file's own (a loop that never ends?)");
      error = error_;
      return false;
    }
    if (!b.dynamic) {
      ++pc_;
      block = &b;
      words = b.words;
      return true;
    }
    const LineCode& c = codes_[static_cast<std::size_t>(code_of_[i])];
    const bool ok = c.oword != Oword::none ? run_oword(i, c) : run_dynamic(b, c);
    if (!ok) return error = error_, false;
    if (c.oword != Oword::none) continue;
    ++pc_;
    if (words_.empty()) continue;
    block = &b;
    words = words_;
    return true;
  }
  return false;
}

}  // namespace kerf::job

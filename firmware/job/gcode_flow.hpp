// Running a G-code file's blocks in program order: parameters, expressions
// and O-word control flow with LinuxCNC's meaning (o-code.adoc):
// `oN sub`/`endsub`/`return` and `oN call [args]` (#1..#30, subroutines of
// the same file only), `if`/`elseif`/`else`/`endif`, `while`/`endwhile`,
// `do`/`while`, `repeat [n]`/`endrepeat`, `break`, `continue`. Each block
// it yields has every word's value computed; the interpreter
// (job/gcode_interp.hpp) gives them their meaning.
//
// On a line, every parameter is read before any of its assignments takes
// effect (LinuxCNC's rule). The blocks run are counted, and a program whose
// loops run more than `max_blocks` beyond the file's own blocks (a loop that
// never ends) is refused at the block that passes the cap: nothing runs
// blind, nothing hangs, and a long straight file is never refused.
#pragma once

#include <cstddef>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "job/gcode_expr.hpp"
#include "job/gcode_params.hpp"
#include "job/gcode_reader.hpp"

namespace kerf::job {

struct Construct;

// QtPlasmaC's G-code filter directives (#<holes> = 2 ...): recorded, kerf's
// own [cut] rules do that work.
bool is_qtplasmac_directive(const std::string& name);

// QtPlasmaC's #<_hal[plasmac.cut-feed-rate]> reads `cut_feed` (the cut feed
// in the program's units); kerf has no other pin: false with the reason.
bool qtplasmac_pin(std::string_view pin, double cut_feed, double& value, std::string& reason);

class GcodeFlow {
 public:
  GcodeFlow(const GcodeFile& g, GcodeParams::HalRead hal, std::size_t max_blocks,
            std::map<std::string, Construct>& constructs, std::vector<std::string>& notes);

  // Parses the marked lines and matches the O-words. False with "FILE:LINE: reason".
  bool prepare(std::string& error);
  // The window reading (job/program_window.hpp), for a file without
  // O-words: runs `part` (the file's next lines) from its first block, its
  // marked lines parsed; the parameters carry on. False with "FILE:LINE: reason".
  bool start_part(const GcodeFile& part, std::string& error);
  // The next block to run, with its words' values: false at the end of the
  // file, or on an error (then `error` is "FILE:LINE: reason").
  bool next(const GBlock*& block, std::span<const GWord>& words, std::string& error);
  // The line of the block being run (for what a parameter read records).
  std::size_t line() const { return pc_ < g_->blocks.size() ? g_->blocks[pc_].line : 0; }

 private:
  struct Frame {  // a call in progress
    std::size_t return_to = 0;
    std::size_t repeats = 0;  // repeat_ size at the call
  };
  struct Repeat {
    std::size_t at = 0;  // the repeat line's block
    long long left = 0;
  };
  bool fail(std::size_t line, std::string why);
  bool value(int expr, double& v, std::size_t line);
  bool run_dynamic(const GBlock& b, const LineCode& code);
  bool run_oword(std::size_t at, const LineCode& code);
  bool condition(std::size_t at, const LineCode& code, bool& truth);
  bool match(std::string& error);
  void seen(const std::string& name, const char* handling, std::size_t line);

  const GcodeFile* g_;
  GcodeParams params_;
  std::size_t max_blocks_;
  std::map<std::string, Construct>& constructs_;
  std::vector<std::string>& notes_;
  ExprPool pool_;
  std::vector<int> code_of_;       // per block: index in codes_, or -1 (a plain block)
  std::vector<LineCode> codes_;
  std::vector<std::size_t> partner_;  // per O-word block: its loop/if/sub's closing block (or opening, for closers)
  std::vector<std::size_t> next_branch_;  // if/elseif/else: the next branch of its chain
  std::map<std::string, std::size_t> subs_;  // o-name -> its sub line's block
  std::vector<Frame> calls_;
  std::vector<Repeat> repeats_;
  std::vector<GWord> words_;
  std::size_t pc_ = 0, run_ = 0;
  std::string error_;
};

}  // namespace kerf::job

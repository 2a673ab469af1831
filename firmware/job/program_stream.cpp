#include "job/program_stream.hpp"

#include <filesystem>
#include <system_error>
#include <utility>

#include "job/program_window.hpp"

namespace kerf::job {

WholeProgramStream::WholeProgramStream(GcodeProgram program) : program_(std::move(program)) {
  summary_.points.file = program_.points.file;
  summary_.interp = program_.interp;
  summary_.dry_run = program_.dry_run;
  summary_.z_moves = program_.z_moves;
  summary_.final_z = program_.final_z;
  summary_.points.duplicates_dropped = program_.points.duplicates_dropped;
}

ProgramStream::Next WholeProgramStream::next(ProgramPiece& path, ProgramAction& action) {
  const std::vector<std::size_t>& begins = program_.points.path_begin;
  if (action_ < program_.actions.size() && program_.actions[action_].before_path <= path_) {
    action = program_.actions[action_++];
    return Next::action;
  }
  if (path_ >= begins.size()) return Next::end;
  const auto b = static_cast<std::ptrdiff_t>(begins[path_]);
  const auto e = static_cast<std::ptrdiff_t>(path_ + 1 < begins.size() ? begins[path_ + 1] : program_.points.points.size());
  const io::PointFile& in = program_.points;
  path.path = program_.paths[path_];
  path.points.assign(in.points.begin() + b, in.points.begin() + e);
  path.lines.assign(in.point_lines.begin() + b, in.point_lines.begin() + e);
  path.feed.clear();
  for (auto k = b; k < e; ++k)
    path.feed.push_back(static_cast<std::size_t>(k) < program_.point_feed.size() ? program_.point_feed[static_cast<std::size_t>(k)] : 0.0);
  ++path_;
  return Next::path;
}

bool open_program_stream(const std::string& file, const InterpSettings& settings, const MachineState& state,
                         std::unique_ptr<ProgramStream>& out, std::string& error) {
  return open_program_stream(file, settings, state, ProgramStreamOptions{}, out, error);
}

bool open_program_stream(const std::string& file, const InterpSettings& settings, const MachineState& state,
                         const ProgramStreamOptions& options, std::unique_ptr<ProgramStream>& out,
                         std::string& error) {
  error.clear();
  ProgramScan scan;
  // A pipe (stdin, a named pipe) cannot be read twice: it is read whole.
  std::error_code ec;
  const bool regular = std::filesystem::is_regular_file(file, ec);
  const bool whole = options.whole || !regular ||
                     (scan_program(file, settings, options.part_bytes, scan, error) &&
                      (scan.o_words || scan.torch_unknown));
  if (whole) {
    GcodeProgram program;
    if (!read_gcode_program(file, settings, state, program, error)) return false;
    out = std::make_unique<WholeProgramStream>(std::move(program));
    return true;
  }
  if (!error.empty()) return false;
  auto window = std::make_unique<WindowProgramStream>(settings, state, !scan.torch_word);
  if (!window->open(file, options.part_bytes, error)) return false;
  out = std::move(window);
  return true;
}

}  // namespace kerf::job

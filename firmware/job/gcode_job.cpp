// A G-code file as a job's cut paths (job/gcode_reader.hpp: read_gcode_job):
// the interpreter's program (job/gcode_program.hpp) with the default
// settings, its points only (`kerf fit`, `kerf plan`).
#include <cctype>
#include <string>

#include "job/gcode_program.hpp"
#include "job/gcode_reader.hpp"

namespace kerf::job {

bool gcode_job_from(const GcodeFile& g, io::PointFile& out, std::string& error) {
  out = io::PointFile{};
  out.file = g.file;
  GcodeProgram prog;
  Interpretation it;
  const InterpSettings settings;
  if (!interpret(g, settings, MachineState{}, it, error) || !build_program(g, settings, it, prog, error)) {
    out.ok = false;
    out.reason = error;
    return false;
  }
  out = std::move(prog.points);
  return true;
}

bool read_gcode_job(const std::string& path, io::PointFile& out, std::string& error) {
  const GcodeFile g = read_gcode(path);
  if (!g.ok) {
    out = io::PointFile{};
    out.file = g.file;
    out.line = g.line;
    out.reason = g.reason;
    error = describe_error(g);
    return false;
  }
  return gcode_job_from(g, out, error);
}

bool is_gcode_path(const std::string& path) {
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || path.find('/', dot) != std::string::npos) return false;
  std::string ext;
  for (char c : path.substr(dot + 1)) ext += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const char* e : {"nc", "ngc", "gcode", "gco", "gc", "tap", "cnc"})
    if (ext == e) return true;
  return false;
}

}  // namespace kerf::job

#include "job/gcode_program.hpp"

#include "job/program_builder.hpp"

namespace kerf::job {

bool build_program(const GcodeFile& g, const InterpSettings& settings, const Interpretation& it, GcodeProgram& out,
                   std::string& error) {
  out = GcodeProgram{};
  out.points.file = g.file;
  out.interp.constructs = it.constructs;  // not the canonical moves: the points hold them
  bool torch_word = false;
  for (const Canon& c : it.canon)
    if (c.kind == CanonKind::torch && c.index == 1) torch_word = true;
  out.dry_run = !torch_word;
  ProgramBuilder b(settings.z_axis, out.dry_run, settings.start, out);
  for (const Canon& c : it.canon) b.step(c);
  b.finish(out.interp.constructs);
  out.interp.notes = it.notes;
  out.interp.state = it.state;
  out.interp.analog_inputs = it.analog_inputs;
  if (out.paths.empty()) {
    error = g.file + ": no cut moves (G1/G2/G3" + (out.dry_run ? std::string(")") : " with the torch on)");
    return false;
  }
  out.points.ok = true;
  return true;
}

bool read_gcode_program(const std::string& path, const InterpSettings& settings, const MachineState& state,
                        GcodeProgram& out, std::string& error) {
  const GcodeFile g = read_gcode(path);
  if (!g.ok) {
    error = describe_error(g);
    return false;
  }
  Interpretation it;
  if (!interpret(g, settings, state, it, error)) return false;
  return build_program(g, settings, it, out, error);
}

}  // namespace kerf::job

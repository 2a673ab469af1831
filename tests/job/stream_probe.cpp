// Reads a G-code program through open_program_stream and prints what it
// gave: the child process whose peak memory and time the scale test
// (test_program_window_scale.cpp) measures.
//   kerf_program_stream_probe FILE window|whole [PART_BYTES]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "job/program_stream.hpp"

int main(int argc, char** argv) {
  using namespace kerf::job;
  if (argc < 3) return std::fprintf(stderr, "usage: %s FILE window|whole [PART_BYTES]\n", argv[0]), 2;
  const auto t0 = std::chrono::steady_clock::now();
  ProgramStreamOptions o;
  o.whole = std::string(argv[2]) == "whole";
  if (argc > 3) o.part_bytes = std::strtoull(argv[3], nullptr, 10);
  std::unique_ptr<ProgramStream> s;
  std::string error;
  InterpSettings settings;
  if (!open_program_stream(argv[1], settings, MachineState{}, o, s, error))
    return std::fprintf(stderr, "%s\n", error.c_str()), 1;
  ProgramPiece piece;
  ProgramAction action;
  unsigned long long paths = 0, points = 0, actions = 0;
  double first = -1;
  for (;;) {
    const ProgramStream::Next n = s->next(piece, action);
    if (n == ProgramStream::Next::path) {
      if (paths++ == 0) first = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      points += piece.points.size();
    } else if (n == ProgramStream::Next::action) {
      ++actions;
    } else if (n == ProgramStream::Next::end) {
      break;
    } else {
      return std::fprintf(stderr, "%s\n", s->error().c_str()), 1;
    }
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("paths %llu points %llu actions %llu first_path_s %.4f seconds %.4f\n", paths, points, actions, first,
              secs);
  return 0;
}

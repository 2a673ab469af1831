#include "control/streamed_job.hpp"

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <thread>

#include "control/job_producer.hpp"
#include "control/fnv1a.hpp"
#include "control/stream_job_source.hpp"
#include "job/gcode_reader.hpp"
#include "job/program_stream.hpp"

namespace kerf::control {

namespace {

// What decides the segments and actions besides the file's bytes: the fit,
// the feeds, the rules, the holds, the interpreter's settings and the offsets.
void hash_setup(const StreamedJobSetup& s, bool gcode, Fnv1a& f) {
  f.value(std::uint64_t{gcode ? 0x5354474bu : 0x53545054u});  // a streamed job: never a whole job's id
  f.value(static_cast<std::uint32_t>(s.criterion));
  f.value(static_cast<std::uint32_t>(s.numeric));
  f.value(s.tol);
  f.value(s.feed_mm_s);
  f.value(s.max_feed_mm_s);
  f.value(s.rules.has_value());
  if (s.rules) {
    const config::CutRules& r = *s.rules;
    for (double v : {r.hole_diameter, r.hole_feed, r.arc_radius, r.arc_feed, r.overcut}) f.value(v);
  }
  f.value(s.torch_off);
  f.value(s.outputs_off);
  if (!gcode) return;
  const job::InterpSettings& i = s.interp;
  for (double v : {i.start[0], i.start[1], i.fit_tol, i.cut_feed}) f.value(v);
  for (int v : {i.torch_output, i.mist_output, i.flood_output}) f.value(v);
  f.value(i.z_axis);
  for (const auto& [tool, m] : i.tool_material) {
    f.value(tool);
    f.text(m.name);
    f.value(m.feed_mm_min);
    f.value(m.pierce_delay_s);
  }
  for (const auto& [m, u] : i.mcodes) {
    f.value(m);
    f.value(static_cast<int>(u.action));
    f.value(u.output);
    f.value(u.seconds);
  }
  const job::MachineState& st = s.state;
  for (const auto& sys : st.g5x)
    for (double v : sys) f.value(v);
  f.value(st.coord);
  for (double v : st.g92) f.value(v);
  f.value(st.g92_on);
}

bool hash_file(const std::string& file, Fnv1a& f, std::string& error) {
  std::FILE* in = std::fopen(file.c_str(), "rb");
  if (in == nullptr) {
    error = file + ": cannot open: " + std::strerror(errno);
    return false;
  }
  static thread_local char buf[1 << 16];
  std::size_t got = 0;
  while ((got = std::fread(buf, 1, sizeof buf, in)) > 0) f.bytes(buf, got);
  const bool ok = std::ferror(in) == 0;
  if (!ok) error = file + ": cannot read: " + std::strerror(errno);
  std::fclose(in);
  return ok;
}

void nap() { std::this_thread::sleep_for(std::chrono::microseconds(200)); }

}  // namespace

struct StreamedJob::Impl {
  std::string file;
  StreamedJobSetup setup;
  bool gcode = false;
  JobId id{};
  std::unique_ptr<JobItemRing> ring;
  std::unique_ptr<JobProducer> producer;
  std::unique_ptr<StreamJobSource> source;
  std::string error;  // the producer's, for the source

  // A producer from the file's start. 0 or the exit code with `why`.
  int start(bool quiet, std::string& why) {
    if (producer) producer->stop();
    producer = std::make_unique<JobProducer>();
    ring = std::make_unique<JobItemRing>();
    std::unique_ptr<job::ProgramStream> program;
    std::unique_ptr<PointPaths> points;
    if (gcode && !job::open_program_stream(file, setup.interp, setup.state, program, why)) return 2;
    if (!gcode) {
      points = std::make_unique<PointPaths>();
      if (!points->open(file, setup.criterion, why)) return 2;
    }
    producer->start(std::move(program), std::move(points), setup, *ring, quiet);
    return 0;
  }
};

StreamedJob::StreamedJob() : impl_(std::make_unique<Impl>()) {}

StreamedJob::~StreamedJob() {
  if (impl_->producer) impl_->producer->stop();
}

int StreamedJob::open(const std::string& file, const StreamedJobSetup& setup, std::string& error) {
  Impl& m = *impl_;
  m.file = file;
  m.setup = setup;
  m.gcode = job::is_gcode_path(file);
  Fnv1a f;
  hash_setup(setup, m.gcode, f);
  if (!hash_file(file, f, error)) return 2;
  m.id = {f.h, 0xffffffffu};  // a stream's size is not known before its end: the bytes identify it
  if (const int rc = m.start(false, error); rc != 0) return rc;
  const auto rewind = [&m]() -> JobItemRing* {
    std::string why;
    if (m.start(true, why) != 0) {
      m.error = why;
      return nullptr;
    }
    return m.ring.get();
  };
  const auto producer_error = [&m]() -> std::string { return m.producer ? m.producer->error() : m.error; };
  m.source = std::make_unique<StreamJobSource>(m.id, m.ring.get(), rewind, producer_error);
  return 0;
}

int StreamedJob::prime(std::string& error) {
  Impl& m = *impl_;
  while (m.ring->size() < JobItemRing::kCapacity && !m.ring->closed()) nap();
  if (!m.producer->failed()) return 0;
  error = m.producer->say();
  return m.producer->exit_code();
}

JobSource& StreamedJob::source() { return *impl_->source; }
JobId StreamedJob::id() const { return impl_->id; }
const std::string& StreamedJob::file() const { return impl_->file; }

const fit::Piece<double>* StreamedJob::piece(std::size_t k, std::size_t* path) const {
  return impl_->source ? impl_->source->piece(k, path) : nullptr;
}

StreamTotals StreamedJob::totals() const {
  return impl_->producer ? impl_->producer->totals() : StreamTotals{};
}

}  // namespace kerf::control

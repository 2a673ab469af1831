// The producer thread of the streaming pipeline (control/job_stream.hpp):
// the first segment is handed over before the file has been written to its
// end (a FIFO the test writes in two halves), and a bad line ends the
// stream with FILE:LINE.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "control/job_stream.hpp"

namespace {

using namespace kerf;
using control::StreamItem;

std::string temp_path(const char* name) {
  const std::string dir = std::filesystem::temp_directory_path() / ("kerf_job_stream_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir + "/" + name;
}

// Points along a spiral: arcs, never one segment for the whole path.
std::string points(int from, int to) {
  std::string s;
  char line[64];
  for (int k = from; k < to; ++k) {
    const double a = k * 0.02, r = 20 + k * 0.01;
    std::snprintf(line, sizeof line, "%.4f %.4f\n", r * std::cos(a), r * std::sin(a));
    s += line;
  }
  return s;
}

TEST(JobStream, FirstSegmentBeforeTheFileEnds) {
  const std::string fifo = temp_path("job.fifo");
  std::filesystem::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0) << std::strerror(errno);
  std::atomic<bool> got_first{false}, writer_done{false};
  std::thread writer([&] {
    std::FILE* f = std::fopen(fifo.c_str(), "w");
    if (!f) return;
    std::fputs(points(0, 1500).c_str(), f);
    std::fflush(f);
    // The second half only once a segment came out (or after 20 s: the test then fails below).
    for (int k = 0; k < 2000 && !got_first; ++k) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    std::fputs(points(1500, 3000).c_str(), f);
    writer_done = true;
    std::fclose(f);
  });
  static control::JobRing ring;
  control::PointFileProducer producer;
  control::JobStreamSetup setup;
  setup.criterion = job::Criterion::vertex;
  setup.tol = 0.01;
  setup.window = 64;
  std::string error;
  ASSERT_TRUE(producer.start(fifo, setup, ring, error)) << error;
  StreamItem item;
  std::uint64_t segments = 0, read_at_first = 0;
  bool done_at_first = true;
  Vec2<double> at{};
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  for (;;) {
    if (!ring.try_pop(item)) {
      ASSERT_LT(std::chrono::steady_clock::now(), give_up) << "the stream never ended";
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      continue;
    }
    if (item.kind != StreamItem::Kind::segment) break;
    if (segments == 0) {
      done_at_first = writer_done;
      read_at_first = producer.points_read();
      got_first = true;
    } else {
      ASSERT_EQ(std::memcmp(&item.seg.from, &at, sizeof at), 0) << "segment " << segments;
    }
    at = item.seg.cmd.end;
    ++segments;
  }
  writer.join();
  producer.join();
  EXPECT_EQ(item.kind, StreamItem::Kind::end) << producer.error();
  EXPECT_FALSE(done_at_first) << "the first segment came after the whole file was written";
  EXPECT_LE(read_at_first, 1500u);
  EXPECT_GT(segments, 10u);
  EXPECT_EQ(producer.stats().points, 3000u);
  EXPECT_EQ(producer.stats().streamed_paths, 1u);
  std::filesystem::remove(fifo);
}

TEST(JobStream, BadLineEndsTheStreamWithFileAndLine) {
  const std::string file = temp_path("bad.txt");
  std::ofstream(file) << points(0, 200) << "1 oops\n" << points(200, 300);
  static control::JobRing ring;
  control::PointFileProducer producer;
  control::JobStreamSetup setup;
  setup.window = 32;
  std::string error;
  ASSERT_TRUE(producer.start(file, setup, ring, error)) << error;
  StreamItem item;
  do {
    while (!ring.try_pop(item)) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  } while (item.kind == StreamItem::Kind::segment);
  producer.join();
  EXPECT_EQ(item.kind, StreamItem::Kind::error);
  EXPECT_NE(producer.error().find(file + ":201: "), std::string::npos) << producer.error();
  std::filesystem::remove(file);
}

}  // namespace

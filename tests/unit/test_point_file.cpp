// Point files with several cut paths: blank lines separate paths.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "io/point_file.hpp"

namespace {

using kerf::io::parse_points;
using kerf::io::PointFile;
using V = kerf::Vec2<double>;
using Begins = std::vector<std::size_t>;

PointFile parse(const std::string& text) { return parse_points(text, "job.txt"); }

TEST(PointFilePaths, OnePathStartsAtZero) {
  const PointFile f = parse("0 0\n1 0\n2 1\n");
  ASSERT_TRUE(f.ok) << kerf::io::describe_error(f);
  EXPECT_EQ(f.path_begin, (Begins{0}));
  EXPECT_EQ(f.points.size(), 3u);
}

TEST(PointFilePaths, BlankLineSeparatesTwoPaths) {
  const PointFile f = parse("0 0\n1 0\n2 1\n\n5 5\n6 5\n");
  ASSERT_TRUE(f.ok) << kerf::io::describe_error(f);
  EXPECT_EQ(f.path_begin, (Begins{0, 3}));
  ASSERT_EQ(f.points.size(), 5u);
  EXPECT_EQ(f.points[3], (V{5, 5}));
  EXPECT_EQ(f.point_lines[3], 5u);
}

TEST(PointFilePaths, SeveralBlankLinesWithSpacesAndCrlfMakeOneSeparator) {
  const PointFile f = parse("0 0\r\n1 0\r\n  \t\r\n\r\n   \r\n5 5\r\n6 5\r\n\r\n7 7\r\n8 8\r\n");
  ASSERT_TRUE(f.ok) << kerf::io::describe_error(f);
  EXPECT_EQ(f.path_begin, (Begins{0, 2, 4}));
  EXPECT_EQ(f.points.size(), 6u);
}

TEST(PointFilePaths, CommentOnlyLinesDoNotSeparate) {
  const PointFile f = parse("0 0\n1 0\n# next part\n   # indented comment\r\n2 1\n3 1\n");
  ASSERT_TRUE(f.ok) << kerf::io::describe_error(f);
  EXPECT_EQ(f.path_begin, (Begins{0}));
  EXPECT_EQ(f.points.size(), 4u);
}

TEST(PointFilePaths, CommentNextToABlankLineStillSeparates) {
  const PointFile f = parse("0 0\n1 0\n\n# the hole\n5 5\n6 5\n");
  ASSERT_TRUE(f.ok) << kerf::io::describe_error(f);
  EXPECT_EQ(f.path_begin, (Begins{0, 2}));
}

TEST(PointFilePaths, LeadingAndTrailingBlankLinesMakeNoEmptyPath) {
  const PointFile f = parse("\n  \n# header\n\n0 0\n1 0\n\n2 2\n3 3\n\n \n\n");
  ASSERT_TRUE(f.ok) << kerf::io::describe_error(f);
  EXPECT_EQ(f.path_begin, (Begins{0, 2}));
  EXPECT_EQ(f.points.size(), 4u);
}

TEST(PointFilePaths, DuplicateAcrossABoundaryIsKept) {
  // The second path starts where the first ended: a new pierce, not a duplicate.
  const PointFile f = parse("0 0\n1 0\n1 0\n\n1 0\n1 0\n2 0\n");
  ASSERT_TRUE(f.ok) << kerf::io::describe_error(f);
  EXPECT_EQ(f.path_begin, (Begins{0, 2}));
  ASSERT_EQ(f.points.size(), 4u);
  EXPECT_EQ(f.points[1], (V{1, 0}));
  EXPECT_EQ(f.points[2], (V{1, 0}));
  EXPECT_EQ(f.point_lines[2], 5u);
  EXPECT_EQ(f.duplicates_dropped, 2u);  // one inside each path
}

TEST(PointFilePaths, TolColumnFollowsThePaths) {
  const PointFile f = parse("0 0 0.1\n1 0 0.2\n\n1 0 0.3\n2 0 0.4\n");
  ASSERT_TRUE(f.ok) << kerf::io::describe_error(f);
  EXPECT_EQ(f.tols, (std::vector<double>{0.1, 0.2, 0.3, 0.4}));
}

TEST(PointFilePaths, SinglePointPathInTheMiddleIsAnError) {
  const PointFile f = parse("0 0\n1 0\n\n# lone\n5 5\n\n6 6\n7 7\n");
  ASSERT_FALSE(f.ok);
  EXPECT_EQ(f.line, 5u);
  EXPECT_EQ(kerf::io::describe_error(f), "job.txt:5: path 2 has only one point");
  EXPECT_TRUE(f.points.empty());
  EXPECT_TRUE(f.path_begin.empty());
}

TEST(PointFilePaths, SinglePointLastPathIsAnError) {
  const PointFile f = parse("0 0\n1 0\n\n\n9 9\n\n");
  ASSERT_FALSE(f.ok);
  EXPECT_EQ(kerf::io::describe_error(f), "job.txt:5: path 2 has only one point");
}

TEST(PointFilePaths, PathOfOneDistinctPointIsAnError) {
  // Duplicates collapse inside a path: two lines, one distinct point.
  const PointFile f = parse("3 3\n3 3\n\n0 0\n1 0\n");
  ASSERT_FALSE(f.ok);
  EXPECT_EQ(kerf::io::describe_error(f), "job.txt:1: path 1 has only one point");
}

TEST(PointFilePaths, WholeFileOfOnePointKeepsItsOldMessage) {
  const PointFile f = parse("5 5\n\n");
  ASSERT_FALSE(f.ok);
  EXPECT_EQ(kerf::io::describe_error(f), "job.txt: fewer than two distinct points (got 1)");
}

// Tangent columns, for the biarc criterion.
TEST(PointFileTangents, FourColumnsAreUnitTangents) {
  const PointFile f = parse("0 0 3 4\n1 0 0 2\n1 0 5 5\n2 1 -1 0\n");
  ASSERT_TRUE(f.ok) << kerf::io::describe_error(f);
  ASSERT_EQ(f.points.size(), 3u);  // the duplicate keeps the first tangent
  ASSERT_EQ(f.tangents.size(), 3u);
  EXPECT_TRUE(f.tols.empty());
  EXPECT_NEAR(f.tangents[0].x, 0.6, 1e-15);
  EXPECT_NEAR(f.tangents[0].y, 0.8, 1e-15);
  EXPECT_EQ(f.tangents[1], (V{0, 1}));
  EXPECT_EQ(f.tangents[2], (V{-1, 0}));
}

TEST(PointFileTangents, ThirdColumnAsAngleInDegrees) {
  const PointFile f = parse_points("0 0 90\n1 1 -45\n2 0 360\n", "job.txt", true);
  ASSERT_TRUE(f.ok) << kerf::io::describe_error(f);
  ASSERT_EQ(f.tangents.size(), 3u);
  EXPECT_TRUE(f.tols.empty());
  EXPECT_NEAR(f.tangents[0].x, 0.0, 1e-15);
  EXPECT_NEAR(f.tangents[0].y, 1.0, 1e-15);
  EXPECT_NEAR(f.tangents[1].x, std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(f.tangents[1].y, -std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(f.tangents[2].x, 1.0, 1e-15);
}

TEST(PointFileTangents, BadTangentsAreRefusedWithTheirLine) {
  PointFile f = parse("0 0 1 0\n1 0 0 0\n");
  EXPECT_FALSE(f.ok);
  EXPECT_EQ(kerf::io::describe_error(f), "job.txt:2: tangent must not be zero");
  f = parse_points("0 0 abc\n1 0 0\n", "job.txt", true);
  EXPECT_FALSE(f.ok);
  EXPECT_EQ(f.line, 1u);
  f = parse("0 0 1 0\n1 0\n");
  EXPECT_FALSE(f.ok);
  EXPECT_EQ(kerf::io::describe_error(f), "job.txt:2: expected 4 columns like line 1, got 2");
  // Without the angle reading a third column is still a tol (> 0).
  f = parse("0 0 -45\n1 1 -45\n");
  EXPECT_FALSE(f.ok);
}

// A runaway line (a binary file, a file without line ends) is refused with
// its line, however long; a line up to the limit is read.
TEST(PointFileLines, LineLongerThanTheLimitIsRefusedWithItsLine) {
  const std::string longest = "1 2 #" + std::string(kerf::io::kMaxLineBytes - 5, 'x');
  PointFile f = parse("0 0\n" + longest + "\n3 4\n");
  EXPECT_TRUE(f.ok) << kerf::io::describe_error(f);
  f = parse("0 0\n1 1\n" + longest + "x\n3 4\n");
  EXPECT_FALSE(f.ok);
  EXPECT_EQ(kerf::io::describe_error(f), "job.txt:3: line longer than 65536 bytes (not a point file?)");
  f = parse("0 0\n1 nan\n" + longest + "x");  // an earlier error comes first
  EXPECT_EQ(kerf::io::describe_error(f), "job.txt:2: NaN or infinite coordinate");
}

}  // namespace

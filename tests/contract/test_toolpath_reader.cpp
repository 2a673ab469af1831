// The independent toolpath reader that checks `kerf sim` (tests/support/
// toolpath_reader.hpp), on small programs whose moves are worked out by hand
// from the LinuxCNC G-code reference.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "toolpath_eval.hpp"
#include "toolpath_reader.hpp"

namespace kerf_test {
namespace {

void expect_at(TPoint p, double x, double y) {
  EXPECT_NEAR(p.x, x, 1e-9);
  EXPECT_NEAR(p.y, y, 1e-9);
}

TEST(ToolpathReader, AbsoluteRelativeAndInches) {
  const Toolpath t = parse_toolpath("G21 G90\nG0 X1 Y2\nG1 X3\nG91 G1 X1 Y1\nG20 G1 X1\nG90 G0 X0 Y0\n");
  ASSERT_TRUE(t.ok) << t.error;
  ASSERT_EQ(t.moves.size(), 5u);
  EXPECT_TRUE(t.moves[0].rapid);
  expect_at(t.moves[1].end, 3, 2);
  expect_at(t.moves[2].end, 4, 3);
  expect_at(t.moves[3].end, 4 + 25.4, 3);
  expect_at(t.moves[4].end, 0, 0);
}

TEST(ToolpathReader, ArcsByCentreAndByRadius) {
  // Quarter circles of radius 10 round (0, 0) from (10, 0) to (0, 10).
  const Toolpath t = parse_toolpath(
      "G0 X10 Y0\nG3 X0 Y10 I-10 J0\n"       // I J from the start
      "G0 X10 Y0\nG3 X0 Y10 R10\n"           // R: the short way, counter-clockwise
      "G0 X10 Y0\nG2 X0 Y10 R-10\n"          // R < 0: the long way, clockwise
      "G0 X10 Y0\nG90.1 G3 X0 Y10 I0 J0\n");  // absolute centre
  ASSERT_TRUE(t.ok) << t.error;
  ASSERT_EQ(t.moves.size(), 8u);
  for (int k : {1, 3, 5, 7}) {
    EXPECT_TRUE(t.moves[k].arc);
    expect_at(t.moves[k].centre, 0, 0);
  }
  EXPECT_EQ(t.moves[3].dir, 1);
  EXPECT_EQ(t.moves[5].dir, -1);
  // On the long way round, (-10, 0) is on the arc; on the short way it is not.
  EXPECT_NEAR(distance_to_move(t.moves[5], {-10, 0}), 0, 1e-9);
  EXPECT_NEAR(distance_to_move(t.moves[3], {-10, 0}), std::hypot(10, 10), 1e-9);
  EXPECT_NEAR(distance_to_move(t.moves[1], {5, 5}), 10 - std::hypot(5, 5), 1e-9);
}

TEST(ToolpathReader, OffsetsMoveThePath) {
  const Toolpath t = parse_toolpath(
      "G10 L2 P2 X100 Y50\nG55\nG0 X1 Y1\n"  // G55's origin at (100, 50)
      "G92 X0 Y0\nG1 X2 Y0\n"                 // here is (0, 0) now
      "G53 G0 X5 Y5\n"                        // machine coordinates, this block only
      "G92.1 G1 X1 Y1\n"                      // G92 off: back to G55
      "G54 G1 X1 Y1\n");                      // G54 is still at the origin
  ASSERT_TRUE(t.ok) << t.error;
  ASSERT_EQ(t.moves.size(), 5u);
  expect_at(t.moves[0].end, 101, 51);
  expect_at(t.moves[1].end, 103, 51);
  expect_at(t.moves[2].end, 5, 5);
  expect_at(t.moves[3].end, 101, 51);
  expect_at(t.moves[4].end, 1, 1);
}

TEST(ToolpathReader, TorchAndCutMoves) {
  const Toolpath t = parse_toolpath("G0 X1 Y0\nM3\nG1 X2\nG1 Y1\nM5\nG1 X0\nM3 G1 Y0\nM30\nG1 X9\n");
  ASSERT_TRUE(t.ok) << t.error;
  EXPECT_TRUE(t.uses_torch);
  ASSERT_EQ(t.moves.size(), 5u);  // nothing after M30
  EXPECT_EQ(cut_moves(t).size(), 3u);
  const Toolpath dry = parse_toolpath("G0 X1\nG1 X2\nG1 X3\n");
  EXPECT_FALSE(dry.uses_torch);
  EXPECT_EQ(cut_moves(dry).size(), 2u);
}

TEST(ToolpathReader, MarksWhereZMoves) {
  const Toolpath t = parse_toolpath("G1 X1\nG1 Z-1\nG1 X2\nG3 X2 Y0 I1 J0 Z-2\nG1 X3 Z-2\n");
  ASSERT_TRUE(t.ok) << t.error;
  ASSERT_EQ(t.moves.size(), 4u);
  EXPECT_FALSE(t.moves[0].after_z || t.moves[0].z_moves);
  EXPECT_TRUE(t.moves[1].after_z);
  EXPECT_FALSE(t.moves[1].z_moves);
  EXPECT_TRUE(t.moves[2].z_moves);  // a helix: a full circle going down
  EXPECT_TRUE(t.moves[2].arc);
  EXPECT_FALSE(t.moves[3].after_z || t.moves[3].z_moves);  // Z-2 again: no change
}

TEST(ToolpathReader, WordsWithoutBlanksAndComments) {
  const Toolpath t = parse_toolpath("%\nN10G1X1.5Y-2(comment)E1.1F1800.0 ; more\n/G1 X2\n");
  ASSERT_TRUE(t.ok) << t.error;
  ASSERT_EQ(t.moves.size(), 2u);
  expect_at(t.moves[0].end, 1.5, -2);
  expect_at(t.moves[1].end, 2, -2);
}

TEST(ToolpathReader, RefusesWhatItCannotFollow) {
  EXPECT_FALSE(parse_toolpath("G1 X1\nO100 sub\n").ok);
  EXPECT_FALSE(parse_toolpath("G1 X#<unset>\n").ok);  // a named parameter read before it is set
  EXPECT_FALSE(parse_toolpath("G1 X[1/0]\n").ok);
  std::vector<RunLine> run;
  std::string why;
  EXPECT_FALSE(run_program("o1 while [1]\no1 endwhile\n", run, why, 1000));  // the line cap
  EXPECT_EQ(why.substr(0, 2), "1:");
  EXPECT_FALSE(parse_toolpath("o<elsewhere> call\n").ok);
  EXPECT_FALSE(parse_toolpath("G18\n").ok);
  const Toolpath off = parse_toolpath("G0 X21 Y-21\nG1 X20\nG3 X21 Y-20 I20 J21\n");
  EXPECT_FALSE(off.ok);
  EXPECT_EQ(off.error.substr(0, 2), "3:");
}

// Its own evaluator (toolpath_eval.hpp): values worked out by hand.
TEST(ToolpathReader, ParametersAndExpressions) {
  const Toolpath t = parse_toolpath(
      "#1 = 10 #2 = 20\n#1 = 30 #2 = #1\nG0 X#1 Y#2\n"             // reads before the line's assignments
      "#<w> = 4\nG0 X[#<w> * 2 + 1] Y[2 ** 3 MOD 5]\n"              // 9, 8 MOD 5 = 3
      "G0 X[-7 MOD 3] Y-[2]\n"                                       // 2 (never negative), -2
      "G0 X[1 LT 2 AND 3 GE 3] Y[1 EQ 2 OR 1 XOR 1]\n"              // 1, 0
      "G0 X[SQRT[16] + ABS[-1] + ROUND[2.5] + FIX[-0.5]] Y[ATAN[1]/[1]]\n"  // 4+1+3-1 = 7, 45
      "G0 x [ sin [ 30 ] ] y[EXISTS[#<w>] + EXISTS[#<v>] + #<_hal[plasmac.cut-feed-rate]>]\n");  // 0.5, 1
  ASSERT_TRUE(t.ok) << t.error;
  ASSERT_EQ(t.moves.size(), 6u);
  expect_at(t.moves[0].end, 30, 10);
  expect_at(t.moves[1].end, 9, 3);
  expect_at(t.moves[2].end, 2, -2);
  expect_at(t.moves[3].end, 1, 0);
  expect_at(t.moves[4].end, 7, 45);
  expect_at(t.moves[5].end, 0.5, 1);
}

TEST(ToolpathReader, OwordFlow) {
  const Toolpath t = parse_toolpath(
      "o<sq> sub\n  G1 X[#1 + 1]\n  o<sq> return\n  G1 X99\no<sq> endsub\n"  // never run where it stands
      "o1 repeat [2]\n  o2 repeat [2]\n    #3 = [#3 + 1]\n    G1 X#3 Y0\n  o2 endrepeat\no1 endrepeat\n"  // X1..X4
      "#4 = 0\no3 while [#4 LT 9]\n  #4 = [#4 + 1]\n  o4 if [#4 EQ 2]\n    o3 continue\n  o4 elseif [#4 EQ 4]\n"
      "    o3 break\n  o4 else\n    G1 Y#4\n  o4 endif\no3 endwhile\n"  // Y1, Y3
      "o5 do\n  G1 X10\no5 while [0]\n"                                   // once
      "o<sq> call [20]\n");                                                  // X21
  ASSERT_TRUE(t.ok) << t.error;
  ASSERT_EQ(t.moves.size(), 8u);
  for (int k = 0; k < 4; ++k) expect_at(t.moves[static_cast<std::size_t>(k)].end, k + 1, 0);
  expect_at(t.moves[4].end, 4, 1);
  expect_at(t.moves[5].end, 4, 3);
  expect_at(t.moves[6].end, 10, 3);
  expect_at(t.moves[7].end, 21, 3);
  EXPECT_EQ(t.moves[7].line, 2u);
}

TEST(ToolpathReader, IndexFindsTheNearestMove) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-50, 50);
  std::vector<TMove> moves;
  for (int k = 0; k < 300; ++k) {
    TMove m;
    m.start = {u(rng), u(rng)};
    if (k % 3 == 0) {
      m.arc = true;
      m.dir = k % 2 ? 1 : -1;
      m.centre = {m.start.x + u(rng) / 10, m.start.y + u(rng) / 10};
      const double r = std::hypot(m.start.x - m.centre.x, m.start.y - m.centre.y);
      const double a = u(rng);
      m.end = {m.centre.x + r * std::cos(a), m.centre.y + r * std::sin(a)};
    } else {
      m.end = {m.start.x + u(rng) / 5, m.start.y + u(rng) / 5};
    }
    moves.push_back(m);
  }
  const MoveIndex index(moves, 2.0);
  for (int k = 0; k < 2000; ++k) {
    const TPoint p{u(rng), u(rng)};
    double brute = INFINITY;
    for (const TMove& m : moves) brute = std::min(brute, distance_to_move(m, p));
    EXPECT_NEAR(index.nearest(p, 0.5), brute, 1e-12);
  }
}

}  // namespace
}  // namespace kerf_test

// `convray field` end to end: the binary reads points on stdin and must reproduce the
// analytic field of an (effectively) infinite plane, and reject malformed input with
// "stdin:LINE: ..." and exit code 2.
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli.hpp"

namespace convray {
namespace {

constexpr double kPi = 3.14159265358979323846;

class FieldCommand : public testing::CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    // A 200 x 200 square in z = 0, written by hand (not by our writer).
    std::ofstream(file("square.obj")) << "v -100 -100 0\nv 100 -100 0\nv 100 100 0\nv -100 100 0\n"
                                         "f 1 2 3\nf 1 3 4\n";
  }
  testing::CliRun run(const std::string& args, const std::string& stdin_text) const {
    return run_convray(args, stdin_text);
  }
  std::string square() const { return file("square.obj"); }
};

std::vector<std::vector<double>> parse_rows(const std::string& text) {
  std::vector<std::vector<double>> rows;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line);
    std::vector<double> row;
    for (double v; fields >> v;) row.push_back(v);
    rows.push_back(row);
  }
  return rows;
}

TEST_F(FieldCommand, ReproducesTheInfinitePlaneAndItsGradient) {
  const double r = 1.5, s = 2.0;
  const std::vector<double> heights = {0.0, 0.3, -0.7, 1.2, 1.6};
  std::string input;
  for (double h : heights) input += "0.25 -3.5 " + std::to_string(h) + "\n";
  const testing::CliRun result = run("field --mesh " + square() + " --radius 1.5 --strength 2", input);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto rows = parse_rows(result.out);
  ASSERT_EQ(rows.size(), heights.size());
  for (size_t k = 0; k < heights.size(); ++k) {
    const double h = std::stod(std::to_string(heights[k]));
    const double a = std::max(0.0, 1.0 - h * h / (r * r));
    const double value = s * (kPi / 3.0) * r * r * a * a * a;
    const double dvalue_dh = s * (kPi / 3.0) * r * r * 3.0 * a * a * (-2.0 * h / (r * r));
    ASSERT_EQ(rows[k].size(), 4u);
    EXPECT_NEAR(rows[k][0], value, 1e-12 * r * r) << "h=" << h;
    EXPECT_NEAR(rows[k][1], 0.0, 1e-12 * r);
    EXPECT_NEAR(rows[k][2], 0.0, 1e-12 * r);
    EXPECT_NEAR(rows[k][3], dvalue_dh, 1e-11 * r);
  }
}

TEST_F(FieldCommand, PrintsSeventeenSignificantDigits) {
  const testing::CliRun result = run("field --mesh " + square() + " --radius 1", "0 0 0.1\n");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  std::istringstream in(result.out);
  std::string first;
  in >> first;
  // (π/3)(0.99)^3 = 1.0161... needs all 17 digits to round-trip a double.
  const std::string digits = first.substr(0, first.find_first_of("eE"));
  size_t count = 0;
  for (char c : digits) count += std::isdigit(static_cast<unsigned char>(c)) ? 1 : 0;
  EXPECT_EQ(count, 17u) << first;
}

TEST_F(FieldCommand, AcceptsTabsSignsExponentsAndCrLf) {
  const testing::CliRun result = run("field --mesh " + square() + " --radius 1", "+0\t-0.0  1e-1\r\n");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(parse_rows(result.out).size(), 1u);
}

TEST_F(FieldCommand, MalformedLineStopsWithLineNumberAndExitCode2) {
  const testing::CliRun result = run("field --mesh " + square() + " --radius 1", "0 0 0\n1 2\n0 0 0\n");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("stdin:2: expected three numbers 'x y z', found 2 numbers"),
            std::string::npos)
      << result.err;
  EXPECT_EQ(parse_rows(result.out).size(), 1u);  // the line before it was answered
}

TEST_F(FieldCommand, EachKindOfBadLineIsNamed) {
  const std::string mesh = square();
  const auto err_for = [&](const std::string& line) {
    const testing::CliRun r = run("field --mesh " + mesh + " --radius 1", line);
    EXPECT_EQ(r.exit_code, 2) << line;
    return r.err;
  };
  EXPECT_NE(err_for("1 x 3\n").find("stdin:1: y is not a number: 'x'"), std::string::npos);
  EXPECT_NE(err_for("1 2 3 4\n").find("stdin:1: unexpected text after 'x y z': '4'"),
            std::string::npos);
  EXPECT_NE(err_for("nan 0 0\n").find("stdin:1: x is not finite"), std::string::npos);
  EXPECT_NE(err_for("\n").find("stdin:1: expected three numbers 'x y z', found 0 numbers"),
            std::string::npos);
  EXPECT_NE(err_for("1,2,3\n").find("stdin:1: x is not a number: '1,2,3'"), std::string::npos);
}

TEST_F(FieldCommand, BadCommandLineAndMissingMeshExitWith2) {
  testing::CliRun r = run("field --mesh " + square() + " --radius -1", "");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("radius"), std::string::npos) << r.err;
  r = run("field --mesh " + file("missing.obj") + " --radius 1", "");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("missing.obj"), std::string::npos) << r.err;
  r = run("field --radius 1", "");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--mesh"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace convray

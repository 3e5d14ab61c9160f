// Messages that name the real problem (issue 21), each with its exit code: bad input is exit 2
// everywhere, with a text that says what to change; nothing passes without a word.
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli.hpp"

namespace convray {
namespace {

const std::string kSoup = "'" + std::string(CONVRAY_SOURCE_DIR) + "/scenes/models/soup.obj'";

class Messages : public testing::CliTest {
 protected:
  // A segment skeleton with the given convolution settings.
  std::string segment_scene(const std::string& settings) const {
    std::ofstream(file("s.pov"))
        << "camera { location <0, 0, -4> look_at 0 }\n"
           "light_source { <-3, 4, -5> color rgb 1 }\n"
           "convolution { " << settings
        << " segment { <-0.8, 0, 0>, <0.8, 0.3, 0> } pigment { color rgb 1 } finish { phong 0.5 } }\n";
    return "'" + file("s.pov") + "'";
  }
  testing::CliRun render(const std::string& scene, const std::string& output) const {
    return run_convray(scene + " -o '" + file(output) + "' +W64 +H48 --quiet");
  }
};

TEST_F(Messages, KernelRadiiBeyondDoublePrecisionAreNamedInQuick) {
  std::ofstream(file("huge.obj")) << "v 0 0 0\nv 1e308 0 0\nv 0 1e308 0\nf 1 2 3\n";
  for (const std::string& arguments :
       {"'" + file("huge.obj") + "'", kSoup + " --fit-box 1e300", kSoup + " --fit-box 1e-300",
        kSoup + " --radius 1e300", kSoup + " --radius 1e-300"}) {
    const testing::CliRun run =
        run_convray("quick " + arguments + " --size 32x24 -o '" + file("q.png") + "'");
    EXPECT_EQ(run.exit_code, 2) << arguments << "\n" << run.err;
    EXPECT_NE(run.err.find("is outside what double precision carries"), std::string::npos)
        << arguments << "\n" << run.err;
    EXPECT_EQ(run.err.find("offset"), std::string::npos) << "no offset was given: " << run.err;
  }
}

TEST_F(Messages, StrengthsAndRadiiBeyondDoublePrecisionAreRefusedInScenes) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"radius 1e300", "the kernel radius 1e+300 is outside"},
      {"radius 1e-300", "the kernel radius 1e-300 is outside"},
      // T = s (pi/3) (1 - 1/4)^3 = 0.4418 s at the default offset R/2.
      {"radius 1 strength 1e308", "the threshold 4.41786e+307 is outside"},
      {"radius 1 strength 1e-320", "the threshold 4.41695e-321 is outside"},
  };
  for (const auto& [settings, message] : cases) {
    const testing::CliRun run = render(segment_scene(settings), "x.png");
    EXPECT_EQ(run.exit_code, 2) << settings;
    EXPECT_NE(run.err.find(message), std::string::npos) << settings << "\n" << run.err;
    EXPECT_EQ(run.err.find("needs a positive strength"), std::string::npos) << run.err;
  }
}

TEST_F(Messages, ExtremeStrengthsShadeAsStrengthOne) {
  // F / T is the same function for every strength s (T from the offset scales with s), so the
  // pictures must be too: the normal is normalised without overflowing or underflowing.
  ASSERT_EQ(render(segment_scene("radius 1 offset 0.3"), "one.png").exit_code, 0);
  const std::string one = testing::read_file(file("one.png"));
  for (const std::string strength : {"1e200", "1e250", "1e-160", "1e-250"}) {
    const testing::CliRun run =
        render(segment_scene("radius 1 offset 0.3 strength " + strength), "s.png");
    ASSERT_EQ(run.exit_code, 0) << strength << ": " << run.err;
    EXPECT_EQ(testing::read_file(file("s.png")), one) << "strength " << strength;
  }
}

// The Cauchy kernel's surface F = T with T scaled as the strength is the same surface: its
// picture at strength 1e200 or 1e-160 must be that at strength 1 (the normal was zero at 1e200,
// |grad F|^2 overflowing, and rounded at 1e-160).
TEST_F(Messages, ExtremeStrengthsShadeAsStrengthOneWithTheCauchyKernel) {
  ASSERT_EQ(render(segment_scene("kernel cauchy 2 radius 1 strength 1 threshold 0.5"), "one.png")
                .exit_code,
            0);
  const std::string one = testing::read_file(file("one.png"));
  for (const std::string& scale : {"1e200", "1e-160"}) {
    const testing::CliRun run = render(
        segment_scene("kernel cauchy 2 radius 1 strength " + scale + " threshold 0.5 * " + scale),
        "s.png");
    ASSERT_EQ(run.exit_code, 0) << scale << ": " << run.err;
    EXPECT_EQ(testing::read_file(file("s.png")), one) << "strength " << scale;
  }
}

// polygonize's normals likewise: at strength 1e200 |grad F|^2 overflowed and every normal was
// zero. With T from the default offset (scaling with the strength) the mesh is the mesh of
// strength 1, and its normals agree to rounding.
TEST_F(Messages, ExtremeStrengthsGivePolygonizeTheNormalsOfStrengthOne) {
  auto normals = [&](const std::string& strength) {
    const testing::CliRun run =
        run_convray("polygonize " + kSoup + " --radius 0.25 --cell 0.05 --strength " + strength +
                    " -o '" + file("p.obj") + "'");
    EXPECT_EQ(run.exit_code, 0) << strength << ": " << run.err;
    std::vector<double> values;
    std::istringstream in(testing::read_file(file("p.obj")));
    for (std::string line; std::getline(in, line);) {
      if (line.rfind("vn ", 0) != 0) continue;
      std::istringstream numbers(line.substr(3));
      for (double v; numbers >> v;) values.push_back(v);
    }
    return values;
  };
  const std::vector<double> one = normals("1");
  ASSERT_GT(one.size(), 300u);
  for (const std::string strength : {"1e200", "1e-160"}) {
    const std::vector<double> scaled = normals(strength);
    ASSERT_EQ(scaled.size(), one.size()) << strength;
    for (size_t i = 0; i < one.size(); ++i) {
      ASSERT_NEAR(scaled[i], one[i], 1e-9) << strength << " at " << i;
    }
  }
}

TEST_F(Messages, AnEmptySurfaceIsBadInput) {
  const testing::CliRun run = run_convray("polygonize " + kSoup +
                                          " --radius 0.25 --threshold 1e9 -o '" +
                                          file("e.obj") + "'");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("the surface is empty: the field stays below T = 1e+09 everywhere"),
            std::string::npos)
      << run.err;
}

TEST_F(Messages, AMissingLibraryFolderIsSaid) {
  const testing::CliRun run =
      run_convray(segment_scene("radius 1") + " -L /nonexistent/folder -o '" + file("x.png") +
                  "' +W16 +H12 --quiet");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("warning: library path '/nonexistent/folder' is not a folder"),
            std::string::npos)
      << run.err;
}

// POV-Ray renders with Declare=sphere=1 (the keyword shadows the declaration, which nothing
// can read; checked with the povray binary): convray renders too, and says so.
TEST_F(Messages, AKeywordDeclaredOnTheCommandLineIsIgnoredWithAWarning) {
  const testing::CliRun keyword =
      run_convray(segment_scene("radius 1") + " --declare sphere=1 -o '" + file("x.png") +
                  "' +W16 +H12 --quiet");
  EXPECT_EQ(keyword.exit_code, 0) << keyword.err;
  EXPECT_NE(keyword.err.find("command line: Declare=sphere: 'sphere' is a reserved word of the "
                             "scene language, so the scene cannot read this declaration "
                             "(POV-Ray ignores it too); ignored"),
            std::string::npos)
      << keyword.err;
}

}  // namespace
}  // namespace convray

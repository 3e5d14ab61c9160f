#pragma once
// Whole scenes rendered by the installed POV-Ray 3.7 and by the convray binary with the same
// switches (small, without anti-aliasing), compared pixel by pixel: PSNR over the 8-bit RGB
// values, as scripts/compare-povray.sh --examples measures. Tests skip without povray.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "reference/png_pixels.hpp"

namespace convray::testing {

inline bool povray_installed() {
  static const bool installed = std::system("povray --version > /dev/null 2>&1") == 0;
  return installed;
}

#define SKIP_WITHOUT_POVRAY()                                                 \
  if (!::convray::testing::povray_installed())                               \
  GTEST_SKIP() << "povray is not installed (scripts/setup.sh installs it); " \
                  "this test compares with POV-Ray 3.7's own picture"

// 8-bit RGB values of a PNG picture; empty if it cannot be read.
inline std::vector<unsigned char> read_rgb8(const std::string& path) {
  return ::convray::reference::read_png_rgb8(path).rgb;
}

// 99 for identical pictures; -1 if they differ in size or cannot be read.
inline double psnr(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b) {
  if (a.empty() || a.size() != b.size()) return -1.0;
  double sum = 0.0;
  for (size_t k = 0; k < a.size(); ++k) sum += (double(a[k]) - b[k]) * (double(a[k]) - b[k]);
  const double mse = sum / double(a.size());
  return mse == 0.0 ? 99.0 : 10.0 * std::log10(255.0 * 255.0 / mse);
}

class PovRayPictureTest : public CliTest {
 protected:
  // Renders `scene` (written as NAME.pov in the test's folder) with both programs at 80x60,
  // -A; returns the PSNR of convray's picture against POV-Ray's. `convray_err` gets our
  // messages, `povray_messages` POV-Ray's warnings.
  double compare(const std::string& name, const std::string& scene) {
    std::ofstream(file(name + ".pov")) << scene;
    const std::string switches = " +W80 +H60 -A -D +WT1";
    // POV-Ray's own output is kept, so that a failure (seen once under ctest -j2, never
    // reproduced) says what happened.
    const std::string pov = "cd '" + dir_.string() + "' && povray +I" + name + ".pov +O" + name +
                            "_pov.png" + switches + " -GA +GW" + name + "_pov.txt > " + name +
                            "_pov.log 2>&1";
    const int pov_status = std::system(pov.c_str());
    if (pov_status != 0) {
      ADD_FAILURE() << "povray failed on " << name << " (status " << pov_status << "):\n"
                    << read_file(dir_ / (name + "_pov.log"));
    }
    povray_messages = read_file(dir_ / (name + "_pov.txt"));
    const CliRun ours = run_convray_after("cd '" + dir_.string() + "' && ",
                                          "+I" + name + ".pov +O" + name + "_our.png" + switches);
    EXPECT_EQ(ours.exit_code, 0) << ours.err;
    convray_err = ours.err;
    const std::vector<unsigned char> theirs = read_rgb8(file(name + "_pov.png"));
    const std::vector<unsigned char> mine = read_rgb8(file(name + "_our.png"));
    if (theirs.empty() || mine.empty()) {
      ADD_FAILURE() << name << ": a picture could not be read (POV-Ray's: "
                    << (theirs.empty() ? "no" : "yes") << ", ours: " << (mine.empty() ? "no" : "yes")
                    << "); POV-Ray said:\n" << read_file(dir_ / (name + "_pov.log"));
    }
    return psnr(theirs, mine);
  }

  // Runs `scene` (written as scene.pov) through both programs at 1x1 and gathers the numbers
  // of every #debug line, in order: POV-Ray's (its debug stream) into `pov`, ours (our
  // messages, "file:line:col: #debug: TEXT") into `ours`. `our_output` gets all we printed.
  void debug_numbers(const std::string& scene, std::vector<double>& pov, std::vector<double>& ours,
                     std::string* our_output = nullptr) {
    std::ofstream(file("scene.pov")) << scene;
    const std::string command = "cd '" + dir_.string() +
                                "' && povray +Iscene.pov +W1 +H1 -F -D -GA +GDdebug.txt "
                                "> /dev/null 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0);
    const CliRun run =
        run_convray_after("cd '" + dir_.string() + "' && ", "+Iscene.pov +W1 +H1 -D +Oout.png");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    if (our_output) *our_output = run.all();
    std::string debug;
    std::istringstream lines(run.all());
    for (std::string line; std::getline(lines, line);) {
      const size_t at = line.find("#debug: ");
      if (at != std::string::npos) debug += line.substr(at + 8) + "\n";
    }
    pov = numbers(read_file(dir_ / "debug.txt"));
    ours = numbers(debug);
  }

  // The decimal numbers (with a point) in `text`, in order.
  static std::vector<double> numbers(const std::string& text) {
    std::vector<double> out;
    const std::regex number(R"([-+]?[0-9]+\.[0-9]+)");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), number);
         it != std::sregex_iterator(); ++it) {
      out.push_back(std::stod(it->str()));
    }
    return out;
  }

  std::string convray_err, povray_messages;
};

}  // namespace convray::testing

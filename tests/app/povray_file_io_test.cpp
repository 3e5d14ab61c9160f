// #fopen, #write, #read and #fclose against the povray binary: the bytes a scene writes (floats
// as %g, vectors as <a,b,c>), what it reads back (strings, floats, vectors, the end of the
// file undefining the handle) as a picture, and POV-Ray's I/O restrictions on writing.
#include <gtest/gtest.h>

#include <string>

#include "povray_pictures.hpp"

namespace convray::testing {
namespace {

class PovRayFileIo : public PovRayPictureTest {};

// Writes a file, reads it back to place spheres; reads to the end with defined().
const std::string kScene =
    "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
    "camera { location <0, 2, -8> look_at <0, 0.5, 0> angle 50 }\n"
    "light_source { <-4, 8, -6> color rgb 1 }\n"
    "#fopen Out \"data.txt\" write\n"
    "#write (Out, \"\\\"first\\\",\", 0.5, \",\", <1.25, -0.5, 0.123456789>, \",\\n\")\n"
    "#for (I, 0, 4) #write (Out Out_Value, I * 1.5 - 2.875, \",\") #end\n"
    "#write (Out, 1e-7, \",\", 123456789, \"\\n\")\n"
    "#fclose Out\n"
    "#fopen In \"data.txt\" read\n"
    "#read (In, Name, Radius, Where)\n"
    "sphere { Where, Radius pigment { rgb <1, 0.5, 0> } }\n"
    "#declare N = 0;\n"
    "#while (defined(In))\n"
    "  #read (In, X)\n"
    "  #if (defined(In)) sphere { <X, 0, 1>, 0.3 pigment { rgb <0, N / 8, 1> } } "
    "#declare N = N + 1; #end\n"
    "#end\n"
    "#if (strcmp(Name, \"first\") = 0 & N = 6) plane { y, -0.3 pigment { checker } } #end\n";

TEST_F(PovRayFileIo, WritesAndReadsAsPovRay) {
  SKIP_WITHOUT_POVRAY();
  // Out_Value is the macro-free way of writing a string identifier; declared before use.
  const std::string scene = "#declare Out_Value = \"\";\n" + kScene;
  EXPECT_GE(compare("io", scene), 60.0) << convray_err;
  // Both programs wrote data.txt into the same folder, convray last: POV-Ray's bytes are
  // those of its own run, redone here.
  const std::string ours = read_file(file("data.txt"));
  const std::string pov = "cd '" + file("") + "' && mv data.txt ours.txt && povray +Iio.pov "
                          "+W8 +H8 -F -D -GA > /dev/null 2>&1";
  ASSERT_EQ(std::system(pov.c_str()), 0);
  EXPECT_EQ(ours, read_file(file("data.txt")));
  EXPECT_NE(ours.find("<1.25,-0.5,0.123457> ,"), std::string::npos) << ours;
}

TEST_F(PovRayFileIo, WritesOnlyInTheOutputAndSceneFolders) {
  std::filesystem::create_directories(file("scene"));
  std::filesystem::create_directories(file("out"));
  std::ofstream(file("scene/w.pov")) << "camera { location -5 * z look_at 0 }\n"
                                        "#fopen F \"../elsewhere.txt\" write\n";
  const CliRun run = run_convray("+I" + file("scene/w.pov") + " +O" + file("out/w.png") +
                                 " +W8 +H8");
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.err.find("w.pov:2:10"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("writes files only in the output folder"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(file("elsewhere.txt")));
  // A relative name goes to the output folder.
  std::ofstream(file("scene/ok.pov")) << "camera { location -5 * z look_at 0 }\n"
                                         "#fopen F \"note.txt\" write #write (F, \"hi\") #fclose F\n";
  const CliRun ok = run_convray("+I" + file("scene/ok.pov") + " +O" + file("out/ok.png") +
                                " +W8 +H8");
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_EQ(read_file(file("out/note.txt")), "hi");
}

}  // namespace
}  // namespace convray::testing

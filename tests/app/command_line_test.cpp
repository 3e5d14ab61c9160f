// The top-level command line: help that answers, a version, and clear refusals.
#include <fstream>
#include <string>

#include "app/cli.hpp"

namespace convray {
namespace {

using CommandLine = testing::CliTest;

TEST_F(CommandLine, HelpListsEveryCommandAndExitsZero) {
  const testing::CliRun run = run_convray("--help");
  EXPECT_EQ(run.exit_code, 0);
  for (const char* command : {"info", "field", "slice"}) {
    EXPECT_NE(run.out.find(command), std::string::npos) << command;
  }
}

TEST_F(CommandLine, VersionExitsZero) {
  const testing::CliRun run = run_convray("--version");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_EQ(run.out.rfind("convray ", 0), 0u) << run.out;
}

TEST_F(CommandLine, UnknownCommandIsNamed) {
  const testing::CliRun run = run_convray("render-everything");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("unknown command 'render-everything' (expected info, field, slice, quick, polygonize, distance, view or a scene file)"),
            std::string::npos)
      << run.err;
}

TEST_F(CommandLine, NoCommandOrUnknownOptionExitsWith2) {
  EXPECT_EQ(run_convray("").exit_code, 2);
  const testing::CliRun run = run_convray("info --frobnicate x.obj");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--frobnicate"), std::string::npos) << run.err;
}

TEST_F(CommandLine, MalformedNumbersAreRefusedNeverCrash) {
  std::ofstream(file("tri.obj")) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  const std::string mesh = "'" + file("tri.obj") + "'";
  const struct {
    std::string arguments, message;
  } cases[] = {
      {"field --mesh " + mesh + " --radius abc", "--radius: expected a number, got 'abc'"},
      {"field --mesh " + mesh + " --radius ''", "--radius: expected a number, got ''"},
      {"field --mesh " + mesh + " --radius 0x10", "--radius: expected a number, got '0x10'"},
      {"field --mesh " + mesh + " --radius 1e999", "--radius: must be finite, got '1e999'"},
      {"field --mesh " + mesh + " --radius nan", "--radius: must be finite, got 'nan'"},
      {"field --mesh " + mesh + " --radius 0", "--radius: must be > 0, got '0'"},
      {"field --mesh " + mesh + " --radius 1 --strength 2x", "--strength: expected a number"},
      {"slice " + mesh + " --radius 1 --at -inf", "--at: must be finite"},
      {"slice " + mesh + " --radius 1 --size 80x60junk", "expected WIDTHxHEIGHT"},
      {"slice " + mesh + " --radius 1 --size 0x60", "expected WIDTHxHEIGHT"},
  };
  for (const auto& c : cases) {
    const testing::CliRun run = run_convray(c.arguments);
    EXPECT_EQ(run.exit_code, 2) << c.arguments << "\n" << run.err;
    EXPECT_NE(run.err.find(c.message), std::string::npos) << c.arguments << "\n" << run.err;
  }
}

}  // namespace
}  // namespace convray

// The top-level command line: help that answers, a version, and clear refusals.
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
  EXPECT_NE(run.err.find("unknown command 'render-everything' (expected info, field or slice)"),
            std::string::npos)
      << run.err;
}

TEST_F(CommandLine, NoCommandOrUnknownOptionExitsWith2) {
  EXPECT_EQ(run_convray("").exit_code, 2);
  const testing::CliRun run = run_convray("info --frobnicate x.obj");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--frobnicate"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace convray

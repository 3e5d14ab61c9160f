// The program starts once more with glibc's malloc tunables (app/malloc_tunables.hpp), and
// only once: counted by the dynamic loader itself, whose LD_DEBUG=statistics report is
// printed at every start of a program. A user's own glibc.malloc.hugetlb is left alone (no
// second start), and the program does what it was asked either way.
#include <string>

#include "app/cli.hpp"

namespace convray::testing {
namespace {

class MallocTunables : public CliTest {
 protected:
  // How many times the loader started a program for `convray --version` run after `env ...`.
  int starts(const std::string& environment, std::string* out = nullptr) const {
    const CliRun run = run_convray_after("env " + environment + " LD_DEBUG=statistics ",
                                         "--version");
    EXPECT_EQ(run.exit_code, 0) << run.all();
    if (out) *out = run.out;
    int count = 0;
    const std::string mark = "total startup time in dynamic loader";
    for (size_t at = run.err.find(mark); at != std::string::npos;
         at = run.err.find(mark, at + 1)) {
      ++count;
    }
    return count;
  }
};

#if defined(__GLIBC__) && __GLIBC_PREREQ(2, 35)
TEST_F(MallocTunables, StartsOnceMoreWithThemAndNoMore) {
  std::string out;
  EXPECT_EQ(starts("-u GLIBC_TUNABLES", &out), 2);
  EXPECT_NE(out.find("convray 0.1.0"), std::string::npos) << out;
  // A user's other tunables: ours are added to them, once.
  EXPECT_EQ(starts("GLIBC_TUNABLES=glibc.malloc.perturb=0"), 2);
}

TEST_F(MallocTunables, AUsersOwnHugePageChoiceIsLeftAlone) {
  std::string out;
  EXPECT_EQ(starts("GLIBC_TUNABLES=glibc.malloc.hugetlb=0", &out), 1);
  EXPECT_NE(out.find("convray 0.1.0"), std::string::npos) << out;
}
#endif

}  // namespace
}  // namespace convray::testing

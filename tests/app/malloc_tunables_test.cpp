// The program starts once more with glibc's malloc tunables (app/malloc_tunables.hpp), and
// only once: counted by the dynamic loader itself, whose LD_DEBUG=statistics report is
// printed at every start of a program. A user's own glibc.malloc.hugetlb is left alone (no
// second start), and the program does what it was asked either way. Huge pages are asked
// for only where small pages' faults are dear, by a probe of this machine.
#include <cmath>
#include <fstream>
#include <string>

#include "app/cli.hpp"
#include "app/malloc_tunables.hpp"

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

TEST(MallocTunablesChoice, HugePagesOnlyWhereSmallPagesFaultsAreDear) {
  EXPECT_FALSE(app::huge_pages_pay(std::nullopt));  // no huge pages to ask for
  EXPECT_FALSE(app::huge_pages_pay(1e-6));          // a bare-metal fault
  EXPECT_FALSE(app::huge_pages_pay(app::kHugePagesPayAbove));
  EXPECT_TRUE(app::huge_pages_pay(1e-5));  // a virtual machine's dear faults
}

TEST(MallocTunablesChoice, TheUsersOwnTunablesComeFirstAndOursFollow) {
  const std::string thresholds =
      "glibc.malloc.mmap_threshold=33554432:glibc.malloc.trim_threshold=4294967296:"
      "glibc.malloc.top_pad=33554432";
  EXPECT_EQ(app::malloc_tunables("", true), "glibc.malloc.hugetlb=1:" + thresholds);
  EXPECT_EQ(app::malloc_tunables("", false), "glibc.malloc.hugetlb=0:" + thresholds);
  EXPECT_EQ(app::malloc_tunables("glibc.malloc.perturb=0", false),
            "glibc.malloc.perturb=0:glibc.malloc.hugetlb=0:" + thresholds);
}

// The probe answers where the kernel offers huge pages (its sysfs setting read here on its
// own), with a time a page that a fault and zeroing 4 KiB can take.
TEST(MallocTunablesChoice, TheProbeAnswersWhereTheKernelOffersHugePages) {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string modes;
  const bool offered = std::getline(in, modes) && modes.find("[never]") == std::string::npos;
  const std::optional<double> seconds = app::probe_small_page_touch();
  ASSERT_EQ(seconds.has_value(), offered) << modes;
  if (seconds) {
    EXPECT_TRUE(std::isfinite(*seconds));
    EXPECT_GT(*seconds, 0.0);
    EXPECT_LT(*seconds, 0.1);
  }
}

}  // namespace
}  // namespace convray::testing

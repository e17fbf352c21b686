// liggghts_pwtest: the package's launcher with the test-only styles added to the shipped
// ones, to test the registration path end to end.
#include "fix_pwtest_addforce.h"
#include "launcher.h"

namespace {

void register_test_styles(porewater_liggghts::StyleSink &sink)
{
  porewater_liggghts::register_styles(sink);
  sink.fix("pwtest/addforce",
           &porewater_liggghts::fix_creator<porewater_liggghts_test::FixPwtestAddforce>);
}

}    // namespace

int main(int argc, char **argv)
{
  return porewater_liggghts::run_launcher(argc, argv, &register_test_styles);
}

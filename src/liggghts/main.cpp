// liggghts: Debian's LIGGGHTS-PUBLIC with the styles of this package.
#include "launcher.h"

int main(int argc, char **argv)
{
  return porewater_liggghts::run_launcher(argc, argv, &porewater_liggghts::register_styles);
}

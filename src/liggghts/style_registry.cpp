#include "style_registry.h"

#include "error.h"
#include "force.h"
#include "modify.h"

#include <map>
#include <string>

using namespace LAMMPS_NS;

namespace porewater_liggghts {
namespace {

// ---- access to the private Modify::fix_map --------------------------------------------
// Standard C++ ([temp.explicit], C++14 14.7.2/12; C++20 [temp.spec.general]/6): "the usual
// access checking rules do not apply to names used to specify explicit instantiations", so
// `&Modify::fix_map` may be a template argument of an explicit instantiation. The template
// stores it in a friend function found by argument-dependent lookup on the tag. Nothing is
// redefined (unlike `#define private public` or a second `class Info`, both ill-formed:
// ODR) and the member's type is spelled out here, so a LIGGGHTS whose map differs fails to
// compile instead of misbehaving.
using FixMap = std::map<std::string, FixCreator>;

struct ModifyFixMapTag {
  using type = FixMap *Modify::*;
  friend type member_pointer(ModifyFixMapTag);
};

template <class Tag, typename Tag::type Member> struct ExposeMember {
  friend typename Tag::type member_pointer(Tag) { return Member; }
};

template struct ExposeMember<ModifyFixMapTag, &Modify::fix_map>;

FixMap &fix_map(Modify *modify)
{
  return *(modify->*member_pointer(ModifyFixMapTag()));
}

// ---- sinks -----------------------------------------------------------------------------
// Collects the names offered ("fix a, pair b").
class Lister : public StyleSink {
 public:
  void fix(const char *name, FixCreator) override { note("fix", name); }
  void pair(const char *name, PairCreator) override { note("pair", name); }

  std::string names;

 private:
  void note(const char *kind, const char *name)
  {
    if (!names.empty()) names += ", ";
    names += std::string(kind) + " " + name;
  }
};

// Inserts them into one LAMMPS instance's maps.
class Installer : public Lister {
 public:
  explicit Installer(LAMMPS *lmp) : lmp_(lmp) {}

  void fix(const char *name, FixCreator create) override
  {
    insert(fix_map(lmp_->modify), "fix", name, create);
    Lister::fix(name, create);
  }

  void pair(const char *name, PairCreator create) override
  {
    insert(*lmp_->force->pair_map, "pair style", name, create);
    Lister::pair(name, create);
  }

 private:
  template <class Map, class Creator>
  void insert(Map &map, const char *kind, const char *name, Creator create)
  {
    if (map.count(name)) error_all(lmp_, FLERR, std::string("LIGGGHTS already has ") + kind + " " + name);
    map[name] = create;
  }

  LAMMPS *lmp_;
};

}    // namespace

std::string install_styles(LAMMPS *lmp, RegisterFunction fn)
{
  Installer installer(lmp);
  fn(installer);
  return installer.names;
}

std::string style_names(RegisterFunction fn)
{
  Lister lister;
  fn(lister);
  return lister.names;
}

}    // namespace porewater_liggghts
